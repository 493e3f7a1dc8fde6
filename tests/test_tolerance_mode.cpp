// Rule T (tolerance, issue 15): every mesh within δ of its surface (the proven per-node bound
// of shaders/lib/tolerance_bound.h; docs/quadtree.md, "Rule T: tolerance"), anisotropic
// splits, and parity of the fp32 mirror with the GPU and with the double reference.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <tuple>

#include "common/stopwatch.h"
#include "division/count.h"
#include "general_samples.h"
#include "geometry/rational.h"
#include "geometry/surface_normal.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "mesh/deviation.h"
#include "mesh/tessellate.h"
#include "quadtree/node_split.h"
#include "quadtree/quadtree.h"
#include "quadtree_compare.h"
#include "sweep_share.h"

using namespace tessera;

namespace {

// The patch moved and scaled so that its control net's bounding box has diagonal 1.
BezierPatch normalised(BezierPatch p) {
  const double d = controlNetDiagonal(p);
  const glm::dvec3 origin = p.cp[0];
  for (auto& c : p.cp) c = (c - origin) / d;
  return p;
}

// 1,078 random patches, fixed seeds: every degree pair 1..7 × 1..7, polynomial and rational,
// the rational ones of degree ≥ 2 both ways with one inner weight zero every other time.
std::vector<BezierPatch> randomPatchZoo() {
  std::vector<BezierPatch> zoo;
  uint32_t seed = 1500;
  for (int round = 0; round < 11; ++round)
    for (int n = 1; n <= 7; ++n)
      for (int m = 1; m <= 7; ++m) {
        const bool rational = (round + n + m) % 2 == 1;
        const bool innerZero = rational && n >= 2 && m >= 2 && round % 2 == 0;
        for (BezierPatch& p : test::randomGeneralPatches(2, n, m, rational, innerZero, ++seed))
          zoo.push_back(normalised(p));
      }
  return zoo;
}

double setDiagonal(const std::vector<BezierPatch>& patches) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : patches)
    for (const auto& c : p.cp) lo = glm::min(lo, c), hi = glm::max(hi, c);
  return glm::length(hi - lo);
}

std::vector<BezierPatch> teaModel(const char* name) {
  return readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + name + ".bpt");
}

}  // namespace

TEST_CASE("rule T: over 1000 random patches of degree 1..7 stay within δ", "[tolerance]") {
  REQUIRE(randomPatchZoo().size() >= 1000);
  const std::vector<BezierPatch> zoo = test::sweptSubset(randomPatchZoo());  // all in Release
  Backend backend = makeMirrorBackend();
  // Mostly classification (rational nets: the split bounds, O(points²) a node); 1e-3 makes
  // 3.1M triangles (minutes), 3e-3 1.2M (~45 s).
  for (double delta : {3e-2, 1e-2}) {
    const Stopwatch clock;
    Tessellation t = tessellate(zoo, toleranceOptions(delta), backend);
    const double tessellateMs = clock.elapsedMs();
    // 3 subdivisions: 10 samples per triangle, corners and edge midpoints included.
    DeviationReport r = measureDeviation(t, zoo, 3, DeviationMetric::Parametric);
    const double measureMs = clock.elapsedMs() - tessellateMs;
    size_t worst = 0;
    for (size_t p = 0; p < zoo.size(); ++p)
      if (r.perPatchMax[p] > r.perPatchMax[worst]) worst = p;
    size_t maxDepthLeaves = 0, diagonalLeaves = 0;
    for (const auto& leaf : t.tree.leaves) {
      maxDepthLeaves += leaf.cause != gpu::kCauseWithinTolerance;
      diagonalLeaves += leaf.diagonal != gpu::kToleranceAnyDiagonal;
    }
    WARN("δ = " << delta << " of each patch's size: " << zoo.size() << " patches, "
                << t.stats.triangles << " triangles (" << diagonalLeaves << " of "
                << t.tree.leaves.size() << " leaves proven for one diagonal), depth "
                << t.stats.depth
                << ", largest measured/δ = " << r.maxDeviation / delta << " (patch " << worst
                << ", degree " << zoo[worst].degreeU << "×" << zoo[worst].degreeV
                << (zoo[worst].weights.empty() ? "" : " rational") << "); tessellated in "
                << tessellateMs << " ms, measured in " << measureMs << " ms");
    CHECK(maxDepthLeaves == 0);
    CHECK(diagonalLeaves > 0);  // the one-diagonal bound is exercised, and measured below
    CHECK(t.stats.diagonalFans == 0);
    REQUIRE(r.maxDeviation <= delta);
  }
}

