#include "trim/mesher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include "common/hash_map.h"
#include "common/parallel_for.h"
#include "common/small_id_list.h"
#include "common/stopwatch.h"
#include "quadtree/quadtree.h"
#include "trim/detail/affine_face.h"
#include "trim/detail/gap_refine.h"
#include "trim/detail/open_edges.h"
#include "trim/face_surface.h"
#include "trim/face_tessellation.h"
#include "trim/gap_triangulate.h"
#include "trim/trim_cut.h"

namespace tessera {
namespace {

using trim_detail::EdgeKey;
using trim_detail::FaceTriangle;
using trim_detail::FaceVertex;
using trim_detail::edgeKey;

std::string faceName(const TrimmedFace& face, size_t position) {
  return face.label.empty() ? "face " + std::to_string(position) : face.label;
}

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// One face's vertices (detail/gap_refine.h) in its own (u, v). A trim point is keyed by its
// shared id and uv (a seam edge brings the same id twice, at u = 0 and u = 2π), a quad-tree
// vertex by its mesh vertex and uv (a collapsed edge welds corners of different uv into one).
class FaceBuilder {
 public:
  std::vector<FaceVertex> vertices;

  // The vertex among `candidates` (those of one key) within `weld` of uv, or a new one.
  uint32_t vertex(SmallIdList& candidates, glm::dvec2 uv, const glm::dvec3& position,
                  int64_t sharedId, double weld) {
    // The same uv (a quad-tree vertex seen again from the same piece, nearly always) is at
    // distance 0, within any weld: no square root.
    for (size_t k = 0; k < candidates.size(); ++k)
      if (vertices[candidates[k]].uv == uv || glm::length(vertices[candidates[k]].uv - uv) <= weld)
        return candidates[k];
    vertices.push_back({uv, position, sharedId});
    candidates.push_back(uint32_t(vertices.size() - 1));
    return uint32_t(vertices.size() - 1);
  }
};


// The (u, v) scale the gap is triangulated and refined in (docs/trimmed_faces.md, step 3): u
// scaled by a ratio rounded to a power of two, so the scaling is exact and every orientation
// sign the gap's predicates see is the unscaled one. The ratio makes a triangle's error about
// the same along u and v: a chord of parameter length d along u is off the surface by about
// ⅛·b_u·d² (FaceSurface::meanScales), so d_u = √(8δ/b_u) is the longest allowed, and scaling u
// by 1/d_u and v by 1/d_v makes every allowed triangle about unit size. Where the surface is
// flat along a direction (a cylinder's rulings: b_v = 0), its allowed length is the face's own
// extent, not infinite: longer does not exist and the gap's triangles would turn into slivers.
// On a face flat both ways at δ, the surface's 3D proportions (meanScales' speeds).
glm::dvec2 gapMetric(const FaceSurface& surface, glm::dvec2 lo, glm::dvec2 hi, double tolerance) {
  const FaceSurface::Scales scales = surface.meanScales(lo, hi);
  const glm::dvec2 speeds = scales.speeds, bending = scales.bending;
  const glm::dvec2 extent = hi - lo;
  const auto allowed = [&](double b, double e) {
    return b > 0 ? std::min(std::sqrt(8.0 * tolerance / b), e) : e;
  };
  const double du = allowed(bending.x, extent.x), dv = allowed(bending.y, extent.y);
  const bool flat = du >= extent.x && dv >= extent.y;
  const double ratio = flat ? speeds.x / speeds.y : dv / du;
  return {std::exp2(std::round(std::log2(ratio))), 1.0};
}

}  // namespace

void validateTrimmedModel(const TrimmedModel& model) {
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const TrimmedFace& face = model.faces[f];
    const auto fail = [&](const std::string& why) {
      throw std::invalid_argument("trimmed model: " + faceName(face, f) + ": " + why);
    };
    if (face.pieces.empty()) fail("no surface pieces");
    for (size_t k = 0; k < face.pieces.size(); ++k) {
      const BezierPatchPiece& p = face.pieces[k];
      if (!(std::isfinite(p.u0) && std::isfinite(p.u1) && std::isfinite(p.v0) &&
            std::isfinite(p.v1) && p.u1 > p.u0 && p.v1 > p.v0))
        fail("piece " + std::to_string(k) + " has an empty or non-finite rectangle");
    }
    for (size_t l = 0; l < face.loops.size(); ++l) {
      const TrimLoop& loop = face.loops[l];
      const std::string name = "loop " + std::to_string(l);
      if (loop.uv.size() < 3) fail(name + " has " + std::to_string(loop.uv.size()) + " points");
      if (loop.pointIds.size() != loop.uv.size())
        fail(name + " has " + std::to_string(loop.pointIds.size()) + " point ids for " +
             std::to_string(loop.uv.size()) + " points");
      for (size_t k = 0; k < loop.uv.size(); ++k) {
        if (!std::isfinite(loop.uv[k].x) || !std::isfinite(loop.uv[k].y))
          fail(name + " point " + std::to_string(k) + " is not finite");
        if (loop.pointIds[k] >= model.sharedPoints.size())
          fail(name + " point " + std::to_string(k) + " has id " +
               std::to_string(loop.pointIds[k]) + " past the " +
               std::to_string(model.sharedPoints.size()) + " shared points");
      }
    }
  }
}

