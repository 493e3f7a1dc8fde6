// The gap refinement's shortcut on affine faces (host/trim/detail/affine_face.h): which faces
// take it, and that taking it changes no mesh byte and only the samples' rounding in the
// parametric stats, on hand-built planes and on the FreeCAD IDF models (mostly planes).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "trim/detail/affine_face.h"
#include "trim/face_surface.h"
#include "trim/mesher.h"
#include "trimmed_models.h"
#ifdef TESSERA_HAVE_CAD
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>

#include "cad/cad_file.h"
#include "cad/to_trimmed.h"
#endif

using namespace tessera;
using namespace tessera::test;
using trim_detail::FaceVertex;

namespace {

std::vector<FaceVertex> cornersOfUnitSquare() {
  return {{{0, 0}, {}, -1}, {{1, 0}, {}, -1}, {{1, 1}, {}, -1}, {{0, 1}, {}, -1}};
}

// The face's (u, v) box as the mesher takes it: its pieces and its loops.
std::pair<glm::dvec2, glm::dvec2> faceBox(const TrimmedFace& face) {
  glm::dvec2 lo(face.pieces[0].u0, face.pieces[0].v0), hi = lo;
  for (const BezierPatchPiece& p : face.pieces)
    lo = glm::min(lo, {p.u0, p.v0}), hi = glm::max(hi, {p.u1, p.v1});
  for (const TrimLoop& loop : face.loops)
    for (const glm::dvec2 uv : loop.uv) lo = glm::min(lo, uv), hi = glm::max(hi, uv);
  return {lo, hi};
}

// mesher.cpp's gapMetric, from meanScales' 180 surface points: what affineGapMetric must give.
glm::dvec2 sampledGapMetric(const TrimmedFace& face, double tolerance) {
  const auto [lo, hi] = faceBox(face);
  const FaceSurface::Scales scales = FaceSurface(face).meanScales(lo, hi);
  const glm::dvec2 extent = hi - lo;
  const auto allowed = [&](double b, double e) {
    return b > 0 ? std::min(std::sqrt(8.0 * tolerance / b), e) : e;
  };
  const double du = allowed(scales.bending.x, extent.x), dv = allowed(scales.bending.y, extent.y);
  const bool flat = du >= extent.x && dv >= extent.y;
  const double ratio = flat ? scales.speeds.x / scales.speeds.y : dv / du;
  return {std::exp2(std::round(std::log2(ratio))), 1.0};
}

// The model meshed with and without the shortcut, compared: the same mesh bit for bit, the same
// stats but the parametric ones, which may only lose the samples' rounding (`slack`). Returns
// the faces gapRefinementIdle takes, judged on their loop points.
size_t expectSameMeshes(const TrimmedModel& model, double delta, double slack) {
  size_t affineFaces = 0, metricFaces = 0;
  Backend cpu = makeMirrorBackend();
  TrimmedMeshOptions options;
  options.tolerance = delta;
  options.measureGeometric = false;
  const TrimmedMesh fast = meshTrimmedModel(model, options, cpu);
  options.affineShortcut = false;
  const TrimmedMesh sampled = meshTrimmedModel(model, options, cpu);
  CHECK(fast.mesh.indices == sampled.mesh.indices);
  CHECK(fast.mesh.positions == sampled.mesh.positions);
  CHECK(fast.mesh.uvs == sampled.mesh.uvs);
  CHECK(fast.cornerUv == sampled.cornerUv);
  REQUIRE(fast.faces.size() == sampled.faces.size());
  double largestLoss = 0;
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const TrimmedFaceStats &a = fast.faces[f], &b = sampled.faces[f];
    CHECK(a.gapTriangles == b.gapTriangles);
    CHECK(a.triangles == b.triangles);
    CHECK(a.refinementSplits == b.refinementSplits);
    CHECK(a.unfinishedGapTriangles == b.unfinishedGapTriangles);
    CHECK(a.maxTrimPointOffset == b.maxTrimPointOffset);
    CHECK(a.measuredTriangles == b.measuredTriangles);
    CHECK(a.maxGapParametricDeviation <= b.maxGapParametricDeviation);
    CHECK(a.maxParametricDeviation <= b.maxParametricDeviation);
    largestLoss = std::max({largestLoss, b.maxParametricDeviation - a.maxParametricDeviation,
                            b.maxGapParametricDeviation - a.maxGapParametricDeviation});
    std::vector<FaceVertex> loopPoints;
    for (const TrimLoop& loop : model.faces[f].loops)
      for (const glm::dvec2 uv : loop.uv) loopPoints.push_back({uv, {}, -1});
    const auto [lo, hi] = faceBox(model.faces[f]);
    if (const auto metric = trim_detail::affineGapMetric(model.faces[f], lo, hi, delta)) {
      ++metricFaces;
      CHECK(*metric == sampledGapMetric(model.faces[f], delta));
    }
    if (trim_detail::gapRefinementIdle(model.faces[f], loopPoints, delta)) {
      ++affineFaces;
      // Nothing to split (the sampled path agrees), and the gap's parametric deviation is its
      // corners' offsets: the trim points' (the file's edge gap) and the quad-tree vertices'
      // fp32 rounding (far under δ: a hundredth of it is asserted), not the surface's bending.
      CHECK(b.refinementSplits == 0);
      CHECK(a.maxGapParametricDeviation <= 0.01 * delta + a.maxTrimPointOffset);
    }
  }
  WARN(affineFaces << " affine faces of " << model.faces.size() << "; the sampled parametric "
                   << "deviation's largest excess over the shortcut's " << largestLoss);
  CHECK(largestLoss <= slack);
  CHECK(metricFaces == affineFaces);  // the corpus's planes take both shortcuts
  return affineFaces;
}

}  // namespace

