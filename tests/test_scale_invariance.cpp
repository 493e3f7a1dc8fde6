// The same answer at any scale and position (issue 18): tessellate() works in the model's
// local frame (geometry/model_frame.h), so the teapot scaled by 10⁻³⁰..10³⁰ or moved by up to
// 10¹² gets the tree it gets at the origin, for rules A–D and T (δ relative to its size), on
// the fp32 mirror and on Vulkan; the mesh comes back in model coordinates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/bezier.h"
#include "geometry/model_frame.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "io/stats_report.h"
#include "mesh/result_warnings.h"
#include "mesh/tessellate.h"
#include "mesh/triangulate.h"
#include "quadtree/tolerance.h"
#include "sweep_share.h"
#include "trim/mesher.h"
#include "trimmed_models.h"
#include "vector_difference.h"

using namespace tessera;

namespace {

const std::vector<BezierPatch>& teapot() {
  static const std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  return patches;
}

// Every control point p → p·scale + offset, in double (one rounding per coordinate).
std::vector<BezierPatch> placed(std::vector<BezierPatch> patches, double scale,
                                glm::dvec3 offset = glm::dvec3(0.0)) {
  for (BezierPatch& p : patches)
    for (glm::dvec3& c : p.cp) c = c * scale + offset;
  return patches;
}

// The teapot with every coordinate rounded to a multiple of 2⁻¹²: |x| < 4, so x + c is exact in
// double for |c| ≤ 2⁴⁰ (≈ 1.1·10¹²; 52 bits hold 2⁴⁰ in steps of 2⁻¹²), and so are the box's
// halves and midpoint: the moved model is exactly the origin's, moved. The real teapot's 1.4 at
// 10¹² is 10¹² + 1.4 rounded to 2⁻¹³ (another model, by 3·10⁻⁵ of its size).
const std::vector<BezierPatch>& gridTeapot() {
  static const std::vector<BezierPatch> patches = [] {
    std::vector<BezierPatch> p = teapot();
    for (BezierPatch& patch : p)
      for (glm::dvec3& c : patch.cp) c = glm::round(c * 4096.0) / 4096.0;
    return p;
  }();
  return patches;
}

QuadtreeOptions optionsFor(char rule, const std::vector<BezierPatch>& patches) {
  if (rule == 'T') return toleranceOptions(1e-3 * controlPointDiagonal(patches));  // 0.1%
  QuadtreeOptions options;
  options.rule = parseSplitRule(std::string(1, rule));
  return options;
}

Tessellation onMirror(const std::vector<BezierPatch>& patches, char rule) {
  Backend mirror = makeMirrorBackend();
  return tessellate(patches, optionsFor(rule, patches), mirror);
}

// Leaves equal in patch, level, path, cause, rectangle and test values, bit for bit, in order.
size_t differingLeaves(const QuadtreeResult& a, const QuadtreeResult& b) {
  if (a.leaves.size() != b.leaves.size()) return std::max(a.leaves.size(), b.leaves.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.leaves.size(); ++i) {
    const QuadLeaf &x = a.leaves[i], &y = b.leaves[i];
    differing += !(x.patchIndex == y.patchIndex && x.level == y.level && x.path == y.path &&
                   x.cause == y.cause && std::memcmp(&x.rect, &y.rect, sizeof x.rect) == 0 &&
                   std::memcmp(&x.split, &y.split, sizeof x.split) == 0 &&
                   std::memcmp(&x.linearity, &y.linearity, sizeof(float)) == 0 &&
                   std::memcmp(&x.flatness, &y.flatness, sizeof(float)) == 0);
  }
  return differing;
}

// The largest |p − (scale·q + offset)| over the two meshes' positions, over the largest
// |coordinate| of the first: the mesh is the origin's, placed, up to fp32 rounding.
double placementError(const TriangleMesh& placedMesh, const TriangleMesh& origin, double scale,
                      glm::dvec3 offset) {
  double worst = 0, largest = 0;
  for (size_t i = 0; i < placedMesh.positions.size(); ++i) {
    const glm::dvec3 p(placedMesh.positions[i]);
    const glm::dvec3 expected = glm::dvec3(origin.positions[i]) * scale + offset;
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst, std::abs(p[k] - expected[k]));
      largest = std::max(largest, std::abs(p[k]));
    }
  }
  return largest > 0 ? worst / largest : 0.0;
}