TEST_CASE("rule T: the tea set within δ in both metrics", "[tolerance]") {
  Backend backend = makeMirrorBackend();
  for (const char* name : {"teapot", "teacup", "teaspoon"}) {
    const auto patches = teaModel(name);
    for (double delta : {1e-2, 1e-3}) {
      Tessellation t = tessellate(patches, toleranceOptions(delta), backend);
      DeviationReport par = measureDeviation(t, patches, 4, DeviationMetric::Parametric);
      DeviationReport geo = measureDeviation(t, patches, 2, DeviationMetric::Geometric);
      // Rule A's per-patch Filip grids at the same δ (2 triangles a cell), for comparison.
      long long filip = 0;
      for (const auto& p : patches) {
        DivisionOptions options;
        options.tolerance = delta;
        options.maxPerDirection = 1 << 20;
        filip += 2 * patchDivisions(toRationalPatch(p), options).divisionNumber();
      }
      WARN(name << " at δ = " << delta << ": " << t.stats.triangles << " triangles (Filip grids "
                << filip << ", ratio " << double(t.stats.triangles) / double(filip)
                << "), depth " << t.stats.depth << ", parametric " << par.maxDeviation
                << ", geometric " << geo.maxDeviation);
      for (const auto& leaf : t.tree.leaves) REQUIRE(leaf.cause == gpu::kCauseWithinTolerance);
      REQUIRE(t.stats.diagonalFans == 0);  // every leaf's triangles keep to its bound's diagonal
      // Paths name leaves uniquely, grid splits' variable-width codes included.
      std::set<std::tuple<uint32_t, uint32_t, uint64_t>> paths;
      for (const auto& leaf : t.tree.leaves) paths.insert({leaf.patchIndex, leaf.level, leaf.path});
      REQUIRE(paths.size() == t.tree.leaves.size());
      REQUIRE(par.maxDeviation <= delta);
      REQUIRE(geo.maxDeviation <= delta);
    }
  }
}

// The quadratic S(s, t) = (s, t, s² + σ·st + t²) as a degree-n × n Bézier patch (the
// coefficients of s, s² and st in the Bernstein basis: i/n, i(i−1)/(n(n−1)), ij/n²).
BezierPatch quadraticBowl(int n, double sigma) {
  BezierPatch p;
  p.degreeU = p.degreeV = n;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double s1 = double(i) / n, t1 = double(j) / n;
      const double s2 = double(i * (i - 1)) / (n * (n - 1)), t2 = double(j * (j - 1)) / (n * (n - 1));
      p.cp.push_back({s1, t1, s2 + sigma * s1 * t1 + t2});
    }
  return p;
}

