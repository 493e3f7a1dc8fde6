// Real-time frames are watertight by construction (issue 16): on four teapots (one of them
// four times smaller, beside the others) at seven camera positions, among them cameras inside
// a teapot and next to its body (patches cut by the eye plane) and close-ups (neighbouring
// patches whose counts are over 4× apart), the mesh read back from the GPU is checked after welding bit-equal
// positions:
// - no cracks: every shared edge of two visible patches has the same count on both sides and
//   the same vertex positions bit for bit, and the open edges are exactly the segments of the
//   sides no visible patch shares;
// - no T-junctions (no vertex inside an open edge) and no edge used by three triangles;
// - the screen-space error of the frame against the double surface is ≤ the tolerance (also
//   where close views cap a few counts at 128).
#include <catch2/catch.hpp>

#include <cstring>
#include <map>
#include <sstream>
#include <string>

#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "mesh/shared_edges.h"
#include "mesh_checks.h"
#include "realtime/detail/stitch_mirror.h"
#include "realtime/frame.h"

using namespace tessera;

namespace {

std::vector<BezierPatch> fourTeapots() {
  const std::vector<BezierPatch> teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  std::vector<BezierPatch> scene;
  const glm::dvec3 offsets[4] = {{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {4.5, 3, 0}};
  for (int c = 0; c < 4; ++c)
    for (BezierPatch p : teapot) {
      for (glm::dvec3& q : p.cp) q = (c == 3 ? 0.25 : 1.0) * q + offsets[c];
      scene.push_back(p);
    }
  return scene;
}

Camera view(const glm::dvec3& eye, const glm::dvec3& target) {
  return lookAtCamera(eye, target, {0, 0, 1}, 0.8, 960, 540, 0.05, 200.0);
}

struct FrameDefects {
  size_t sharedSides = 0;        // side pairs of two visible patches compared
  size_t countMismatches = 0;    // pairs whose edge counts differ
  size_t vertexMismatches = 0;   // edge points whose positions differ between the two sides
  size_t openEdges = 0, expectedOpenEdges = 0;
  size_t overusedEdges = 0, tJunctions = 0;
  double largestGap = 0;
  double largestCountRatio = 1;  // max(N_u, N_v) of two patches sharing an edge, larger/smaller
  size_t degenerateTriangles = 0;  // after welding
  std::string unexpectedOpen;      // where the first open edges off the unshared sides lie
};

// Where frame vertex v comes from: its patch and its place in the patch's pattern (an inner
// vertex, or point k of side s), for the report of an unexpected open edge.
std::string vertexOrigin(const RealtimeFrame& frame, uint32_t v) {
  for (const gpu::StitchPatch& r : frame.records) {
    if (v < r.firstVertex || v >= r.firstVertex + mirror::stitchVertexCount(r)) continue;
    std::ostringstream text;
    text << "patch " << r.patchIndex << " (" << r.nu << "x" << r.nv << ")";
    for (uint32_t s = 0; s < 4; ++s)
      for (uint32_t k = 0; k <= r.sideSegments[s]; ++k)
        if (r.firstVertex + mirror::stitchSideVertex(r, s, k) == v) {
          text << " side " << s << " point " << k << "/" << r.sideSegments[s]
               << ((r.sideFlags[s] & gpu::kStitchCollapsed) ? " collapsed" : "");
          return text.str();
        }
    text << " inner " << v - r.firstVertex;
    return text.str();
  }
  return "no patch";
}

bool samePosition(const gpu::GridVertex& a, const gpu::GridVertex& b) {
  return std::memcmp(&a.position, &b.position, sizeof a.position) == 0;
}

FrameDefects checkFrame(const RealtimeFrame& frame, const std::vector<BezierPatch>& scene,
                        const PatchTopology& topology, double eps) {
  FrameDefects d;
  std::map<uint32_t, const gpu::StitchPatch*> recordOf;
  for (const gpu::StitchPatch& r : frame.records) recordOf[r.patchIndex] = &r;
  // Sides of each shared group that are visible this frame.
  std::map<int32_t, std::vector<std::pair<const gpu::StitchPatch*, uint32_t>>> groups;
  for (const gpu::StitchPatch& r : frame.records)
    for (uint32_t s = 0; s < 4; ++s) {
      const SideInfo& info = topology.sides[r.patchIndex][s];
      if (info.group >= 0) groups[info.group].push_back({&r, s});
      if (info.collapsed) continue;
      // Open unless another visible patch has this curve.
      bool partner = false;
      if (info.group >= 0)
        for (size_t p = 0; p < scene.size() && !partner; ++p)
          for (uint32_t t = 0; t < 4; ++t)
            if ((p != r.patchIndex || t != s) && topology.sides[p][t].group == info.group &&
                recordOf.count(uint32_t(p)))
              partner = true;
      if (!partner) d.expectedOpenEdges += r.sideSegments[s];
    }
  for (const auto& [group, members] : groups)
    for (size_t m = 1; m < members.size(); ++m) {
      const auto [a, sa] = members[0];
      const auto [b, sb] = members[m];
      ++d.sharedSides;
      const uint32_t na = std::max(a->nu, a->nv), nb = std::max(b->nu, b->nv);
      d.largestCountRatio = std::max(d.largestCountRatio, double(std::max(na, nb)) / std::min(na, nb));
      if (a->sideSegments[sa] != b->sideSegments[sb]) {
        ++d.countMismatches;
        continue;
      }
      const uint32_t e = a->sideSegments[sa];
      const bool reversed = ((a->sideFlags[sa] ^ b->sideFlags[sb]) & gpu::kStitchReversed) != 0;
      for (uint32_t k = 0; k <= e; ++k) {
        const uint32_t va = a->firstVertex + mirror::stitchSideVertex(*a, sa, k);
        const uint32_t vb = b->firstVertex + mirror::stitchSideVertex(*b, sb, reversed ? e - k : k);
        d.vertexMismatches += samePosition(frame.vertices[va], frame.vertices[vb]) ? 0 : 1;
      }
    }
  // The welded mesh: vertices with bit-equal positions become one.
  TriangleMesh mesh;
  std::map<std::array<uint32_t, 3>, uint32_t> weld;
  std::vector<uint32_t> welded(frame.vertexCount);
  std::vector<uint32_t> firstOf;  // a frame vertex of each welded one
  for (size_t v = 0; v < frame.vertexCount; ++v) {
    std::array<uint32_t, 3> key;
    std::memcpy(key.data(), &frame.vertices[v].position, sizeof key);
    const auto [it, inserted] = weld.emplace(key, uint32_t(mesh.positions.size()));
    if (inserted) {
      mesh.positions.push_back(glm::vec3(frame.vertices[v].position));
      firstOf.push_back(uint32_t(v));
    }
    welded[v] = it->second;
  }
  for (size_t k = 0; k < 3 * frame.triangles; ++k) mesh.indices.push_back(welded[frame.indices[k]]);
  const test::EdgeCensus census = test::censusOf(mesh, 0.0);
  d.openEdges = census.boundaryEdges;
  d.degenerateTriangles = census.degenerateTriangles;
  if (census.boundaryEdges != d.expectedOpenEdges) {
    // Name the open edges that are not segments of one unshared side (at most six).
    std::ostringstream text;
    int named = 0;
    for (const auto& [edge, count] : census.undirected) {
      if (count != 1 || named >= 6) continue;
      const std::string a = vertexOrigin(frame, firstOf[edge.first]);
      const std::string b = vertexOrigin(frame, firstOf[edge.second]);
      const bool sameSide = a.find(" side ") != std::string::npos &&
                            a.substr(0, a.find(" point ")) == b.substr(0, b.find(" point "));
      if (sameSide) continue;
      const glm::vec3 pa = mesh.positions[edge.first], pb = mesh.positions[edge.second];
      text << "\n  open edge " << a << " -> " << b << ", length " << glm::length(pb - pa);
      ++named;
    }
    d.unexpectedOpen = text.str();
  }
  d.overusedEdges = census.overusedEdges;
  d.tJunctions = test::tJunctionCount(mesh, census, eps, &d.largestGap);
  return d;
}

}  // namespace

TEST_CASE("Real-time frames: no cracks, no T-junctions, no non-manifold edges, within 1 px",
          "[gpu][realtime]") {
  vk::Context& context = test::gpuContext();
  const std::vector<BezierPatch> scene = fourTeapots();
  const PatchTopology topology = findSharedEdges(scene);
  RealtimeTessellator tessellator(context, scene, {1.0, 128});
  const std::vector<std::pair<const char*, Camera>> cameras = {
      {"overview", view({4, -16, 8}, {4, 4, 1})},
      {"small teapot beside large ones", view({4.5, -2, 3}, {4.5, 3, 0.5})},
      {"grazing close-up", view({-3.2, -0.4, 1.6}, {3, 0.5, 1.2})},
      {"next to the body", view({0, -1.9, 1.2}, {0, 0, 1.2})},
      {"close to the spout", view({2.2, -1.0, 2.0}, {3, 0, 2.0})},
      {"inside a teapot", view({8, 0, 1.5}, {0, 0, 1.5})},
      {"from above", view({4, 2, 14}, {4, 4, 0})},
  };
  double largestRatio = 1;
  for (const auto& [name, camera] : cameras) {
    const RealtimeFrame& frame = tessellator.tessellate(camera);
    const FrameDefects d = checkFrame(frame, scene, topology, 1e-6 * 12.0);
    const ScreenErrorReport error = measureScreenError(frame, scene, camera, 2);
    largestRatio = std::max(largestRatio, d.largestCountRatio);
    WARN(name << ": " << frame.records.size() << " patches, " << frame.triangles
              << " triangles (counts ask " << frame.countedTriangles << "), " << frame.fallback
              << " eye-plane fallbacks, " << frame.capped << " capped; " << d.sharedSides << " shared sides, "
              << d.countMismatches << " count and " << d.vertexMismatches
              << " vertex mismatches, open edges " << d.openEdges << " (expected "
              << d.expectedOpenEdges << "), " << d.overusedEdges << " overused, " << d.tJunctions
              << " T-junctions (longest " << d.largestGap << "), neighbour count ratio up to "
              << d.largestCountRatio << "; error " << error.maxAffinePixels << " px affine, "
              << error.maxPerspectivePixels << " px perspective; " << d.degenerateTriangles
              << " degenerate triangles after welding" << d.unexpectedOpen);
    CHECK(frame.records.size() > 0);
    CHECK(d.sharedSides > 0);
    CHECK(d.countMismatches == 0);
    CHECK(d.vertexMismatches == 0);
    CHECK(d.openEdges == d.expectedOpenEdges);
    CHECK(d.overusedEdges == 0);
    CHECK(d.tJunctions == 0);
    CHECK(error.triangles > 0);
    CHECK(error.maxAffinePixels <= 1.0);
    if (std::string(name) == "inside a teapot") CHECK(frame.fallback > 0);
  }
  CHECK(largestRatio >= 4.0);  // the views do put very different counts side by side
  test::requireValidationClean();
}
