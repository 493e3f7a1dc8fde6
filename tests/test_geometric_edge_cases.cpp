// Shapes that break naive tessellators, through the public tessellate() API on the CPU
// backend and on Vulkan: a patch collapsed to a point, collapsed edges, a cusp, zero-length
// corner tangents, a patch that folds over itself. Each must give a finite mesh (no NaN, no
// infinity), every leaf must record why it ended, and refinement that can never pass the
// tests (the tangent flips at a cusp, the normal at a fold) must stop at the documented
// limits — the maximum depth, or the minimum node size — with that cause on the leaves
// (docs/quadtree.md, "A node and its decision").
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "gpu_test_context.h"
#include "quadtree_compare.h"
#include "mesh/tessellate.h"

using namespace tessera;

namespace {

// A bicubic patch from a function of the control-net indices (i along u, j along v).
BezierPatch net(const std::function<glm::dvec3(int i, int j)>& point) {
  BezierPatch p;
  p.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.at(i, j) = point(i, j);
  return p;
}

struct EdgeCase {
  std::string name;
  BezierPatch patch;
  bool refinesToTheLimit;  // no node near the defect can pass, so some leaf hits the limit
  // The defect's line v = const where a split may land on it instead (< 0: none). A node
  // with the cusp on its side sees no tangent there (a missing direction passes).
  float defectV = -1.0f;
};

std::vector<EdgeCase> edgeCases() {
  std::vector<EdgeCase> cases;
  cases.push_back({"all control points equal", net([](int, int) { return glm::dvec3(1, 2, 3); }),
                   false});
  // Row i = 0 collapsed to one point: a curved triangle (the teapot lid's top is like this).
  cases.push_back({"one collapsed edge", net([](int i, int j) {
                     const double r = i / 3.0;
                     return glm::dvec3(r * (j - 1.5), r * 2.0, 0.3 * r * r * (j % 2));
                   }),
                   false});
  // Rows i = 0 and i = 3 collapsed: a lens whose two poles are points.
  cases.push_back({"two collapsed edges", net([](int i, int j) {
                     const double w = (i == 0 || i == 3) ? 0.0 : 1.0;
                     return glm::dvec3(i, w * (j - 1.5), w * 0.5 * (j == 1 || j == 2));
                   }),
                   false});
  // Every v-curve is the cubic with control points (0,0), (1,1), (0,1), (1,0): its derivative
  // vanishes at v = 1/2, where the curve turns back on itself (a cusp), extruded along u.
  cases.push_back({"cusp", net([](int i, int j) {
                     const double x[4] = {0, 1, 0, 1}, y[4] = {0, 1, 1, 0};
                     return glm::dvec3(x[j], y[j], i);
                   }),
                   true, 0.5f});
  // b_00 = b_01 = b_10: Pu and Pv are both zero at the corner (u, v) = (0, 0).
  cases.push_back({"zero-length tangents at a corner", net([](int i, int j) {
                     if (i <= 1 && j <= 1 && i + j <= 1) return glm::dvec3(0, 0, 0);
                     return glm::dvec3(i, j, 0.2 * i * j);
                   }),
                   false});
  // The u-curves run out to x = 2, back to x = −1, then to 1: the surface folds over itself
  // along two lines where Pu reverses and the normal flips.
  cases.push_back({"folding over itself", net([](int i, int j) {
                     const double x[4] = {0, 2, -1, 1};
                     return glm::dvec3(x[i], j, 0.1 * i * j);
                   }),
                   true});
  return cases;
}

void requireFiniteMesh(const Tessellation& t) {
  REQUIRE_NOTHROW(t.mesh.validate());  // throws on a NaN or infinite coordinate
  for (const glm::vec3& p : t.mesh.positions) REQUIRE(std::isfinite(p.x + p.y + p.z));
  for (const glm::vec3& n : t.mesh.normals) REQUIRE(std::isfinite(n.x + n.y + n.z));
  for (const glm::vec2& uv : t.cornerUv) REQUIRE(std::isfinite(uv.x + uv.y));
}

// Every leaf ended for a recorded reason consistent with the limits; returns how many leaves
// ended at the limits (maximum depth or minimum size).
size_t checkCauses(const Tessellation& t, const QuadtreeOptions& o) {
  size_t atLimit = 0;
  for (const QuadLeaf& leaf : t.tree.leaves) {
    REQUIRE(leaf.cause != gpu::kCauseSplit);
    REQUIRE(leaf.level <= o.maxDepth);
    REQUIRE(std::isfinite(leaf.linearity));
    REQUIRE(std::isfinite(leaf.flatness));
    if (leaf.cause == gpu::kCauseMaxDepth) REQUIRE(leaf.level == o.maxDepth);
    if (leaf.cause == gpu::kCauseMaxDepth || leaf.cause == gpu::kCauseMinSize) ++atLimit;
  }
  return atLimit;
}

void runEdgeCases(Backend& backend, const char* backendName) {
  for (const EdgeCase& c : edgeCases()) {
    for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax}) {
      QuadtreeOptions o;
      o.rule = rule;
      o.maxDepth = 8;
      INFO(backendName << ", " << c.name << ", rule " << splitRuleLetter(rule));
      const Tessellation t = tessellate({c.patch}, o, backend);
      requireFiniteMesh(t);
      const size_t atLimit = checkCauses(t, o);
      INFO(t.tree.leaves.size() << " leaves, " << atLimit << " at the depth limit, "
                                << t.mesh.triangleCount() << " triangles");
      if (c.refinesToTheLimit) {
        // The limit stops it, and only along the defect's line: far fewer leaves than the
        // 4^8 = 65536 of a full tree at that depth. Or a split put the line on the nodes'
        // sides: rule C's sample at v = 1/2 is the cusp, where rounding leaves κ largest (in
        // the model's local frame; at the model's own coordinates, 0 and 1, it ran to the
        // limit), and no leaf may then straddle the line.
        size_t straddling = 0, onSide = 0;
        for (const QuadLeaf& leaf : t.tree.leaves) {
          straddling += leaf.rect.y < c.defectV && c.defectV < leaf.rect.w;
          onSide += leaf.rect.y == c.defectV || leaf.rect.w == c.defectV;
        }
        INFO(straddling << " leaves straddle the defect's line, " << onSide << " end on it");
        REQUIRE((atLimit > 0 || (onSide > 0 && straddling == 0)));
        REQUIRE(t.tree.leaves.size() < 8192);
      }
      if (rule == SplitRule::Midpoint)
        WARN(backendName << ", " << c.name << ": " << t.tree.leaves.size() << " leaves ("
                         << atLimit << " at the limit), depth " << t.stats.depth << ", "
                         << t.mesh.triangleCount() << " triangles");
    }
  }
}

}  // namespace