namespace {

// One face cut, refined and measured, in its own vertex numbering; emitted later in face order.
struct FaceMesh {
  std::vector<FaceVertex> vertices;
  std::vector<FaceTriangle> triangles;  // emission order and orientation (reversed faces flipped)
  std::vector<bool> collapsed;          // per triangle: two corners on one vertex or shared id
  TrimmedFaceStats stats;
  double classifyMs = 0, gapMs = 0, refineMs = 0, measureMs = 0;  // this face's thread time
};

FaceMesh meshFace(const TrimmedModel& model, size_t f, const Tessellation& tess,
                  const TrimmedMeshOptions& options) {
  const TrimmedFace& face = model.faces[f];
  TrimmedFaceStats stats;
  stats.faceIndex = face.faceIndex;
  const FaceSurface surface(face);

  // The face's size in (u, v) sets the two length scales: vertices this close are one
  // (rounding of the same point), and a trim segment this close to a triangle makes it
  // Crossing (a conservative call: dropping a triangle only re-triangulates its place).
  glm::dvec2 lo(face.pieces[0].u0, face.pieces[0].v0), hi = lo;
  for (const BezierPatchPiece& p : face.pieces)
    lo = glm::min(lo, {p.u0, p.v0}), hi = glm::max(hi, {p.u1, p.v1});
  for (const TrimLoop& loop : face.loops)
    for (glm::dvec2 uv : loop.uv) lo = glm::min(lo, uv), hi = glm::max(hi, uv);
  const double size = std::max(hi.x - lo.x, hi.y - lo.y);
  FaceBuilder builder;
  const double margin = 1e-9 * size;
  // One quad-tree vertex seen from two pieces has two fp32 local uvs (cornerUv): one
  // vertex within 10⁻⁶ of the face; a collapsed edge's corners, a whole side apart, stay
  // apart. Trim points are given in double: 10⁻⁹.
  const double meshWeld = 1e-6 * size, trimWeld = 1e-9 * size;

  stats.quadtreeTriangles = tess.mesh.triangleCount();
  FaceMesh out;
  Stopwatch step;

  // The vertices of each quad-tree mesh vertex (a flat array by its id) and of each shared
  // trim point (hashed: the ids run over the whole model); looked up, never walked.
  std::vector<SmallIdList> meshKeyed(tess.mesh.positions.size());
  HashMap<int64_t, SmallIdList> trimKeyed;
  const TrimSegmentIndex index(face.loops);
  size_t loopPoints = 0;
  for (const TrimLoop& loop : face.loops) loopPoints += loop.uv.size();
  // Room for every vertex and triangle before the gap's (grown by doubling, their copies were a
  // twentieth of the cut on the IDF library's small faces).
  builder.vertices.reserve(tess.mesh.positions.size() + loopPoints);
  std::vector<FaceTriangle> triangles;
  triangles.reserve(tess.mesh.triangleCount() + loopPoints);
  for (size_t t = 0; t < tess.mesh.triangleCount(); ++t) {
    std::array<uint32_t, 3> v;
    std::array<glm::dvec2, 3> uv;
    for (int k = 0; k < 3; ++k) {
      const uint32_t id = tess.mesh.indices[3 * t + k];
      uv[k] = surface.faceUv(tess.trianglePatch[t], glm::dvec2(tess.cornerUv[3 * t + k]));
      v[k] = builder.vertex(meshKeyed[id], uv[k], glm::dvec3(tess.mesh.positions[id]), -1,
                            meshWeld);
    }
    const double area = cross(uv[1] - uv[0], uv[2] - uv[0]);
    if (area == 0) continue;
    if (area < 0) std::swap(v[1], v[2]), std::swap(uv[1], uv[2]);
    if (!face.loops.empty() && classifyTrimTriangle(uv, index, margin) != TrimClass::Inside)
      continue;
    triangles.push_back({v, false});
  }
  stats.keptTriangles = triangles.size();
  out.classifyMs = step.elapsedMs();
  step.restart();

  // The gap: bounded by the trim segments (material on their left) and by the kept
  // triangles' open edges, reversed.
  std::vector<std::pair<uint32_t, uint32_t>> gapEdges;
  std::vector<EdgeKey> trimEdges;  // sorted and made distinct below
  gapEdges.reserve(loopPoints), trimEdges.reserve(loopPoints);
  std::vector<double> sampledParametric;  // per triangle, where the refinement measured it
  trimKeyed.reserve(loopPoints);
  std::vector<uint32_t> ids;
  ids.reserve(loopPoints);
  for (const TrimLoop& loop : face.loops) {
    ids.clear();
    for (size_t k = 0; k < loop.uv.size(); ++k) {
      const uint32_t id = loop.pointIds[k];
      ids.push_back(
          builder.vertex(trimKeyed[id], loop.uv[k], model.sharedPoints[id], id, trimWeld));
    }
    for (size_t k = 0; k < ids.size(); ++k) {
      const uint32_t a = ids[k], b = ids[(k + 1) % ids.size()];
      if (a == b) continue;  // a repeated point
      gapEdges.push_back({a, b});
      trimEdges.push_back(edgeKey(a, b));
    }
  }
  std::sort(trimEdges.begin(), trimEdges.end());
  trimEdges.erase(std::unique(trimEdges.begin(), trimEdges.end()), trimEdges.end());
  if (!face.loops.empty()) {
    trim_detail::appendReversedOpenEdges(triangles, builder.vertices.size(), gapEdges);
    const std::optional<glm::dvec2> affineMetric =
        options.affineShortcut ? trim_detail::affineGapMetric(face, lo, hi, options.tolerance)
                               : std::nullopt;
    const glm::dvec2 metric =
        affineMetric ? *affineMetric : gapMetric(surface, lo, hi, options.tolerance);
    std::vector<glm::dvec2> points;
    points.reserve(builder.vertices.size());
    for (const FaceVertex& v : builder.vertices) points.push_back(v.uv * metric);
    const GapTriangulation gap = triangulateGap(points, gapEdges);
    stats.gapFailures = gap.failures;
    for (const auto& t : gap.triangles) triangles.push_back({t, true});
    out.gapMs = step.elapsedMs();
    step.restart();
    trim_detail::GapRefineResult refined;
    if (options.affineShortcut &&
        trim_detail::gapRefinementIdle(face, builder.vertices, options.tolerance))
      sampledParametric = trim_detail::cornerParametric(surface, builder.vertices, triangles);
    else
      refined = trim_detail::refineGap(
          surface, builder.vertices, triangles, trimEdges,
          {options.tolerance, options.deviationSubdivisions, options.maxRefineRounds, metric,
           options.gapMeasure},
          &sampledParametric);
    stats.refinementSplits = refined.changes;
    stats.unfinishedGapTriangles = refined.unfinished;
    out.refineMs = step.elapsedMs();
  }
  step.restart();

  // Orientation, collapsed triangles (two corners on one shared point: they become one mesh
  // vertex) and the measured deviation of what will be emitted.
  const std::vector<FaceVertex>& vs = builder.vertices;
  const auto oneVertex = [&](uint32_t a, uint32_t b) {
    return a == b || (vs[a].sharedId >= 0 && vs[a].sharedId == vs[b].sharedId);
  };
  out.collapsed.reserve(triangles.size());
  std::vector<double> trimOffset(vs.size(), -1.0);  // per vertex, once measured
  for (size_t index = 0; index < triangles.size(); ++index) {
    FaceTriangle& t = triangles[index];
    const std::array<uint32_t, 3> measured = t.v;
    if (face.reversed) std::swap(t.v[1], t.v[2]);
    const std::array<uint32_t, 3>& v = t.v;
    const bool collapsed = oneVertex(v[0], v[1]) || oneVertex(v[1], v[2]) || oneVertex(v[0], v[2]);
    out.collapsed.push_back(collapsed);
    if (collapsed) {
      ++stats.collapsedTriangles;
      continue;
    }
    ++stats.triangles;
    // The file's own offset of the trim points from the surface: part of the promise
    // (deviation ≤ δ + maxTrimPointOffset), measured whatever measureKeptTriangles says.
    stats.maxTrimPointOffset = std::max(
        stats.maxTrimPointOffset, trim_detail::cornerOffset(surface, vs, measured, &trimOffset));
    if (!t.gap && !options.measureKeptTriangles) continue;
    ++stats.measuredTriangles;
    const double parametric =
        index < sampledParametric.size() && sampledParametric[index] >= 0
            ? sampledParametric[index]
            : trim_detail::parametricDeviation(surface, vs, measured, options.deviationSubdivisions);
    stats.maxParametricDeviation = std::max(stats.maxParametricDeviation, parametric);
    if (t.gap)
      stats.maxGapParametricDeviation = std::max(stats.maxGapParametricDeviation, parametric);
    if (options.measureGeometric)
      stats.maxGeometricDeviation =
          std::max(stats.maxGeometricDeviation,
                   trim_detail::geometricDeviation(surface, vs, measured,
                                                   options.deviationSubdivisions));
  }
  stats.keptTriangles = 0;
  for (const FaceTriangle& t : triangles) (t.gap ? stats.gapTriangles : stats.keptTriangles)++;
  out.vertices = std::move(builder.vertices);
  out.triangles = std::move(triangles);
  out.stats = stats;
  out.measureMs = step.elapsedMs();
  return out;
}

}  // namespace

