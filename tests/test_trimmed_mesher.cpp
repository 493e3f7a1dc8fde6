// The trimmed mesher (host/trim/mesher.h) on hand-built TrimmedModels: a flat square with a
// round hole, a curved bicubic face with an inner loop (and one with a hole inside a single
// quad-tree triangle), two faces sharing a curved edge, closed solids (a cube of six planes,
// a pillow of two bicubics), deviation within δ at several δ, reversed faces. Checks: every
// edge used by two consistently oriented triangles except along the model's open boundary,
// no T-junction, no zero-area triangle, the triangles' (u, v) areas add up to the area
// inside the loops (so they cover it without overlap), measured deviation ≤ δ.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "mesh/tessellate.h"
#include "mesh_checks.h"
#include "trim/face_surface.h"
#include "trim/gap_triangulate.h"
#include "trim/mesher.h"
#include "trimmed_models.h"

using namespace tessera;
using namespace tessera::test;

namespace {

double loopArea(const TrimLoop& loop) {
  double area = 0;
  for (size_t k = 0; k < loop.uv.size(); ++k) {
    const glm::dvec2 a = loop.uv[k], b = loop.uv[(k + 1) % loop.uv.size()];
    area += 0.5 * (a.x * b.y - a.y * b.x);
  }
  return area;
}

// A path through `uvs` (each segment sampled so that the 3D chord is within δ/2 of the
// surface along the uv segment, as an edge discretised to the tolerance would be).
std::vector<glm::dvec2> refinedPath(const std::vector<glm::dvec2>& uvs, const BezierPatch& s,
                                    double delta) {
  std::vector<glm::dvec2> out;
  for (size_t k = 0; k + 1 < uvs.size(); ++k) {
    for (int n = 1;; n *= 2) {
      double worst = 0;
      for (int i = 0; i < n; ++i) {
        const glm::dvec2 a = glm::mix(uvs[k], uvs[k + 1], double(i) / n);
        const glm::dvec2 b = glm::mix(uvs[k], uvs[k + 1], double(i + 1) / n);
        const glm::dvec3 pa = patchPoint(s, a.x, a.y), pb = patchPoint(s, b.x, b.y);
        for (int j = 1; j < 8; ++j) {
          const glm::dvec2 m = glm::mix(a, b, j / 8.0);
          worst = std::max(worst, glm::length(glm::mix(pa, pb, j / 8.0) - patchPoint(s, m.x, m.y)));
        }
      }
      if (worst <= delta / 2 || n >= 4096) {
        for (int i = 0; i < n; ++i) out.push_back(glm::mix(uvs[k], uvs[k + 1], double(i) / n));
        break;
      }
    }
  }
  return out;
}

// A closed curve's samples refined to δ/2 as above (the curve sampled at `n` first).
std::vector<glm::dvec2> refinedClosed(const std::function<glm::dvec2(double)>& curve, int n,
                                      const BezierPatch& s, double delta) {
  std::vector<glm::dvec2> uvs;
  for (int k = 0; k <= n; ++k) uvs.push_back(curve(double(k) / n));
  return refinedPath(uvs, s, delta);
}

TrimLoop loopThrough(const std::vector<glm::dvec2>& uvs,
                     const std::function<glm::dvec3(glm::dvec2)>& position, SharedPoints& shared) {
  TrimLoop loop;
  for (glm::dvec2 uv : uvs) {
    loop.uv.push_back(uv);
    loop.pointIds.push_back(shared.at(position(uv)));
  }
  return loop;
}

struct MeshCheck {
  EdgeCensus census;
  size_t tJunctions = 0;
};

MeshCheck checkMesh(const TrimmedModel& model, const TrimmedMesh& m, const std::string& name,
                    double delta, GapMeasure measure = GapMeasure::Geometric) {
  MeshCheck c;
  c.census = censusOf(m.mesh, 1e-14);
  c.tJunctions = tJunctionCount(m.mesh, c.census, 1e-7);
  WARN(name << " at δ " << delta << ": " << m.mesh.triangleCount() << " triangles, "
            << c.census.boundaryEdges << " boundary edges, over-used " << c.census.overusedEdges
            << ", inconsistent " << c.census.inconsistentEdges << ", zero-area "
            << c.census.degenerateTriangles << ", T-junctions " << c.tJunctions);
  CHECK(c.census.overusedEdges == 0);
  CHECK(c.census.inconsistentEdges == 0);
  CHECK(c.census.degenerateTriangles == 0);
  CHECK(c.tJunctions == 0);
  REQUIRE(m.faces.size() == model.faces.size());
  // The mesher's own figures sample each triangle at (i, j, k)/8; re-measure here, finer
  // (n = 10), against the face's surface, from the emitted fp32 positions: in the measure the
  // gap was refined by (geometric: the closest-point distance; parametric: the same uv mix).
  const bool geometric = measure == GapMeasure::Geometric;
  double remeasured = 0;
  std::vector<FaceSurface> surfaces(model.faces.begin(), model.faces.end());
  for (size_t t = 0; t < m.triangleFace.size(); ++t) {
    const FaceSurface& surface = surfaces[m.triangleFace[t]];
    const int n = 10;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double w[3] = {double(i) / n, double(j) / n, double(n - i - j) / n};
        glm::dvec2 uv(0);
        glm::dvec3 p(0);
        for (int k = 0; k < 3; ++k) {
          uv += w[k] * m.cornerUv[3 * t + k];
          p += w[k] * glm::dvec3(m.mesh.positions[m.mesh.indices[3 * t + k]]);
        }
        remeasured = std::max(remeasured, geometric ? surface.distance(p, uv)
                                                    : glm::length(p - surface.point(uv)));
      }
  }
  WARN("  re-measured " << (geometric ? "geometric" : "parametric")
                        << " deviation at n = 10: " << remeasured);
  CHECK(remeasured <= delta);
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const TrimmedFaceStats& s = m.faces[f];
    // The triangles' uv areas (counter-clockwise positive, clockwise for a reversed face) add
    // up to the area inside the loops: together with every triangle being positive, that is
    // coverage without overlap.
    double meshArea = 0, loopsArea = 0;
    size_t negative = 0;
    for (size_t t = 0; t < m.triangleFace.size(); ++t) {
      if (m.triangleFace[t] != f) continue;
      const glm::dvec2 a = m.cornerUv[3 * t], b = m.cornerUv[3 * t + 1], d = m.cornerUv[3 * t + 2];
      double area = 0.5 * ((b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x));
      if (model.faces[f].reversed) area = -area;
      negative += area <= 0;
      meshArea += area;
    }
    for (const TrimLoop& loop : model.faces[f].loops) loopsArea += loopArea(loop);
    WARN("  face " << f << ": " << s.triangles << " triangles (" << s.keptTriangles
                   << " quad-tree kept of " << s.quadtreeTriangles << ", " << s.gapTriangles
                   << " gap, " << s.refinementSplits << " splits), max deviation parametric "
                   << s.maxParametricDeviation << " (gap " << s.maxGapParametricDeviation
                   << "), geometric " << s.maxGeometricDeviation << "; uv area " << meshArea
                   << " vs loops " << loopsArea);
    CHECK(s.triangles > 0);
    CHECK(s.gapFailures == 0);
    CHECK(negative == 0);
    CHECK(meshArea == Approx(loopsArea).epsilon(1e-9));
    if (!geometric) CHECK(s.maxParametricDeviation <= delta);
    CHECK(s.maxGeometricDeviation <= delta);
  }
  return c;
}