TEST_CASE("rule T: a leaf proven for one diagonal keeps its triangles to it", "[tolerance]") {
  // S_ss = S_tt = 2, S_st = σ = ±1 (along z): across the unit square the diagonal along which
  // st grows with s + t bends by (2 + 2σ + 2)/8 = 0.75 at its middle, the other by 0.25. The
  // bound for any triangles, W/8 = 0.75 (also (M_ss + 2·M_st + M_tt)/8), fails δ = 0.6; the
  // flatter diagonal's, W₂/8 = max(‖S_ss + S_tt‖, …)/8 = 0.5, passes (docs/quadtree.md, "One
  // diagonal"). So the root is a leaf only for that diagonal, and its two triangles are within
  // δ only if the triangulator keeps to it (the other pair deviates by 0.75 > δ).
  Backend backend = makeMirrorBackend();
  for (int n : {2, 3})  // the general path and the bicubic fast path
    for (double sigma : {1.0, -1.0}) {
      const std::vector<BezierPatch> patches = {quadraticBowl(n, sigma)};
      const double delta = 0.6;
      Tessellation t = tessellate(patches, toleranceOptions(delta), backend);
      REQUIRE(t.tree.leaves.size() == 1);
      const QuadLeaf& leaf = t.tree.leaves[0];
      CHECK(leaf.cause == gpu::kCauseWithinTolerance);
      CHECK(leaf.diagonal ==
            (sigma > 0 ? gpu::kToleranceAntiDiagonal : gpu::kToleranceMainDiagonal));
      CHECK(leaf.flatness * t.tree.boundScale == Approx(0.5).epsilon(1e-3));
      REQUIRE(t.stats.triangles == 2);
      const DeviationReport r = measureDeviation(t, patches, 4, DeviationMetric::Parametric);
      WARN("degree " << n << ", σ = " << sigma << ": measured " << r.maxDeviation
                     << " (exactly 1/3 at the triangles' centroids), bound "
                     << leaf.flatness * t.tree.boundScale << ", δ " << delta);
      CHECK(r.maxDeviation > 0.3);
      CHECK(r.maxDeviation <= 1.0 / 3.0 + 1e-6);
      REQUIRE(r.maxDeviation <= delta);
    }
}

TEST_CASE("rule T: a cylinder never splits along its axis, the teapot's poles stay shallow",
          "[tolerance]") {
  // A bicubic extrusion (straight along v) and the exact rational quarter cylinder (2×1).
  BezierPatch extrusion;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      extrusion.cp.push_back({std::cos(0.5 * i), std::sin(0.7 * i) + 0.1 * i * i, 2.0 * j / 3.0});
  const BezierPatch cylinder = test::rationalQuarterCylinder(1.0, 3.0);
  Backend backend = makeMirrorBackend();
  for (const BezierPatch& patch : {extrusion, cylinder}) {
    const double delta = 1e-4 * controlNetDiagonal(patch);
    Tessellation t = tessellate({patch}, toleranceOptions(delta), backend);
    size_t vSplit = 0;
    for (const auto& leaf : t.tree.leaves) vSplit += leaf.rect.y != 0.0f || leaf.rect.w != 1.0f;
    WARN((patch.weights.empty() ? "bicubic extrusion" : "rational quarter cylinder")
         << " at δ = 1e-4 of its size: " << t.tree.leaves.size() << " leaves, " << vSplit
         << " split along the axis");
    REQUIRE(t.tree.leaves.size() > 8);
    REQUIRE(vSplit == 0);
  }
  const auto teapot = teaModel("teapot");
  const double delta = 1e-3 * setDiagonal(teapot);
  Tessellation t = tessellate(teapot, toleranceOptions(delta), backend);
  size_t oneWay = 0;
  for (const auto& leaf : t.tree.leaves)
    oneWay += (leaf.rect.z - leaf.rect.x) != (leaf.rect.w - leaf.rect.y);
  WARN("teapot at δ = 1e-3 of its size (" << delta << "): depth " << t.stats.depth << ", "
                                           << t.tree.leaves.size() << " leaves, " << oneWay
                                           << " not square in (u, v)");
  REQUIRE(t.stats.depth <= 14);
  REQUIRE(oneWay > 0);
  // kToleranceMaxDepth leaves room: at δ = 1e-4 of the size every tea-set leaf is within δ.
  for (const char* name : {"teapot", "teacup", "teaspoon"}) {
    const auto patches = teaModel(name);
    Tessellation fine = tessellate(patches, toleranceOptions(1e-4 * setDiagonal(patches)), backend);
    size_t within = 0;
    for (const auto& leaf : fine.tree.leaves) within += leaf.cause == gpu::kCauseWithinTolerance;
    WARN(name << " at δ = 1e-4 of its size: depth " << fine.stats.depth << " (limit "
              << kToleranceMaxDepth << "), " << fine.stats.triangles << " triangles");
    REQUIRE(within == fine.tree.leaves.size());
  }
}