TEST_CASE("degenerate, cusped and folding patches give finite meshes and recorded limits (CPU)",
          "[tessellate][edge-cases]") {
  Backend cpu = makeMirrorBackend();
  runEdgeCases(cpu, "cpu");
}

TEST_CASE("a cusp stops at the minimum node size when the depth allows more, with that cause",
          "[tessellate][edge-cases]") {
  Backend cpu = makeMirrorBackend();
  QuadtreeOptions o;
  o.maxDepth = 24;
  o.minSize = 1.0f / 256.0f;  // reached at depth 8 by midpoint splits
  const EdgeCase cusp = edgeCases()[3];
  REQUIRE(cusp.name == "cusp");
  const Tessellation t = tessellate({cusp.patch}, o, cpu);
  requireFiniteMesh(t);
  size_t minSizeLeaves = 0;
  for (const QuadLeaf& leaf : t.tree.leaves) {
    REQUIRE(leaf.cause != gpu::kCauseMaxDepth);
    if (leaf.cause == gpu::kCauseMinSize) {
      ++minSizeLeaves;
      REQUIRE(std::min(leaf.rect.z - leaf.rect.x, leaf.rect.w - leaf.rect.y) < o.minSize);
    }
  }
  INFO(t.tree.leaves.size() << " leaves, depth " << t.stats.depth);
  REQUIRE(minSizeLeaves > 0);
  REQUIRE(t.stats.depth <= 9);
}

TEST_CASE("degenerate, cusped and folding patches on Vulkan: finite, and the same trees as the CPU",
          "[gpu][tessellate][edge-cases]") {
  vk::Context& context = test::gpuContext();
  Backend gpu = makeVulkanBackend(context, 0);  // every level on the device (one patch: all small)
  runEdgeCases(gpu, "vulkan");
  Backend cpu = makeMirrorBackend();
  for (const EdgeCase& c : edgeCases()) {
    QuadtreeOptions o;
    o.maxDepth = 8;
    const Tessellation a = tessellate({c.patch}, o, gpu);
    const Tessellation b = tessellate({c.patch}, o, cpu);
    INFO(c.name << ": Vulkan " << a.tree.leaves.size() << " leaves, CPU " << b.tree.leaves.size());
    if (context.info().isLavapipe()) {
      REQUIRE(test::identicalTrees(a.tree, b.tree));
    } else {
      REQUIRE(double(a.tree.leaves.size()) == Approx(double(b.tree.leaves.size())).epsilon(0.02));
    }
  }
  test::requireValidationClean();
}