TrimmedMesh meshAt(const TrimmedModel& model, double delta,
                   GapMeasure measure = GapMeasure::Geometric) {
  Backend cpu = makeMirrorBackend();
  TrimmedMeshOptions options;
  options.tolerance = delta;
  options.gapMeasure = measure;
  return meshTrimmedModel(model, options, cpu);
}

// The curved face of (b): a bicubic bump, outer loop on the domain boundary, a round hole.
TrimmedModel bumpWithHole(double delta, glm::dvec2 centre, double radius, bool reversed) {
  TrimmedModel model;
  SharedPoints shared(model);
  const BezierPatch s = bumpPatch(1, 0.3, 0.5);
  const auto at = [&](glm::dvec2 uv) { return patchPoint(s, uv.x, uv.y); };
  auto outer = refinedPath({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, s, delta);
  auto hole = refinedClosed(circle(centre, radius), 16, s, delta);
  model.faces.push_back(
      faceOf(s, {loopThrough(outer, at, shared), loopThrough(hole, at, shared)}, reversed, 0));
  return model;
}

}  // namespace

TEST_CASE("trimmed mesher: a flat square with a round hole", "[trim]") {
  TrimmedModel model;
  SharedPoints shared(model);
  const BezierPatch plane = planarPatch({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const auto at = [&](glm::dvec2 uv) { return patchPoint(plane, uv.x, uv.y); };
  model.faces.push_back(faceOf(plane,
                               {sampledLoop(squareBoundary(), 32, at, shared),
                                sampledLoop(circle({0.5, 0.5}, 0.25), 64, at, shared)},
                               false, 0));
  const double delta = 1e-3;
  const TrimmedMesh m = meshAt(model, delta);
  const MeshCheck c = checkMesh(model, m, "flat square with a hole", delta);
  // Open boundary: exactly the 32 + 64 loop segments.
  CHECK(c.census.boundaryEdges == 96);
}

TEST_CASE("trimmed mesher: a curved bicubic face with an inner loop", "[trim]") {
  const double delta = 2e-3;
  const TrimmedModel model = bumpWithHole(delta, {0.45, 0.55}, 0.2, false);
  const TrimmedMesh m = meshAt(model, delta);
  const MeshCheck c = checkMesh(model, m, "bump with a hole", delta);
  CHECK(c.census.boundaryEdges ==
        model.faces[0].loops[0].uv.size() + model.faces[0].loops[1].uv.size());
  // The outer loop's sides are straight in 3D (z = 0 rows), so they stay long segments
  // across the curved bump: the triangles beside them had to be split to meet δ.
  double longest = 0;
  const TrimLoop& outer = model.faces[0].loops[0];
  for (size_t k = 0; k < outer.uv.size(); ++k)
    longest = std::max(longest, glm::length(outer.uv[(k + 1) % outer.uv.size()] - outer.uv[k]));
  WARN("longest trim segment " << longest << " (uv), " << m.faces[0].refinementSplits
                               << " splits");
  CHECK(longest >= 0.25);
  CHECK(m.faces[0].refinementSplits > 0);
}

TEST_CASE("trimmed mesher: a hole inside one quad-tree triangle", "[trim]") {
  // At δ = 0.05 the bump is a handful of leaves; the hole (radius 0.004) lies inside one.
  const double delta = 0.05;
  const TrimmedModel model = bumpWithHole(delta, {0.31, 0.62}, 0.004, false);
  REQUIRE(model.faces[0].loops[1].uv.size() == 16);
  const TrimmedMesh m = meshAt(model, delta);
  const MeshCheck c = checkMesh(model, m, "bump with a tiny hole", delta);
  CHECK(c.census.boundaryEdges ==
        model.faces[0].loops[0].uv.size() + model.faces[0].loops[1].uv.size());
}

TEST_CASE("trimmed mesher: two faces sharing a curved edge share its vertices", "[trim]") {
  // Face A is the bump below the curve v = c(u); face B is the same surface parametrised
  // the other way (u' = 1 − u, so its S_u' × S_v points inwards: reversed) above the curve.
  const double delta = 2e-3;
  TrimmedModel model;
  SharedPoints shared(model);
  const BezierPatch a = bumpPatch(1, 0.3, 0.5);
  BezierPatch b = a;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) b.at(i, j) = a.at(3 - i, j);
  const auto c = [](double u) { return 0.5 + 0.15 * std::sin(2 * kPi * u); };
  const auto onA = [&](glm::dvec2 uv) { return patchPoint(a, uv.x, uv.y); };
  std::vector<glm::dvec2> curve;  // u from 1 to 0 along v = c(u), in A's uv
  for (int k = 0; k <= 24; ++k) curve.push_back({1 - k / 24.0, c(1 - k / 24.0)});
  curve = refinedPath(curve, a, delta);
  curve.push_back({0, c(0)});
  const auto side = [&](std::vector<glm::dvec2> corners) { return refinedPath(corners, a, delta); };
  // A (below), counter-clockwise: bottom, right side up to the curve, the curve, left down.
  std::vector<glm::dvec2> loopA = side({{0, 0}, {1, 0}, {1, c(1)}});
  loopA.insert(loopA.end(), curve.begin(), curve.end() - 1);
  for (glm::dvec2 uv : side({{0, c(0)}, {0, 0}})) loopA.push_back(uv);
  // B (above), counter-clockwise in A's uv: the curve reversed, right side, top, left side;
  // then into B's own uv (mirrored, so reversed again to stay counter-clockwise there).
  std::vector<glm::dvec2> loopB(curve.rbegin(), curve.rend() - 1);
  for (glm::dvec2 uv : side({{1, c(1)}, {1, 1}, {0, 1}, {0, c(0)}})) loopB.push_back(uv);
  std::reverse(loopB.begin(), loopB.end());
  TrimLoop inA = loopThrough(loopA, onA, shared), inB = loopThrough(loopB, onA, shared);
  for (glm::dvec2& uv : inB.uv) uv.x = 1 - uv.x;
  model.faces.push_back(faceOf(a, {inA}, false, 0));
  model.faces.push_back(faceOf(b, {inB}, true, 1));
  // Both loops name the same shared points along the curve.
  std::set<uint32_t> idsA(inA.pointIds.begin(), inA.pointIds.end()), common;
  for (uint32_t id : inB.pointIds)
    if (idsA.count(id)) common.insert(id);
  REQUIRE(common.size() == curve.size());

  const TrimmedMesh m = meshAt(model, delta);
  const MeshCheck check = checkMesh(model, m, "two faces sharing a curve", delta);
  // Open edges: the square's boundary only; none along the curve.
  const size_t curveSegments = curve.size() - 1;
  CHECK(check.census.boundaryEdges == inA.uv.size() + inB.uv.size() - 2 * curveSegments);
  size_t openOnCurve = 0;
  for (const auto& [edge, count] : check.census.undirected)
    if (count == 1 && std::abs(m.mesh.positions[edge.first].x - m.mesh.positions[edge.second].x) >
                          0 &&
        m.mesh.uvs[edge.first].y > 0.01 && m.mesh.uvs[edge.first].y < 0.99 &&
        m.mesh.uvs[edge.second].y > 0.01 && m.mesh.uvs[edge.second].y < 0.99)
      ++openOnCurve;
  CHECK(openOnCurve == 0);
}

namespace {

// Signed volume inside a closed mesh (divergence theorem): positive when it faces outward.
double enclosedVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
        c(mesh.positions[mesh.indices[t + 2]]);
    volume += glm::dot(a, glm::cross(b, c)) / 6;
  }
  return volume;
}

}  // namespace