TEST_CASE("rule T: the double reference agrees with the fp32 mirror outside a band around δ",
          "[tolerance][precision]") {
  // Classify level by level along the mirror's tree with both backends; where the decisions
  // part, the exact bound must lie within kBand of δ, or δ between the exact and the fp32
  // bound (the fp32 guard), or the u
  // share within kBand of a split threshold (1/3, 2/3). The fp32 bound must never be below
  // the exact one.
  constexpr double kBand = 1e-2;
  std::vector<BezierPatch> patches = teaModel("teapot");
  std::vector<BezierPatch> zoo = randomPatchZoo();
  zoo.resize(60);  // 150 took 100 s under ASan in CI; 60 still reach 10^5 nodes at 1e-3
  zoo = test::sweptSubset(zoo);  // all 60 in Release
  auto mirror = makeMirrorClassifier();
  auto reference = makeReferenceClassifier();
  for (const auto* input : {&patches, &zoo}) {
    for (double relative : {1e-2, 1e-3}) {
      const PatchSet set = toPatchSet(*input);
      QuadtreeOptions options = toleranceOptions(relative * setDiagonal(*input));
      if (input == &zoo) options.tolerance = relative;  // the zoo's patches have size 1
      mirror->beginTree(set);
      reference->beginTree(set);
      std::vector<gpu::QuadNode> nodes;
      for (uint32_t p = 0; p < set.size(); ++p) nodes.push_back({{0, 0, 1, 1}, p, 0, 0, 0});
      size_t total = 0, parted = 0, unexplained = 0, below = 0, otherCounts = 0;
      double worstBelow = 0;
      std::vector<gpu::NodeDecision> a, b;
      while (!nodes.empty()) {
        LevelStats stats;
        mirror->classify(set, nodes, options, a, stats);
        reference->classify(set, nodes, options, b, stats);
        std::vector<gpu::QuadNode> next;
        for (size_t i = 0; i < nodes.size(); ++i) {
          ++total;
          const double exact = b[i].flatness, fp32 = a[i].flatness;
          if (fp32 < exact) {
            ++below;
            worstBelow = std::max(worstBelow, (exact - fp32) / exact);
          }
          const bool bothSplit = splitCounts(a[i]).splits() && splitCounts(b[i]).splits();
          if (bothSplit && (a[i].cause != b[i].cause || a[i].pad != b[i].pad)) {
            // Both split, into other counts: a grid estimate (M_ss/k_u² + …)/8 at δ, which
            // the decision does not carry; counted, and bounded below.
            ++otherCounts;
          } else if (a[i].cause != b[i].cause) {
            ++parted;
            const double share = b[i].linearity;
            // Within the band, or δ between the exact bound and the guarded fp32 one (a
            // rational net's guard term is up to ~10% of δ for degree 7 at δ = 1e-3 of the
            // size; a polynomial net's, scaled by h², far less).
            const double lo = std::min(exact, fp32), hi = std::max(exact, fp32);
            const bool nearDelta = std::abs(exact / options.tolerance - 1.0) <= kBand ||
                                   (lo * (1 - kBand) <= options.tolerance &&
                                    options.tolerance <= hi * (1 + kBand));
            const bool nearShare =
                std::abs(share - 1.0 / 3.0) <= kBand || std::abs(share - 2.0 / 3.0) <= kBand;
            if (!nearDelta && !nearShare) {
              ++unexplained;
              UNSCOPED_INFO("node at level " << nodes[i].level << ": fp32 cause " << a[i].cause
                                             << " bound " << fp32 << ", double cause "
                                             << b[i].cause << " bound " << exact);
            }
          }
          const SplitCounts counts = splitCounts(a[i]);
          if (counts.splits()) appendChildren(nodes[i], a[i], counts, next);
        }
        nodes.swap(next);
      }
      WARN((input == &zoo ? "60 random patches" : "teapot")
           << " at δ = " << relative << " of the size: " << total << " nodes, " << parted
           << " decided differently (" << unexplained << " outside the band " << kBand
           << "), fp32 bound below the exact one at " << below << " (worst by "
           << worstBelow << " relative); " << otherCounts << " split into other counts");
      CHECK(unexplained == 0);
      CHECK(below == 0);
      CHECK(otherCounts * 100 <= total);  // the guard's band around δ: rare
    }
  }
}

