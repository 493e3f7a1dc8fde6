// The split rules on shapes whose answer is known: rule A's exact grid, a plane (one leaf),
// and a single sharp off-centre bump, where C and D must split at the bump and D's split
// point must lie within 1e-3 of the true maximum of κ (found here in double precision).
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/bicubic.h"
#include "geometry/curvature.h"
#include "eval/evaluator.h"
#include "gpu_test_context.h"
#include "quadtree/quadtree.h"
#include "geometry/surface_normal.h"

using namespace tessera;

namespace {

// z_ij = 0.3·a_i·b_j over a uniform grid: a bump whose κ maximum, near (0.35, 0.43), is 1.8×
// anything on the boundary (found by a search over such nets).
BezierPatch bumpPatch() {
  const double a[4] = {1, 4, 1.5, 0.5}, b[4] = {1, 3, 2, 1};
  BezierPatch p;
  p.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.at(i, j) = glm::dvec3(i / 3.0, j / 3.0, 0.3 * a[i] * b[j]);
  return p;
}

BezierPatch planePatch() {
  BezierPatch p;
  p.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {  // a tilted, sheared plane, unevenly spaced along u
      const double us[4] = {0.0, 0.2, 0.7, 1.0};
      p.at(i, j) = glm::dvec3(us[i] + 0.2 * j / 3.0, j / 3.0, 0.5 * us[i] - 0.25 * (j / 3.0));
    }
  return p;
}

// The maximum of κ over the patch by successively finer grid searches in double precision.
glm::dvec2 trueKappaMaximum(const BezierPatch& patch) {
  double L = controlNetDiagonal(patch);
  auto kappa = [&](double u, double v) {
    return surfaceCurvature(bicubicDerivatives(patch, u, v), L).kappa;
  };
  glm::dvec2 best(0.5), lo(0.0), hi(1.0);
  for (int stage = 0; stage < 6; ++stage) {
    double bestK = -1;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        double u = lo.x + (hi.x - lo.x) * i / 40.0, v = lo.y + (hi.y - lo.y) * j / 40.0;
        double k = kappa(u, v);
        if (k > bestK) bestK = k, best = glm::dvec2(u, v);
      }
    glm::dvec2 half = (hi - lo) / 10.0;
    lo = glm::max(best - half, glm::dvec2(0.0));
    hi = glm::min(best + half, glm::dvec2(1.0));
  }
  return best;
}

gpu::NodeDecision classifyRoot(NodeClassifier& classifier, const BezierPatch& patch,
                               SplitRule rule) {
  std::vector<gpu::BicubicPatch> patches = {toGpuPatch(patch)};
  std::vector<gpu::QuadNode> root = {{gpu::vec4(0, 0, 1, 1), 0, 0, 0, 0}};
  QuadtreeOptions options;
  options.rule = rule;
  std::vector<gpu::NodeDecision> decisions;
  LevelStats stats;
  classifier.beginTree(patches);
  classifier.classify(patches, root, options, decisions, stats);
  return decisions.at(0);
}

}  // namespace

TEST_CASE("rule A with N×M cells gives exactly N·M quads per patch", "[quadtree]") {
  std::vector<gpu::BicubicPatch> patches = {toGpuPatch(bumpPatch()), toGpuPatch(planePatch())};
  auto classifier = makeMirrorClassifier();
  for (auto [n, m] : {std::pair{1, 1}, {4, 4}, {7, 3}, {16, 16}}) {
    QuadtreeOptions options;
    options.rule = SplitRule::UniformGrid;
    options.gridU = n;
    options.gridV = m;
    QuadtreeResult r = buildQuadtree(patches, options, *classifier);
    REQUIRE(r.leaves.size() == size_t(2 * n * m));
    double area = 0;
    for (const QuadLeaf& leaf : r.leaves) {
      REQUIRE(leaf.cause == gpu::kCauseUniform);
      area += double(leaf.rect.z - leaf.rect.x) * double(leaf.rect.w - leaf.rect.y);
    }
    REQUIRE(area == Approx(2.0).epsilon(1e-6));  // the cells tile both parameter squares
  }
}

TEST_CASE("a plane patch is one leaf at any threshold and rule", "[quadtree]") {
  std::vector<gpu::BicubicPatch> patches = {toGpuPatch(planePatch())};
  for (auto* make : {&makeMirrorClassifier, &makeReferenceClassifier}) {
    auto classifier = make();
    for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax})
      for (float threshold : {0.3f, 0.1f, 0.01f, 1e-4f}) {
        QuadtreeOptions options;
        options.rule = rule;
        options.linearity = options.flatness = threshold;
        QuadtreeResult r = buildQuadtree(patches, options, *classifier);
        INFO(classifier->name() << " rule " << splitRuleLetter(rule) << " threshold " << threshold);
        REQUIRE(r.leaves.size() == 1);
        REQUIRE(r.leaves[0].cause == gpu::kCauseFlat);
      }
  }
}