TEST_CASE("trimmed mesher: closed solids give closed meshes", "[trim]") {
  SECTION("a cube of six planar faces, some reversed") {
    TrimmedModel model;
    SharedPoints shared(model);
    const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        const glm::dvec3 du = axes[(axis + 1) % 3], dv = axes[(axis + 2) % 3];
        const glm::dvec3 origin = double(side) * axes[axis];
        const BezierPatch p = planarPatch(origin, du, dv);
        const glm::dvec3 outward = (side ? 1.0 : -1.0) * axes[axis];
        const auto at = [&](glm::dvec2 uv) { return patchPoint(p, uv.x, uv.y); };
        model.faces.push_back(faceOf(p, {sampledLoop(squareBoundary(), 12, at, shared)},
                                     glm::dot(glm::cross(du, dv), outward) < 0,
                                     uint32_t(model.faces.size())));
      }
    REQUIRE(model.sharedPoints.size() == 8 + 12 * 2);
    const TrimmedMesh m = meshAt(model, 1e-3);
    const MeshCheck c = checkMesh(model, m, "cube", 1e-3);
    CHECK(c.census.boundaryEdges == 0);
    const double volume = enclosedVolume(m.mesh);
    WARN("cube volume " << volume);
    CHECK(volume == Approx(1).epsilon(1e-6));
  }
  SECTION("a pillow of two bicubic faces") {
    const double delta = 2e-3;
    TrimmedModel model;
    SharedPoints shared(model);
    const BezierPatch top = bumpPatch(1, 0.3, 0.4), bottom = bumpPatch(1, -0.2, -0.3);
    const auto at = [&](glm::dvec2 uv) { return patchPoint(top, uv.x, uv.y); };
    // The boundary rows are the same in both (z = 0), so one discretisation serves both.
    const auto boundary = refinedPath({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, top, delta);
    model.faces.push_back(faceOf(top, {loopThrough(boundary, at, shared)}, false, 0));
    model.faces.push_back(faceOf(bottom, {loopThrough(boundary, at, shared)}, true, 1));
    const TrimmedMesh m = meshAt(model, delta);
    const MeshCheck c = checkMesh(model, m, "pillow", delta);
    CHECK(c.census.boundaryEdges == 0);
    CHECK(enclosedVolume(m.mesh) > 0);
  }
}