TEST_CASE("rule T: GPU trees equal the fp32 mirror's", "[gpu][tolerance][parity]") {
  vk::Context& context = test::gpuContext();
  auto gpu = makeVulkanClassifier(context);
  auto cpu = makeMirrorClassifier();
  std::vector<std::pair<std::string, std::vector<BezierPatch>>> inputs;
  for (const char* name : {"teapot", "teacup", "teaspoon"}) inputs.push_back({name, teaModel(name)});
  std::vector<BezierPatch> zoo = randomPatchZoo();
  std::vector<BezierPatch> some;
  for (size_t k = 0; k < zoo.size(); k += 12) some.push_back(zoo[k]);
  inputs.push_back({"random general and rational patches", some});
  for (const auto& [name, patches] : inputs) {
    const PatchSet set = toPatchSet(patches);
    for (double relative : {1e-2, 1e-3}) {
      QuadtreeOptions options = toleranceOptions(relative * setDiagonal(patches));
      QuadtreeResult a = buildQuadtree(set, options, *gpu);
      QuadtreeResult b = buildQuadtree(set, options, *cpu);
      const bool identical = test::identicalTrees(a, b);
      WARN(name << " at δ = " << relative << " of the size on " << context.info().name << ": GPU "
                << a.leaves.size() << " leaves depth " << a.depth << ", mirror "
                << b.leaves.size() << (identical ? " (identical)" : " (DIFFERENT)"));
      if (context.info().isLavapipe()) {
        REQUIRE(identical);
      } else {
        REQUIRE(double(a.leaves.size()) == Approx(double(b.leaves.size())).epsilon(0.02));
      }
    }
  }
  test::requireValidationClean();
}

TEST_CASE("rule T: each degree pair with a GPU shader of its own gives the mirror's decisions",
          "[gpu][tolerance][parity]") {
  // Polynomial patches of degree ≤ 3 × 3 and rational ones of degree 2 × 1, 1 × 2, 2 × 2 and
  // 3 × 3 go to the variant built for their degree pair, the others to the generic shader, each
  // shader's nodes one range of the node buffer (classifier_vulkan.cpp): a set with every
  // variant, a rational 3 × 2 and a polynomial 5 × 3, and sets of fewer shaders (one alone:
  // the nodes as they are), each tree equal to the mirror's.
  vk::Context& context = test::gpuContext();
  auto gpu = makeVulkanClassifier(context);
  auto cpu = makeMirrorClassifier();
  std::vector<BezierPatch> mixed, planes, bicubics;
  uint32_t seed = 7100;
  for (int n = 1; n <= 3; ++n)
    for (int m = 1; m <= 3; ++m)
      for (BezierPatch& p : test::randomGeneralPatches(2, n, m, false, false, ++seed))
        mixed.push_back(normalised(p));
  for (auto [n, m, innerZero] :
       {std::tuple{2, 1, false}, {1, 2, false}, {2, 2, true}, {3, 3, true}, {3, 2, false}})
    for (BezierPatch& p : test::randomGeneralPatches(2, n, m, true, innerZero, ++seed))
      mixed.push_back(normalised(p));
  for (BezierPatch& p : test::randomGeneralPatches(2, 5, 3, false, false, ++seed))
    mixed.push_back(normalised(p));
  for (BezierPatch& p : test::randomGeneralPatches(3, 1, 1, false, false, ++seed))
    planes.push_back(normalised(p));
  // Bicubic patches beside a rational one: the general set, polynomial 3 × 3 on its variant.
  for (BezierPatch& p : test::randomGeneralPatches(3, 3, 3, false, false, ++seed))
    bicubics.push_back(normalised(p));
  for (BezierPatch& p : test::randomGeneralPatches(1, 2, 1, true, false, ++seed))
    bicubics.push_back(normalised(p));
  for (const auto& [name, patches] : {std::pair<const char*, const std::vector<BezierPatch>&>{
                                          "every variant, rational, degree 5", mixed},
                                      {"degree 1 x 1 alone", planes},
                                      {"3 x 3 beside a rational 2 x 1", bicubics}}) {
    const PatchSet set = toPatchSet(patches);
    REQUIRE_FALSE(set.isBicubic());
    for (double relative : {3e-2, 3e-3}) {
      const QuadtreeOptions options = toleranceOptions(relative * setDiagonal(patches));
      const QuadtreeResult a = buildQuadtree(set, options, *gpu);
      const QuadtreeResult b = buildQuadtree(set, options, *cpu);
      const bool identical = test::identicalTrees(a, b);
      WARN(name << " at δ = " << relative << " of the size on " << context.info().name << ": GPU "
                << a.leaves.size() << " leaves, mirror " << b.leaves.size()
                << (identical ? " (identical)" : " (DIFFERENT)"));
      REQUIRE(b.leaves.size() > patches.size());  // the trees do split
      if (context.info().isLavapipe()) {
        REQUIRE(identical);
      } else {
        REQUIRE(double(a.leaves.size()) == Approx(double(b.leaves.size())).epsilon(0.02));
      }
    }
  }
  test::requireValidationClean();
}