TEST_CASE("affine faces: a plane's gap refinement is known idle, a twisted or clamped face's not",
          "[trim][affine]") {
  const double delta = 1e-3;
  TrimmedFace plane = faceOf(planarPatch({3, -2, 1}, {2, 0, 0}, {0, 0.5, 1}), {}, false, 0);
  CHECK(trim_detail::gapRefinementIdle(plane, cornersOfUnitSquare(), delta));
  // A twist T: the saddle's chords miss it by up to |T|/4 (at the square's centre, from the
  // diagonal from (1, 0) to (0, 1)): idle only when |T|/4 is under δ.
  for (const double twist : {3.9e-3, 4.1e-3}) {
    TrimmedFace saddle = plane;
    saddle.pieces[0].patch.at(1, 1).z += twist;
    CHECK(trim_detail::gapRefinementIdle(saddle, cornersOfUnitSquare(), delta) ==
          (twist / 4 < delta));
  }
  // A vertex past the rectangle: the surface is clamped there, not affine.
  std::vector<FaceVertex> overhang = cornersOfUnitSquare();
  overhang[2].uv.x = 1 + 1e-6;  // rounding's margin: 10⁻⁹ of the rectangle's reach
  CHECK_FALSE(trim_detail::gapRefinementIdle(plane, overhang, delta));
  // Not bilinear, unequal weights, two pieces.
  TrimmedFace bump = faceOf(bumpPatch(1, 0.0), {}, false, 1);  // flat, but cubic: not taken
  CHECK_FALSE(trim_detail::gapRefinementIdle(bump, cornersOfUnitSquare(), delta));
  TrimmedFace weighted = plane;
  weighted.pieces[0].patch.weights = {1, 1, 1, 2};
  CHECK_FALSE(trim_detail::gapRefinementIdle(weighted, cornersOfUnitSquare(), delta));
  weighted.pieces[0].patch.weights = {2, 2, 2, 2};
  CHECK(trim_detail::gapRefinementIdle(weighted, cornersOfUnitSquare(), delta));
  TrimmedFace halves = plane;
  halves.pieces.push_back(halves.pieces[0]);
  CHECK_FALSE(trim_detail::gapRefinementIdle(halves, cornersOfUnitSquare(), delta));
}