std::string scaleName(int exponent) { return "1e" + std::to_string(exponent); }

}  // namespace

TEST_CASE("local frame: the teapot's frame at 10^±300 and moved, without overflow", "[scale]") {
  const ModelFrame origin = modelFrame(teapot());
  const std::vector<BezierPatch> local = toLocalFrame(teapot(), origin);
  // The box is [−3, 3.525] × [−2, 2] × [0, 3.15]: centre (0.2625, 0, 1.575), half-extent 3.2625.
  CHECK(origin.centre.x == Approx(0.2625).epsilon(1e-15));
  CHECK(origin.centre.y == 0.0);
  CHECK(origin.centre.z == Approx(1.575).epsilon(1e-15));
  CHECK(origin.scale == Approx(3.2625).epsilon(1e-15));
  for (double scale : {1e-300, 1e-30, 1e30, 1e300}) {
    const ModelFrame frame = modelFrame(placed(teapot(), scale));
    CHECK(std::isfinite(frame.scale));
    CHECK(frame.scale / scale == Approx(origin.scale).epsilon(1e-15));
    const std::vector<BezierPatch> scaled = toLocalFrame(placed(teapot(), scale), frame);
    size_t differing = 0;  // local points whose fp32 rounding differs from the origin's
    for (size_t p = 0; p < scaled.size(); ++p)
      for (size_t i = 0; i < scaled[p].cp.size(); ++i)
        differing += glm::vec3(scaled[p].cp[i]) != glm::vec3(local[p].cp[i]);
    WARN("teapot × " << scale << ": " << differing << " local control points differ in fp32");
    CHECK(differing == 0);
  }
  for (double offset : {1e6, 1e12}) {
    const ModelFrame frame = modelFrame(placed(gridTeapot(), 1.0, glm::dvec3(offset)));
    const ModelFrame at0 = modelFrame(gridTeapot());
    CHECK(frame.scale == at0.scale);
    CHECK(frame.centre - glm::dvec3(offset) == at0.centre);
  }
  // Weight-0 points (no position: scenes keep them at the origin) are not part of the box.
  BezierPatch rational = teapot()[0];
  rational.weights.assign(rational.cp.size(), 1.0);
  rational.weights[5] = 0.0;
  rational.cp[5] = glm::dvec3(1e9);
  const ModelFrame withZero = modelFrame({rational});
  CHECK(withZero.scale < 10.0);
  CHECK(toLocalFrame({rational}, withZero)[0].cp[5] == glm::dvec3(0.0));
}

TEST_CASE("local frame: the teapot scaled by 10^k has the tree it has at 10^0, rules A-D and T",
          "[scale]") {
  // Every fifth power from 10^-30 to 10^30 and the scales of issue 18; under the sanitizers
  // (sweep_share.h) a spread share of them, the extremes always.
  std::vector<int> exponents = test::sweptSubsetWithEnds(
      std::vector<int>{-30, -25, -22, -20, -15, -12, -10, -5, 5, 10, 15, 20, 25, 30});
  for (char rule : {'A', 'B', 'C', 'D', 'T'}) {
    const Tessellation origin = onMirror(teapot(), rule);
    size_t worstDiffering = 0;
    double worstPlacement = 0;
    for (int k : exponents) {
      const double scale = std::pow(10.0, k);
      const Tessellation t = onMirror(placed(teapot(), scale), rule);
      const size_t differing = differingLeaves(t.tree, origin.tree);
      worstDiffering = std::max(worstDiffering, differing);
      INFO("rule " << rule << ", teapot × " << scaleName(k) << ": " << t.tree.leaves.size()
                   << " leaves (origin " << origin.tree.leaves.size() << "), " << differing
                   << " differ; " << t.mesh.triangleCount() << " triangles (origin "
                   << origin.mesh.triangleCount() << ")");
      CHECK(differing == 0);
      CHECK(t.mesh.triangleCount() == origin.mesh.triangleCount());
      CHECK(test::vectorDifference(t.mesh.indices, origin.mesh.indices) == "");
      CHECK(t.mesh.normals == origin.mesh.normals);
      // Positions: the origin's mesh scaled, up to a few fp32 roundings (each is rounded
      // once from its local point; 10⁻³⁰·3.5 is still a normal fp32 number).
      const double placement = placementError(t.mesh, origin.mesh, scale, glm::dvec3(0.0));
      worstPlacement = std::max(worstPlacement, placement);
      CHECK(placement <= 0x1p-22);
      if (rule == 'T') {
        // Rule T's bounds are in local units; × boundScale they are model units within δ.
        const double delta = 1e-3 * controlPointDiagonal(placed(teapot(), scale));
        CHECK(largestLeafBound(t.tree) <= delta);
        CHECK(largestLeafBound(t.tree) / scale ==
              Approx(largestLeafBound(origin.tree)).epsilon(1e-12));
      }
    }
    WARN("rule " << rule << ": teapot × 1e-30..1e30 (" << exponents.size() << " scales): "
                 << origin.tree.leaves.size() << " leaves, " << origin.mesh.triangleCount()
                 << " triangles at 10^0; most differing leaves " << worstDiffering
                 << ", largest placement error " << worstPlacement << " of the largest coordinate");
  }
}