namespace {

// Triangles of rule T on one tea-set model at δ with at most `cap` equal children a direction.
size_t teaTriangles(const std::vector<BezierPatch>& patches, double delta, uint32_t cap,
                    Backend& backend, double* measured = nullptr) {
  QuadtreeOptions options = toleranceOptions(delta);
  options.toleranceSplitCap = cap;
  Tessellation t = tessellate(patches, options, backend);
  if (measured)
    *measured = measureDeviation(t, patches, 2, DeviationMetric::Parametric).maxDeviation / delta;
  return t.stats.triangles;
}

}  // namespace

TEST_CASE("rule T: grid splits spend fewer triangles than midpoint splits", "[tolerance]") {
  Backend backend = makeMirrorBackend();
  for (double delta : {1e-2, 1e-3}) {
    size_t midpoint = 0, grid = 0;
    for (const char* name : {"teapot", "teacup", "teaspoon"}) {
      const auto patches = teaModel(name);
      midpoint += teaTriangles(patches, delta, 1, backend);
      grid += teaTriangles(patches, delta, kToleranceSplitCap, backend);
    }
    WARN("tea set at δ = " << delta << ": " << midpoint << " triangles with midpoint splits, "
                           << grid << " with grids of up to " << kToleranceSplitCap << " × "
                           << kToleranceSplitCap << " (ratio " << double(grid) / double(midpoint)
                           << ")");
    REQUIRE(grid < midpoint);
  }
}

// The sweep that chose kToleranceSplitCap (docs/quadtree.md): run with
// `tessera_tests "[caps]"`; prints triangles and measured/δ per model, δ and cap.
TEST_CASE("rule T: the split cap sweep", "[.][tolerance][caps]") {
  Backend backend = makeMirrorBackend();
  for (uint32_t cap : {1u, 2u, 3u, 4u, 6u, 8u, 16u}) {
    size_t total = 0;
    double worst = 0;
    std::string row;
    for (double delta : {1e-2, 1e-3})
      for (const char* name : {"teapot", "teacup", "teaspoon"}) {
        double measured = 0;
        const size_t n = teaTriangles(teaModel(name), delta, cap, backend, &measured);
        total += n;
        worst = std::max(worst, measured);
        row += " " + std::to_string(n);
      }
    WARN("cap " << cap << ": teapot/teacup/teaspoon at 0.01 then 0.001:" << row << "; total "
                << total << ", largest measured/δ " << worst);
    CHECK(worst <= 1.0);
  }
}