TEST_CASE("affine faces: a plane's gap metric is its sides' speed ratio as a power of two, "
          "unless near a half", "[trim][affine]") {
  const double delta = 1e-3;
  const glm::dvec2 lo(0, 0), hi(1, 1);
  // Sides of speed 3 and 1: log₂ 3 = 1.58 → 2 (meanScales agrees); 2^1.5 = 2.83 is refused.
  for (const double side : {1.0, 3.0, 0.3, 2.0 * std::sqrt(2.0), 40.0}) {
    const TrimmedFace plane = faceOf(planarPatch({-7, 5, 2}, {side, 0, side}, {0, 1, 0}), {}, false, 0);
    const std::optional<glm::dvec2> metric = trim_detail::affineGapMetric(plane, lo, hi, delta);
    const double exponent = std::log2(side * std::sqrt(2.0));
    INFO("speed ratio " << side * std::sqrt(2.0));
    CHECK(metric.has_value() == (std::abs(exponent - std::round(exponent)) < 0.49));
    if (metric) CHECK(*metric == sampledGapMetric(plane, delta));
  }
  // A saddle, and a box past the rectangle (clamped stencil points): not affine, not taken.
  TrimmedFace saddle = faceOf(planarPatch({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), {}, false, 1);
  saddle.pieces[0].patch.at(1, 1).z += 0.5;
  CHECK_FALSE(trim_detail::affineGapMetric(saddle, lo, hi, delta));
  const TrimmedFace plane = faceOf(planarPatch({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), {}, false, 2);
  CHECK(trim_detail::affineGapMetric(plane, lo, hi, delta) == glm::dvec2(1, 1));
  CHECK_FALSE(trim_detail::affineGapMetric(plane, lo, {1.01, 1}, delta));
  // δ within reach of meanScales' rounding noise: refused.
  CHECK_FALSE(trim_detail::affineGapMetric(plane, lo, hi, 1e-12));
}

TEST_CASE("affine faces: the shortcut keeps a holed plate's mesh and refines nothing sampled",
          "[trim][affine]") {
  // Square plates with round holes off the origin: gap triangles only, trim points on the plane
  // (offset 0 up to rounding), so the stats' gap deviation is the rounding the samples add.
  TrimmedModel model;
  test::SharedPoints shared(model);
  for (int k = 0; k < 3; ++k) {
    const BezierPatch p = planarPatch({100.0 + k, 7, -3}, {1, 0, 0.25 * k}, {0, 1, 0});
    const auto at = [&](glm::dvec2 uv) { return patchPoint(p, uv.x, uv.y); };
    model.faces.push_back(faceOf(p,
                                 {sampledLoop(squareBoundary(), 40, at, shared),
                                  sampledLoop(circle({0.4, 0.5}, 0.2), 32 + 8 * k, at, shared)},
                                 k == 1, uint32_t(k)));
  }
  CHECK(expectSameMeshes(model, 1e-3, 1e-12) == 3);
}

#ifdef TESSERA_HAVE_CAD
TEST_CASE("affine faces: the IDF models' planes mesh as sampled, bit for bit",
          "[trim][affine][cad]") {
  size_t affineFaces = 0, faces = 0;
  for (const char* name : {"SOT23.stp", "0603_SMD.stp", "TSM_104_01_L_DV_A.stp", "SOT_96.stp"}) {
    const std::string path = std::string("/usr/share/freecad/Mod/Idf/Idflibs/") + name;
    REQUIRE(std::filesystem::exists(path));  // freecad-common (scripts/deps.sh)
    const CadFile file = readCadFile(path);
    Bnd_Box box;
    BRepBndLib::Add(file.shape, box);
    const double diagonal = std::sqrt(box.SquareExtent());
    const CadImport import = toTrimmedModel(file, 1e-3 * diagonal);
    INFO(name);
    // The samples' rounding: a few ulps of the model's coordinates, 10⁻¹² of its diagonal at most.
    affineFaces += expectSameMeshes(import.model, import.delta, 1e-12 * diagonal);
    faces += import.model.faces.size();
  }
  WARN(affineFaces << " of " << faces << " IDF faces take the shortcut");
  CHECK(affineFaces * 2 > faces);  // the corpus is mostly planes
}
#endif