TEST_CASE("local frame: the teapot at 1e-300 keeps its triangles", "[scale]") {
  // fp32 flushes every coordinate to 0 (the fp32-output warning says so), but the tree, the
  // welding and the triangles are the origin's: they live in the local frame.
  for (char rule : {'B', 'T'}) {
    const Tessellation origin = onMirror(teapot(), rule);
    const Tessellation tiny = onMirror(placed(teapot(), 1e-300), rule);
    CHECK(differingLeaves(tiny.tree, origin.tree) == 0);
    CHECK(tiny.mesh.triangleCount() == origin.mesh.triangleCount());
    CHECK(test::vectorDifference(tiny.mesh.indices, origin.mesh.indices) == "");
    CHECK(tiny.mesh.positions[0] == glm::vec3(0.0f));
  }
}

TEST_CASE("local frame: the teapot moved up to 1e12 on each axis and all axes keeps its tree",
          "[scale]") {
  // gridTeapot: moved exactly (see there); each tree must equal the origin's bit for bit.
  // Under the sanitizers (sweep_share.h) a spread share of the 25 offsets, the farthest always.
  std::vector<glm::dvec3> offsets;
  for (double distance : {10.0, 1e3, 1e6, 1e9, 1e12})
    for (const glm::dvec3& direction :
         {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1), glm::dvec3(1, 1, 1),
          glm::dvec3(-1, 1, -1)})
      offsets.push_back(distance * direction);
  offsets = test::sweptSubsetWithEnds(offsets);
  for (char rule : {'A', 'B', 'C', 'D', 'T'}) {
    const Tessellation origin = onMirror(gridTeapot(), rule);
    size_t cases = 0;
    for (const glm::dvec3& offset : offsets) {
      const Tessellation t = onMirror(placed(gridTeapot(), 1.0, offset), rule);
      INFO("rule " << rule << ", grid teapot moved by (" << offset.x << ", " << offset.y << ", "
                   << offset.z << ")");
      CHECK(differingLeaves(t.tree, origin.tree) == 0);
      CHECK(test::vectorDifference(t.mesh.indices, origin.mesh.indices) == "");
      CHECK(t.mesh.normals == origin.mesh.normals);
      ++cases;
    }
    WARN("rule " << rule << ": grid teapot moved by 10..1e12 (" << cases
                 << " placements): " << origin.tree.leaves.size() << " leaves, "
                 << origin.mesh.triangleCount() << " triangles, every tree the origin's");
  }
}