TEST_CASE("rules C and D split at a sharp bump; D within 1e-3 of the true maximum",
          "[quadtree]") {
  BezierPatch bump = bumpPatch();
  glm::dvec2 truth = trueKappaMaximum(bump);
  REQUIRE(glm::distance(truth, glm::dvec2(0.5)) > 0.1);  // off-centre: B cannot find it
  auto mirror = makeMirrorClassifier();
  auto reference = makeReferenceClassifier();

  gpu::NodeDecision b = classifyRoot(*mirror, bump, SplitRule::Midpoint);
  gpu::NodeDecision c = classifyRoot(*mirror, bump, SplitRule::SampledMax);
  gpu::NodeDecision d = classifyRoot(*mirror, bump, SplitRule::TrueMax);
  gpu::NodeDecision d64 = classifyRoot(*reference, bump, SplitRule::TrueMax);
  double errB = glm::distance(glm::dvec2(b.split.x, b.split.y), truth);
  double errC = glm::distance(glm::dvec2(c.split.x, c.split.y), truth);
  double errD = glm::distance(glm::dvec2(d.split.x, d.split.y), truth);
  double errD64 = glm::distance(glm::dvec2(d64.split.x, d64.split.y), truth);
  WARN("true κ maximum (" << truth.x << ", " << truth.y << "); split distance B " << errB
                          << ", C " << errC << ", D fp32 " << errD << ", D double " << errD64);
  REQUIRE(errC < 1.0 / 12.0 * std::sqrt(2.0));  // C lands on the sample next to the bump
  REQUIRE(errC < errB);
  REQUIRE(errD < 1e-3);
  REQUIRE(errD64 < 1e-3);
  REQUIRE(d.split.z >= c.split.z);  // D's κ at its point is at least C's
}

TEST_CASE("rules B to D split no node thinner than fp32 resolves on the model", "[quadtree]") {
  // A cone with its apex at u = 0 (a collapsed side) at (1, 1, 1), a quarter turn in v: a node
  // [0, δ]×[0, 1] there fails flatness at any δ (its corners' normals are a quarter turn
  // apart), and is about δ/2 wide. Narrower than kResolvedWidthUlps units in the last place of
  // its coordinates (about 7.6e-6 at 1) it is a MinSize leaf; wider, it splits. Scaled by 2^-20
  // or 2^20 the answer is the same: the limit is relative to the coordinates, not a length.
  // (At the origin fp32 resolves far finer, and the same node splits. The parameter limit
  // minSize is off, so only the width decides.)
  const auto cone = [](double scale, double apex = 1.0) {
    const glm::dvec2 quarter[4] = {{1, 0}, {1, 0.55}, {0.55, 1}, {0, 1}};
    BezierPatch p;
    p.cp.resize(16);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        p.at(i, j) = scale * (glm::dvec3(apex) + glm::dvec3(i / 3.0 * quarter[j], 0.5 * i));
    return p;
  };
  const auto classify = [](NodeClassifier& classifier, const BezierPatch& patch, SplitRule rule,
                           float delta) {
    std::vector<gpu::BicubicPatch> patches = {toGpuPatch(patch)};
    std::vector<gpu::QuadNode> node = {{gpu::vec4(0, 0, delta, 1), 0, 1, 0, 0}};
    QuadtreeOptions options;
    options.rule = rule;
    options.minSize = 0;
    std::vector<gpu::NodeDecision> decisions;
    LevelStats stats;
    classifier.beginTree(patches);
    classifier.classify(patches, node, options, decisions, stats);
    return decisions.at(0).cause;
  };
  auto mirror = makeMirrorClassifier();
  auto reference = makeReferenceClassifier();
  for (double scale : {1.0, 0x1p-20, 0x1p20})
    for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax})
      for (NodeClassifier* classifier : {mirror.get(), reference.get()}) {
        INFO(classifier->name() << " rule " << splitRuleLetter(rule) << " scale " << scale);
        REQUIRE(classify(*classifier, cone(scale), rule, 0x1p-20f) == gpu::kCauseMinSize);
        REQUIRE(classify(*classifier, cone(scale), rule, 0x1p-10f) == gpu::kCauseSplit);
        REQUIRE(classify(*classifier, cone(scale, 0.0), rule, 0x1p-20f) == gpu::kCauseSplit);
      }
}

TEST_CASE("the GPU's rule D finds the bump's maximum too", "[gpu][quadtree]") {
  vk::Context& context = test::gpuContext();
  BezierPatch bump = bumpPatch();
  glm::dvec2 truth = trueKappaMaximum(bump);
  auto gpu = makeVulkanClassifier(context);
  gpu::NodeDecision d = classifyRoot(*gpu, bump, SplitRule::TrueMax);
  REQUIRE(glm::distance(glm::dvec2(d.split.x, d.split.y), truth) < 1e-3);
  test::requireValidationClean();
}