TrimmedMesh meshTrimmedModel(const TrimmedModel& model, const TrimmedMeshOptions& options,
                             Backend& backend, TrimClassifier* trim) {
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    throw std::invalid_argument("meshTrimmedModel: the tolerance must be finite and > 0");
  validateTrimmedModel(model);
  const Stopwatch total;
  TrimmedMesh out;
  TrimmedMeshTimings& timings = out.timings;

  // Step 1 for all faces at once: a few large backend calls instead of one per face.
  std::unique_ptr<TrimClassifier> mirrorTrim;
  if (options.trimQuadtree && !trim) trim = (mirrorTrim = makeMirrorTrimClassifier()).get();
  FaceTessellations tessellations = tessellateFaces(
      model, options.tolerance, options.frame ? *options.frame : trimmedModelFrame(model), backend,
      options.trimQuadtree ? trim : nullptr, options.threads);
  timings.treeMs = tessellations.treeMs;
  timings.trimMs = tessellations.trimMs;
  timings.triangulateMs = tessellations.triangulateMs;
  timings.evaluateMs = tessellations.evaluateMs;
  timings.assembleMs = tessellations.assembleMs;
  timings.trees = tessellations.trees;
  timings.leaves = tessellations.leaves;
  timings.trimmedAwayLeaves = tessellations.trimmedAwayLeaves;

  // Steps 2–4 and the stats, faces in parallel (each face's work is its own), a face at a time:
  // one face can cost as much as a hundred others (a B-spline face's refinement), and even
  // shares left a thread idle behind the one that drew it. Largest first, by the quad-tree
  // triangles to classify plus the loop points to bridge and refine around (known before the
  // cut, they order the IDF library's faces almost as their measured times do): taken in face
  // order, a large face met late kept one core busy alone at the end of a model.
  Stopwatch step;
  std::vector<FaceMesh> faces(model.faces.size());
  std::vector<double> estimates(model.faces.size());
  for (size_t f = 0; f < model.faces.size(); ++f) {
    estimates[f] = double(tessellations.faces[f].mesh.triangleCount());
    for (const TrimLoop& loop : model.faces[f].loops) estimates[f] += double(loop.uv.size());
  }
  parallelForLargestFirst(estimates, options.threads, [&](size_t f) {
    faces[f] = meshFace(model, f, tessellations.faces[f], options);
    tessellations.faces[f] = Tessellation();  // its memory back early
  });
  timings.cutMs = step.elapsedMs();
  for (const FaceMesh& face : faces) {
    timings.classifyCpuMs += face.classifyMs;
    timings.gapCpuMs += face.gapMs;
    timings.refineCpuMs += face.refineMs;
    timings.measureCpuMs += face.measureMs;
  }

  // Step 5, in face order so the vertex numbering does not depend on the threads: trim points
  // as their shared vertex, the rest as their face's own vertices.
  step.restart();
  std::vector<int64_t> sharedVertex(model.sharedPoints.size(), -1);
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const FaceMesh& face = faces[f];
    const std::vector<FaceVertex>& vs = face.vertices;
    std::vector<int64_t> global(vs.size(), -1);
    auto globalOf = [&](uint32_t v) -> uint32_t {
      if (global[v] >= 0) return uint32_t(global[v]);
      int64_t* slot = vs[v].sharedId >= 0 ? &sharedVertex[vs[v].sharedId] : &global[v];
      if (*slot < 0) {
        *slot = int64_t(out.mesh.positions.size());
        out.mesh.positions.push_back(glm::vec3(vs[v].position));
        out.mesh.uvs.push_back(glm::vec2(vs[v].uv));
        out.mesh.patchIds.push_back(uint32_t(f));
      }
      global[v] = *slot;
      return uint32_t(*slot);
    };
    for (size_t t = 0; t < face.triangles.size(); ++t) {
      const std::array<uint32_t, 3>& v = face.triangles[t].v;
      const uint32_t g0 = globalOf(v[0]), g1 = globalOf(v[1]), g2 = globalOf(v[2]);
      if (face.collapsed[t]) continue;
      out.mesh.indices.insert(out.mesh.indices.end(), {g0, g1, g2});
      out.triangleFace.push_back(uint32_t(f));
      for (uint32_t k : v) out.cornerUv.push_back(vs[k].uv);
    }
    out.faces.push_back(face.stats);
  }
  out.mesh.validate();
  timings.emitMs = step.elapsedMs();
  timings.totalMs = total.elapsedMs();
  return out;
}