TEST_CASE("local frame: the real teapot at 1e12 does not run away", "[scale]") {
  // 10¹² + x rounds x to 2⁻¹³ in double: a slightly different model (3·10⁻⁵ of its size), so
  // rules C and D may move split points; the counts stay within 2% of the origin's (measured:
  // see the WARN). Before the local frame, fp32 collapsed it to a point (every triangle
  // dropped) and at 10⁸ rule B ran to depth 12 with 278,870 triangles.
  for (char rule : {'A', 'B', 'C', 'D', 'T'}) {
    const Tessellation origin = onMirror(teapot(), rule);
    for (const glm::dvec3& offset : {glm::dvec3(1e12, 0, 0), glm::dvec3(1e12)}) {
      const Tessellation far = onMirror(placed(teapot(), 1.0, offset), rule);
      const double leafRatio = double(far.tree.leaves.size()) / double(origin.tree.leaves.size());
      const double triangleRatio =
          double(far.mesh.triangleCount()) / double(origin.mesh.triangleCount());
      WARN("rule " << rule << ", teapot moved by (" << offset.x << ", " << offset.y << ", "
                   << offset.z << "): " << far.tree.leaves.size() << " leaves, "
                   << far.mesh.triangleCount() << " triangles, depth " << far.tree.depth
                   << " (origin " << origin.tree.leaves.size() << ", "
                   << origin.mesh.triangleCount() << ", " << origin.tree.depth << ")");
      CHECK(std::abs(leafRatio - 1.0) <= 0.02);
      CHECK(std::abs(triangleRatio - 1.0) <= 0.02);
      CHECK(far.tree.depth <= origin.tree.depth + 1);
    }
  }
}

TEST_CASE("local frame: a trimmed model scaled and moved meshes face for face alike",
          "[scale][trim]") {
  // A bump with a round hole and a square outer loop (trimmed_models.h): the trimmed mesher's
  // trees work in the model's frame too (face_tessellation.h).
  const auto model = [](double scale, glm::dvec3 offset) {
    TrimmedModel m;
    test::SharedPoints shared(m);
    BezierPatch p = test::bumpPatch(1, 0.3, 0.4);
    for (glm::dvec3& c : p.cp) c = c * scale + offset;
    const auto at = [&](glm::dvec2 uv) { return patchPoint(p, uv.x, uv.y); };
    m.faces.push_back(
        test::faceOf(p,
                     {test::sampledLoop(test::squareBoundary(), 24, at, shared),
                      test::sampledLoop(test::circle({0.5, 0.5}, 0.2, false), 48, at, shared)},
                     false, 0));
    return m;
  };
  Backend mirror = makeMirrorBackend();
  TrimmedMeshOptions options;
  options.tolerance = 1e-3;
  const TrimmedMesh origin = meshTrimmedModel(model(1.0, glm::dvec3(0.0)), options, mirror);
  REQUIRE(origin.mesh.triangleCount() > 0);
  const struct {
    double scale;
    glm::dvec3 offset;
  } placements[] = {{0x1p-20, glm::dvec3(0.0)}, {0x1p20, glm::dvec3(0.0)},
                    {1e-3, glm::dvec3(0.0)},    {1e3, glm::dvec3(0.0)},
                    {1.0, glm::dvec3(1e6)},     {1e-3, glm::dvec3(-1e3, 10, 1e4)}};
  for (const auto& [scale, offset] : placements) {
    options.tolerance = 1e-3 * scale;
    const TrimmedMesh t = meshTrimmedModel(model(scale, offset), options, mirror);
    // The mesh is fp32 (as the CAD path writes it): its corners are rounded at the model's
    // coordinates, by up to √3·fp32RoundingBound(largest) each (result_warnings.h).
    const double largest =
        std::max(std::abs(offset.x), std::max(std::abs(offset.y), std::abs(offset.z))) + scale;
    const double rounding = std::sqrt(3.0) * fp32RoundingBound(largest);
    INFO("scaled by " << scale << ", moved by (" << offset.x << ", " << offset.y << ", " << offset.z
                      << "): deviation " << t.faces[0].maxGeometricDeviation
                      << ", fp32 rounding of a vertex up to " << rounding);
    CHECK(t.faces[0].quadtreeTriangles == origin.faces[0].quadtreeTriangles);
    CHECK(t.faces[0].keptTriangles == origin.faces[0].keptTriangles);
    CHECK(t.mesh.triangleCount() == origin.mesh.triangleCount());
    CHECK(t.faces[0].maxGeometricDeviation <= options.tolerance + rounding);
  }
}