TEST_CASE("trimmed mesher: the measured deviation stays within δ", "[trim]") {
  for (double delta : {0.02, 0.005, 0.001}) {
    const TrimmedModel model = bumpWithHole(delta, {0.45, 0.55}, 0.2, false);
    checkMesh(model, meshAt(model, delta), "bump with a hole", delta);
    // The parametric measure (the stronger one, rule T's) holds its own δ too.
    checkMesh(model, meshAt(model, delta, GapMeasure::Parametric), "bump with a hole, parametric",
              delta, GapMeasure::Parametric);
  }
}

TEST_CASE("trimmed mesher: a reversed face gives the same triangles flipped", "[trim]") {
  const double delta = 5e-3;
  const TrimmedModel forward = bumpWithHole(delta, {0.45, 0.55}, 0.2, false);
  const TrimmedModel backward = bumpWithHole(delta, {0.45, 0.55}, 0.2, true);
  const TrimmedMesh f = meshAt(forward, delta), b = meshAt(backward, delta);
  REQUIRE(f.mesh.triangleCount() == b.mesh.triangleCount());
  // Each triangle as its corners' uv, rotated to start at the smallest: (p, q, r) in the
  // forward mesh must appear as (p, r, q) in the reversed one.
  using Corner = std::pair<double, double>;
  const auto canonical = [](Corner p, Corner q, Corner r) {
    std::array<Corner, 3> t{p, q, r};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::set<std::array<Corner, 3>> flipped;
  for (size_t t = 0; t < b.mesh.triangleCount(); ++t) {
    const auto& uv = b.cornerUv;
    flipped.insert(canonical({uv[3 * t].x, uv[3 * t].y}, {uv[3 * t + 2].x, uv[3 * t + 2].y},
                             {uv[3 * t + 1].x, uv[3 * t + 1].y}));
  }
  size_t missing = 0;
  for (size_t t = 0; t < f.mesh.triangleCount(); ++t) {
    const auto& uv = f.cornerUv;
    missing += !flipped.count(canonical({uv[3 * t].x, uv[3 * t].y}, {uv[3 * t + 1].x, uv[3 * t + 1].y},
                                        {uv[3 * t + 2].x, uv[3 * t + 2].y}));
  }
  WARN("reversed face: " << f.mesh.triangleCount() << " triangles, " << missing
                         << " without their flipped twin");
  CHECK(missing == 0);
  checkMesh(backward, b, "reversed bump with a hole", delta);
}

TEST_CASE("trimmed mesher: a bad model names the face and the loop", "[trim]") {
  TrimmedModel model = bumpWithHole(0.01, {0.5, 0.5}, 0.2, false);
  model.faces[0].label = "face 7 (#88 ADVANCED_FACE)";
  Backend cpu = makeMirrorBackend();
  TrimmedMeshOptions options;
  options.tolerance = 0.01;
  TrimmedModel badId = model;
  badId.faces[0].loops[1].pointIds[3] = uint32_t(model.sharedPoints.size());
  CHECK_THROWS_WITH(meshTrimmedModel(badId, options, cpu),
                    Catch::Contains("face 7 (#88 ADVANCED_FACE)") && Catch::Contains("loop 1") &&
                        Catch::Contains("past the"));
  TrimmedModel shortLoop = model;
  shortLoop.faces[0].loops[0].uv.resize(2);
  shortLoop.faces[0].loops[0].pointIds.resize(2);
  CHECK_THROWS_WITH(meshTrimmedModel(shortLoop, options, cpu),
                    Catch::Contains("loop 0 has 2 points"));
  TrimmedModel badPiece = model;  // the quad-tree's check, named by face and piece
  badPiece.faces[0].pieces.back().patch.cp[1].y = std::nan("");
  CHECK_THROWS_WITH(meshTrimmedModel(badPiece, options, cpu),
                    "face 7 (#88 ADVANCED_FACE), piece " +
                        std::to_string(badPiece.faces[0].pieces.size() - 1) +
                        " has a control point that is not finite or exceeds 1e38 (the mesh is "
                        "fp32)");
  badPiece.faces[0].label.clear();
  CHECK_THROWS_WITH(meshTrimmedModel(badPiece, options, cpu),
                    Catch::StartsWith("face 0, piece "));
  options.tolerance = 0;
  CHECK_THROWS_WITH(meshTrimmedModel(model, options, cpu), Catch::Contains("tolerance"));
}

TEST_CASE("trimmed mesher: a cylinder of four rational pieces with a seam, and two caps",
          "[trim]") {
  // The side (trimmed_models.h): u ∈ [0, 2π] in four quarter-circle pieces, v ∈ [0, 1] the
  // height. Its loop runs round the bottom, up the seam at u = 2π, back round the top and down
  // the seam at u = 0: the seam's points carry the same ids on both sides.
  // The caps are planes over [−1, 1]² (uv ∈ [0,1]²) trimmed by the same circles.
  const double delta = 0.005;
  const int n = 64;  // samples round the circle: chords within δ/2
  TrimmedModel model;
  SharedPoints shared(model);
  TrimmedFace side = fourPieceCylinderSide();
  const FaceSurface sideSurface(side);
  std::vector<glm::dvec2> sideUv;
  for (int k = 0; k <= n; ++k) sideUv.push_back({2 * kPi * k / n, 0});
  for (int k = 1; k <= 4; ++k) sideUv.push_back({2 * kPi, k / 4.0});
  for (int k = n - 1; k >= 0; --k) sideUv.push_back({2 * kPi * k / n, 1});
  for (int k = 3; k >= 1; --k) sideUv.push_back({0, k / 4.0});
  // u = 2π and u = 0 are one place: look ids up by the point at u mod 2π.
  const auto onSide = [&](glm::dvec2 uv) {
    return sideSurface.point({uv.x >= 2 * kPi ? 0.0 : uv.x, uv.y});
  };
  side.loops.push_back(loopThrough(sideUv, onSide, shared));
  side.faceIndex = 0;
  model.faces.push_back(side);
  for (int top = 0; top < 2; ++top) {
    const BezierPatch cap = planarPatch({-1, -1, double(top)}, {2, 0, 0}, {0, 2, 0});
    std::vector<glm::dvec2> capUv;
    for (int k = 0; k < n; ++k) {
      const glm::dvec3 p = sideSurface.point({2 * kPi * k / n, 0});
      capUv.push_back({(p.x + 1) / 2, (p.y + 1) / 2});
    }
    const auto onCap = [&](glm::dvec2 uv) { return patchPoint(cap, uv.x, uv.y); };
    // Outward: +z on top (S_u × S_v = +z), −z below (reversed).
    model.faces.push_back(faceOf(cap, {loopThrough(capUv, onCap, shared)}, !top, 1 + top));
  }
  REQUIRE(model.sharedPoints.size() == size_t(2 * n + 3));

  const TrimmedMesh m = meshAt(model, delta);
  const MeshCheck c = checkMesh(model, m, "cylinder with caps", delta);
  CHECK(c.census.boundaryEdges == 0);
  double volume = 0;
  for (size_t t = 0; t < m.mesh.indices.size(); t += 3) {
    const glm::dvec3 a(m.mesh.positions[m.mesh.indices[t]]),
        b(m.mesh.positions[m.mesh.indices[t + 1]]), d(m.mesh.positions[m.mesh.indices[t + 2]]);
    volume += glm::dot(a, glm::cross(b, d)) / 6;
  }
  WARN("cylinder volume " << volume << " (π = " << kPi << ")");
  CHECK(volume == Approx(kPi).epsilon(0.01));
}

TEST_CASE("trimmed mesher: trim points off the surface (an edge gap) are told, not refined",
          "[trim]") {
  // A CAD file whose edges' 3D curves and pcurves disagree (CadEdgeWarning) gives trim points
  // off the face's surface. Lift every shared point of a flat square with a hole by g = 5δ: the
  // refinement cannot reduce that, so it must not split for it (it once split to its round cap),
  // and the stats must report it: deviation ≤ δ + maxTrimPointOffset, the offset g.
  const double delta = 1e-3, gap = 5 * delta;
  const auto build = [&](double lift) {
    TrimmedModel model;
    SharedPoints shared(model);
    const BezierPatch plane = planarPatch({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const auto at = [&](glm::dvec2 uv) { return patchPoint(plane, uv.x, uv.y); };
    model.faces.push_back(faceOf(plane,
                                 {sampledLoop(squareBoundary(), 32, at, shared),
                                  sampledLoop(circle({0.5, 0.5}, 0.25), 64, at, shared)},
                                 false, 0));
    for (glm::dvec3& p : model.sharedPoints) p.z += lift;
    return model;
  };
  const TrimmedModel exact = build(0), lifted = build(gap);
  const TrimmedMesh a = meshAt(exact, delta), b = meshAt(lifted, delta);
  const TrimmedFaceStats &sa = a.faces[0], &sb = b.faces[0];
  WARN("lifted by " << gap << ": " << sb.triangles << " triangles (exact: " << sa.triangles
                    << "), " << sb.refinementSplits << " splits, trim point offset "
                    << sb.maxTrimPointOffset << ", max parametric " << sb.maxParametricDeviation
                    << ", geometric " << sb.maxGeometricDeviation);
  CHECK(sa.maxTrimPointOffset == 0);
  CHECK(sb.maxTrimPointOffset == Approx(gap).epsilon(1e-9));
  CHECK(sb.refinementSplits == sa.refinementSplits);
  CHECK(sb.triangles == sa.triangles);
  CHECK(sb.maxParametricDeviation <= delta + sb.maxTrimPointOffset);
  CHECK(sb.maxGeometricDeviation <= delta + sb.maxTrimPointOffset);
}

TEST_CASE("trimmed mesher: a self-crossing loop is reported, not hidden", "[trim]") {
  // A bow tie: its two lobes wind +1 and −1, so no loop of the gap holds the −1 lobe.
  TrimmedModel model;
  SharedPoints shared(model);
  const BezierPatch plane = planarPatch({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const auto at = [&](glm::dvec2 uv) { return patchPoint(plane, uv.x, uv.y); };
  model.faces.push_back(faceOf(plane,
                               {loopThrough({{0.1, 0.1}, {0.9, 0.9}, {0.9, 0.1}, {0.1, 0.9}}, at,
                                            shared)},
                               false, 0));
  const TrimmedMesh m = meshAt(model, 1e-3);
  WARN("bow tie: " << m.faces[0].triangles << " triangles, " << m.faces[0].gapFailures
                   << " gap failures");
  CHECK(m.faces[0].gapFailures > 0);
}

// At δ = 10⁻⁴ the bump's gap once kept triangles 4.7·10⁻⁴ off the surface: three kept
// quad-tree vertices on one row v = const, collinear in uv up to the fp32 rounding of their
// corner uvs, taken as an ear or made by a flip; a midpoint split kept both halves on the line.
// Now flat ears and flips are refused and a sliver over δ gives its long side up by a flip
// (docs/trimmed_faces.md, "Slivers"). Both measures, each within its own δ, no flat triangle.
TEST_CASE("trimmed mesher: a finely trimmed bump down to δ = 1e-4, no flat slivers", "[trim]") {
  for (double delta : {1e-3, 3e-4, 1e-4}) {
    const TrimmedModel model = bumpWithHole(delta, {0.45, 0.55}, 0.2, false);
    Backend cpu = makeMirrorBackend();
    for (GapMeasure measure : {GapMeasure::Parametric, GapMeasure::Geometric}) {
      TrimmedMeshOptions options;
      options.tolerance = delta;
      options.gapMeasure = measure;
      options.measureGeometric = measure == GapMeasure::Geometric;
      const auto start = std::chrono::steady_clock::now();
      const TrimmedMesh m = meshTrimmedModel(model, options, cpu);
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      const TrimmedFaceStats& s = m.faces[0];
      double flattest = 1;
      for (size_t t = 0; t < m.triangleFace.size(); ++t) {
        const glm::dvec2 a = m.cornerUv[3 * t], b = m.cornerUv[3 * t + 1],
                         d = m.cornerUv[3 * t + 2];
        const double area2 = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
        const double base = std::max({glm::length(b - a), glm::length(d - b), glm::length(a - d)});
        flattest = std::min(flattest, area2 / (base * base));  // height / longest side
      }
      const bool geometric = measure == GapMeasure::Geometric;
      WARN("δ " << delta << (geometric ? " geometric: " : " parametric: ")
                << model.faces[0].loops[0].uv.size() + model.faces[0].loops[1].uv.size()
                << " trim points, " << s.triangles << " triangles (" << s.gapTriangles
                << " gap, " << s.refinementSplits << " splits), max parametric "
                << s.maxParametricDeviation << ", geometric " << s.maxGeometricDeviation
                << ", flattest height/side " << flattest << ", " << ms << " ms");
      CHECK(s.gapFailures == 0);
      CHECK(flattest > 1e-6);
      if (geometric)
        CHECK(s.maxGeometricDeviation <= delta);
      else
        CHECK(s.maxParametricDeviation <= delta);
    }
  }
}

TEST_CASE("gap triangulation: a hole whose nearest bridges a wall of another hole blocks",
          "[trim][gap]") {
  // A square (64 points, counter-clockwise) with two holes (clockwise): a 16-gon near the left
  // side and, between it and that side, a long thin wall. The bridges from the 16-gon to the
  // side's nearest points cross the wall, so many candidates are tested (the edges in runs with
  // their boxes, bridgeHole); a run passed wrongly lets a bridge cross the wall, and the
  // triangles then overlap it (their areas add up to more) or the ear clipping fails.
  std::vector<glm::dvec2> points;
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  const auto loop = [&](const std::vector<glm::dvec2>& ring) {
    const uint32_t first = uint32_t(points.size());
    points.insert(points.end(), ring.begin(), ring.end());
    for (uint32_t k = 0; k < ring.size(); ++k)
      edges.push_back({first + k, first + (k + 1) % uint32_t(ring.size())});
  };
  std::vector<glm::dvec2> square;
  const glm::dvec2 corners[4] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 16; ++k)
      square.push_back(corners[side] + (corners[(side + 1) % 4] - corners[side]) * (k / 16.0));
  loop(square);
  std::vector<glm::dvec2> ring;
  for (int k = 0; k < 16; ++k) {
    const double angle = -2 * 3.14159265358979323846 * k / 16;  // clockwise
    ring.push_back(glm::dvec2(3.0, 5.0) + 0.8 * glm::dvec2(std::cos(angle), std::sin(angle)));
  }
  loop(ring);
  std::vector<glm::dvec2> wall;  // x in [1.5, 1.7], y in [1, 9], clockwise, 20 points a long side
  for (int k = 0; k <= 20; ++k) wall.push_back({1.5, 1.0 + 8.0 * k / 20});
  for (int k = 0; k <= 20; ++k) wall.push_back({1.7, 9.0 - 8.0 * k / 20});
  loop(wall);
  const GapTriangulation gap = triangulateGap(points, edges);
  REQUIRE(gap.failures == 0);
  double area = 0;
  for (const auto& t : gap.triangles) {
    const glm::dvec2 a = points[t[0]], b = points[t[1]], c = points[t[2]];
    const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    REQUIRE(twice > 0);
    area += 0.5 * twice;
  }
  double expected = 100.0 - 0.2 * 8.0;
  for (int k = 0; k < 16; ++k) {  // the 16-gon's area
    const glm::dvec2 a = ring[k] - glm::dvec2(3, 5), b = ring[(k + 1) % 16] - glm::dvec2(3, 5);
    expected -= 0.5 * std::abs(a.x * b.y - a.y * b.x);
  }
  REQUIRE(area == Approx(expected).epsilon(1e-12));
  // Every input edge is a side of a triangle, in its direction (the region on its left).
  std::set<std::pair<uint32_t, uint32_t>> sides;
  for (const auto& t : gap.triangles)
    for (int k = 0; k < 3; ++k) sides.insert({t[k], t[(k + 1) % 3]});
  for (const auto& e : edges) REQUIRE(sides.count(e) == 1);
}