std::vector<std::string> unfinishedRefinementWarnings(const TrimmedMesh& mesh, double tolerance) {
  std::vector<std::string> warnings;
  for (const TrimmedFaceStats& f : mesh.faces) {
    if (f.unfinishedGapTriangles == 0) continue;
    // The refinement's test is conservative (sampled, with a margin for rounding) and the stats
    // sample otherwise: the measured distance can be within δ where the test did not show it
    // (CAP_50SGV_8_10 at 0.01: 0.009972). Said as it is, with the file's own part: trim points
    // off the surface, which no split reduces.
    char text[384];
    int length = std::snprintf(text, sizeof text,
                               "face %u: the gap refinement ran out of rounds with %zu triangle%s "
                               "it could not show within the tolerance %.4g",
                               f.faceIndex, f.unfinishedGapTriangles,
                               f.unfinishedGapTriangles == 1 ? "" : "s", tolerance);
    if (f.measuredTriangles != 0 && f.maxGeometricDeviation > 0)
      length +=
          std::snprintf(text + length, sizeof text - size_t(length),
                        "; measured up to %.4g from the surface (%s)", f.maxGeometricDeviation,
                        f.maxGeometricDeviation <= tolerance ? "within it" : "over it");
    if (f.maxTrimPointOffset > 1e-3 * tolerance)
      std::snprintf(text + length, sizeof text - size_t(length),
                    "; its trim points lie up to %.3g off the surface (the file's edges)",
                    f.maxTrimPointOffset);
    warnings.push_back(text);
  }
  return warnings;
}

}  // namespace tessera