TEST_CASE("local frame: Vulkan gives the mirror's tree and mesh far from the origin",
          "[scale][gpu]") {
  // Off lavapipe the device's own tree of the unmoved model stands in for the mirror's: the
  // local frame must hand the shaders the same numbers wherever the model lies.
  Backend vulkan = makeVulkanBackend(test::gpuContext());
  const bool exact = test::exactMirrorArithmetic();
  const std::vector<std::pair<std::vector<BezierPatch>, std::vector<BezierPatch>>> cases = {
      {teapot(), placed(teapot(), 1e-25)},
      {gridTeapot(), placed(gridTeapot(), 1.0, glm::dvec3(1e12))}};
  for (char rule : {'D', 'T'})
    for (const auto& [unmoved, patches] : cases) {
      const QuadtreeOptions options = optionsFor(rule, patches);
      Backend mirror = makeMirrorBackend();
      const Tessellation a = exact ? tessellate(patches, options, mirror)
                                   : tessellate(unmoved, optionsFor(rule, unmoved), vulkan);
      const Tessellation b = tessellate(patches, options, vulkan);
      WARN("rule " << rule << " on " << test::gpuContext().info().name << ": "
                   << b.tree.leaves.size() << " leaves, " << b.mesh.triangleCount()
                   << " triangles (" << (exact ? "mirror " : "Vulkan, unmoved model ")
                   << a.tree.leaves.size() << ", " << a.mesh.triangleCount() << ")");
      CHECK(differingLeaves(a.tree, b.tree) == 0);
      CHECK(test::vectorDifference(a.mesh.indices, b.mesh.indices) == "");
      if (exact) {
        CHECK(a.mesh.positions == b.mesh.positions);
        CHECK(a.mesh.normals == b.mesh.normals);
      }
    }
  test::requireValidationClean();
}

TEST_CASE("local frame: a corner weight of 1e-20 gives a finite mesh, and rule T names the patch",
          "[scale][warnings]") {
  // Issue 18: teapot patch 12 with corner weight 10⁻²⁰ stopped with "TriangleMesh: normals[…]
  // is not finite" (fp32 overflowed). In the frame every sample is finite; the surface crowds
  // into u, v ≲ 10⁻²⁰ at that corner, below the tree's minimum node size, so rule T cannot
  // prove the patch and says which it is.
  std::vector<BezierPatch> patches = teapot();
  for (BezierPatch& p : patches) p.weights.assign(p.cp.size(), 1.0);
  patches[12].weights[0] = 1e-20;
  Backend mirror = makeMirrorBackend();
  for (char rule : {'B', 'T'}) {
    const QuadtreeOptions options = optionsFor(rule, patches);
    const Tessellation t = tessellate(patches, options, mirror);
    INFO("rule " << rule);
    CHECK_NOTHROW(t.mesh.validate());
    CHECK(t.mesh.triangleCount() >= onMirror(teapot(), rule).mesh.triangleCount());
    const std::vector<ResultWarning> w =
        findResultWarnings(t, patches, nullptr, rule == 'T' ? options.tolerance : 0.0);
    if (rule == 'T') {
      REQUIRE(w.size() == 1);
      CHECK(w[0].code == "unproven-patch");
      CHECK(w[0].message.find("patch 12 is not proven within the tolerance") == 0);
    } else {
      CHECK(w.empty());
    }
  }
}

TEST_CASE("local frame: a sample that is not finite is refused naming its patch and (u, v)",
          "[scale]") {
  ParamMesh param;
  param.vertices = {{0, 0.0f, 0.0f}, {3, 0.25f, 0.5f}};
  std::vector<gpu::VertexSample> samples(2);
  samples[0].normal = samples[1].normal = gpu::vec4(0, 0, 1, 0);
  samples[1].normal.y = INFINITY;
  try {
    assembleTessellation(4, QuadtreeResult{}, param, samples);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) ==
          "patch 3: the fp32 evaluation at (u, v) = (0.25, 0.5) gives a normal that is not finite "
          "(a rational patch whose weights differ by more than fp32 can hold?)");
  }
}
