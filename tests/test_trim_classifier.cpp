// Quad-tree nodes against trim loops (host/trim/trim_classifier.h): the fp32 mirror against
// the double reference (never a crossing missed, inside/outside never swapped, differences only
// within the margin band), Vulkan against the mirror bit for bit, and the trimming pass of the
// quad-tree frontier (host/trim/trim_frontier.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "common/stopwatch.h"
#include "gpu_test_context.h"
#include "patch_samples.h"
#include "trim/trim_classifier.h"
#include "trim/trim_cut.h"
#include "trim/trim_frontier.h"
#include "trim_samples.h"

using namespace tessera;
using namespace tessera::test;

namespace {

const char* className(uint32_t c) {
  return c == gpu::kTrimInside ? "inside" : c == gpu::kTrimOutside ? "outside" : "crossing";
}

}  // namespace

TEST_CASE("Trim classification: the fp32 mirror never misses a crossing and differs from the "
          "double reference only within the margin band",
          "[trim]") {
  const TrimSet set = trimSampleSet();
  const std::vector<gpu::TrimQuery> queries = trimSampleQueries(set, 4000, 1701);
  const auto reference = makeReferenceTrimClassifier()->classify(set, queries);
  const auto mirror = makeMirrorTrimClassifier()->classify(set, queries);
  REQUIRE(mirror.size() == queries.size());
  std::array<size_t, 3> counts{};
  size_t band = 0, missed = 0, swapped = 0, outsideBand = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    ++counts[reference[i]];
    if (mirror[i] == reference[i]) continue;
    if (reference[i] == gpu::kTrimCrossing) {
      ++missed;
    } else if (mirror[i] != gpu::kTrimCrossing) {
      ++swapped;
    } else {
      ++band;
      // The mirror's crossing must be a segment within 1.25 m of the rectangle in double
      // (m + the 10u·U of rounding the derivation allows, with m = 64u·U).
      const float margin = set.faces[set.pieces[queries[i].piece].face].margin;
      if (classifyTrimNodeReference(set, queries[i], 1.25 * double(margin)) != gpu::kTrimCrossing)
        ++outsideBand;
    }
    if (missed + swapped + outsideBand > 0 && missed + swapped + outsideBand <= 5)
      std::printf("  query %zu (piece %u, rect %.9g %.9g %.9g %.9g): reference %s, mirror %s\n", i,
                  queries[i].piece, queries[i].rect.x, queries[i].rect.y, queries[i].rect.z,
                  queries[i].rect.w, className(reference[i]), className(mirror[i]));
  }
  std::printf("trim mirror vs reference: %zu nodes (reference: %zu outside, %zu inside, %zu "
              "crossing); %zu differ: %zu mirror crossings near a loop (%zu of them beyond 1.25 m "
              "in double), %zu crossings missed, %zu inside/outside swapped\n",
              queries.size(), counts[0], counts[1], counts[2], band + missed + swapped, band,
              outsideBand, missed, swapped);
  CHECK(missed == 0);
  CHECK(swapped == 0);
  CHECK(outsideBand == 0);
  // The samples exercise all three answers.
  CHECK(counts[gpu::kTrimOutside] > 1000);
  CHECK(counts[gpu::kTrimInside] > 1000);
  CHECK(counts[gpu::kTrimCrossing] > 1000);
}

TEST_CASE("Trim classification: segments placed within two margins of a node's side, far from "
          "the origin, are never missed by the mirror",
          "[trim]") {
  const NearSideSamples samples = nearSideTrimSamples(20000, 404);
  const TrimSet& set = samples.set;
  const std::vector<gpu::TrimQuery>& queries = samples.queries;
  const auto reference = makeReferenceTrimClassifier()->classify(set, queries);
  const auto mirror = makeMirrorTrimClassifier()->classify(set, queries);
  size_t referenceCrossing = 0, band = 0, beyondBand = 0, missed = 0, swapped = 0;
  for (size_t q = 0; q < queries.size(); ++q) {
    referenceCrossing += reference[q] == gpu::kTrimCrossing;
    if (mirror[q] == reference[q]) continue;
    if (reference[q] == gpu::kTrimCrossing) ++missed;
    else if (mirror[q] != gpu::kTrimCrossing) ++swapped;
    else {
      ++band;
      const double margin = double(set.faces[q].margin);
      if (classifyTrimNodeReference(set, queries[q], 1.25 * margin) != gpu::kTrimCrossing)
        ++beyondBand;
    }
  }
  std::printf("trim near-side segments: %zu nodes, %zu crossing by the reference, %zu more by the "
              "mirror (the band; %zu of them beyond 1.25 m in double), %zu missed, %zu swapped\n",
              queries.size(), referenceCrossing, band, beyondBand, missed, swapped);
  CHECK(missed == 0);
  CHECK(swapped == 0);
  CHECK(beyondBand == 0);
  CHECK(band > 1000);  // the distances reach into the band on both sides of it
  CHECK(referenceCrossing > 1000);
}

TEST_CASE("Trim classification: touching counts as crossing, and a face without loops is inside",
          "[trim]") {
  const TrimSet set = trimSampleSet();
  // Face 3's square has its sides on u, v = 1/4 and 3/4 (piece 6 is [0,1]²).
  const std::vector<gpu::TrimQuery> queries = {
      {{0.75f, 0.75f, 1.0f, 1.0f}, 6, 0, 0, 0},     // touches the square's corner only
      {{0.25f, 0.25f, 0.75f, 0.75f}, 6, 0, 0, 0},   // its sides are the loop
      {{0.375f, 0.375f, 0.625f, 0.625f}, 6, 0, 0, 0},  // strictly inside
      {{0.8f, 0.8f, 0.9f, 0.9f}, 6, 0, 0, 0},       // strictly outside
      {{0.0f, 0.0f, 1.0f, 1.0f}, 8, 0, 0, 0},       // face 4: no loops
      {{0.0f, 0.0f, 1.0f, 1.0f}, 6, 0, 0, 0},       // contains the whole loop
  };
  const std::vector<uint32_t> expected = {gpu::kTrimCrossing, gpu::kTrimCrossing,
                                          gpu::kTrimInside,   gpu::kTrimOutside,
                                          gpu::kTrimInside,   gpu::kTrimCrossing};
  CHECK(makeReferenceTrimClassifier()->classify(set, queries) == expected);
  CHECK(makeMirrorTrimClassifier()->classify(set, queries) == expected);
}

TEST_CASE("Trim classification: bad input names the face, loop, point or query", "[trim]") {
  using Loops = std::vector<std::vector<std::vector<glm::dvec2>>>;
  CHECK_THROWS_WITH(packTrimSet(Loops{{{{0, 0}, {1, NAN}, {0, 1}}}}, {{0, {0, 0, 1, 1}}}),
                    Catch::Contains("face 0, loop 0, point 1"));
  CHECK_THROWS_WITH(packTrimSet(Loops{{}}, {{1, {0, 0, 1, 1}}}),
                    Catch::Contains("piece 0 names face 1"));
  CHECK_THROWS_WITH(packTrimSet(Loops{{}}, {{0, {0, 0, 0, 1}}}),
                    Catch::Contains("piece 0 of face 0"));
  const TrimSet set = trimSampleSet();
  CHECK_THROWS_WITH(makeMirrorTrimClassifier()->classify(set, {{{0, 0, 1, 1}, 99, 0, 0, 0}}),
                    Catch::Contains("query 0 names piece 99"));
}

TEST_CASE("Trim classification: Vulkan equals the fp32 mirror bit for bit", "[trim][gpu]") {
  auto vulkan = makeVulkanTrimClassifier(gpuContext());
  const TrimSet samples = trimSampleSet();
  REQUIRE(samples.faces[0].binCount > 1);  // the shader's binned reads are compared too
  const NearSideSamples nearSide = nearSideTrimSamples(20000, 405);
  const std::pair<const TrimSet*, std::vector<gpu::TrimQuery>> cases[] = {
      {&samples, trimSampleQueries(samples, 4000, 1702)}, {&nearSide.set, nearSide.queries}};
  for (const auto& [set, queries] : cases) {
    const auto gpuResults = vulkan->classify(*set, queries);
    const auto mirror = makeMirrorTrimClassifier()->classify(*set, queries);
    REQUIRE(gpuResults.size() == mirror.size());
    size_t differ = 0;
    for (size_t i = 0; i < mirror.size(); ++i)
      if (gpuResults[i] != mirror[i] && ++differ <= 5)
        std::printf("  query %zu: GPU %s, mirror %s\n", i, className(gpuResults[i]),
                    className(mirror[i]));
    std::printf("trim classification on %s: %zu nodes (%s), %zu differ from the mirror\n",
                vulkan->name().c_str(), mirror.size(),
                set == &samples ? "hand-made loops" : "segments near node sides", differ);
    CHECK(differ == 0);
  }
  requireValidationClean();
}

TEST_CASE("Trim classification: Vulkan's started classification, finished after other "
          "submissions, is classify()'s",
          "[trim][gpu]") {
  auto vulkan = makeVulkanTrimClassifier(gpuContext());
  auto mirror = makeMirrorTrimClassifier();
  const TrimSet samples = trimSampleSet();
  const NearSideSamples nearSide = nearSideTrimSamples(3000, 406);
  const std::vector<gpu::TrimQuery> queries = trimSampleQueries(samples, 2000, 1703);
  // As the trimmed quad-tree does: start, another classifier's submission on the same queue
  // (its wait covers the started dispatch too), then finish.
  auto other = makeVulkanTrimClassifier(gpuContext());
  vulkan->startClassify(samples, queries);
  const auto between = other->classify(nearSide.set, nearSide.queries);
  const auto started = vulkan->finishClassify();
  CHECK(between == mirror->classify(nearSide.set, nearSide.queries));
  CHECK(started == mirror->classify(samples, queries));
  CHECK(started == vulkan->classify(samples, queries));
  CHECK(vulkan->finishClassify().empty());  // one finish per start
  // The default halves (the mirror's) and an empty start.
  mirror->startClassify(samples, queries);
  CHECK(mirror->finishClassify() == started);
  vulkan->startClassify(samples, {});
  CHECK(vulkan->finishClassify().empty());
  // A bound set (uploaded once, beginSet) serves the starts that follow; a plain classify of
  // another set in between uploads that one, and the next start uploads its own again.
  vulkan->beginSet(samples);
  vulkan->startClassify(samples, queries);
  CHECK(vulkan->finishClassify() == started);
  CHECK(vulkan->classify(nearSide.set, nearSide.queries) == between);
  vulkan->startClassify(samples, queries);
  CHECK(vulkan->finishClassify() == started);
  requireValidationClean();
}

// Timing, not a check (hidden: `tessera_tests "[trim-bench]"`): `nodes` tree cells of levels
// 5..10 on one face whose loop has 1000 segments (a wavy circle filling most of the piece).
TEST_CASE("Trim classification timing: 100k nodes against 1000 segments", "[.][trim-bench]") {
  std::vector<glm::dvec2> wavy;
  for (int k = 0; k < 1000; ++k) {
    const double angle = 2.0 * M_PI * k / 1000, r = 0.4 + 0.05 * std::sin(17.0 * angle);
    wavy.push_back({0.5 + r * std::cos(angle), 0.5 + r * std::sin(angle)});
  }
  const TrimSet set = packTrimSet({{wavy}}, {{0, {0, 0, 1, 1}}});
  std::mt19937 rng(9);
  std::vector<gpu::TrimQuery> queries;
  for (int k = 0; k < 100000; ++k) {
    const uint32_t cells = 1u << (5 + rng() % 6);
    const float size = 1.0f / float(cells), i = float(rng() % cells), j = float(rng() % cells);
    queries.push_back({{i * size, j * size, (i + 1) * size, (j + 1) * size}, 0, 0, 0, 0});
  }
  auto mirror = makeMirrorTrimClassifier();
  auto vulkan = makeVulkanTrimClassifier(gpuContext());
  std::vector<uint32_t> a, b;
  double mirrorMs = 1e300, vulkanMs = 1e300;
  for (int run = 0; run < 3; ++run) {
    const Stopwatch m;
    a = mirror->classify(set, queries);
    mirrorMs = std::min(mirrorMs, m.elapsedMs());
    const Stopwatch v;
    b = vulkan->classify(set, queries);
    vulkanMs = std::min(vulkanMs, v.elapsedMs());
  }
  std::array<size_t, 3> counts{};
  for (uint32_t c : a) ++counts[c];
  std::printf("trim classification, %zu nodes x %zu segments (%zu outside, %zu inside, %zu "
              "crossing): mirror %.1f ms (one core), %s %.1f ms (with transfers); best of 3\n",
              queries.size(), set.segments.size(), counts[0], counts[1], counts[2], mirrorMs,
              vulkan->name().c_str(), vulkanMs);
  CHECK(a == b);
}

TEST_CASE("trim segment index: the binned winding number is the full scan's", "[trim]") {
  // classifyTrimTriangle asks the index for the winding number at a triangle's centroid: it
  // counts only the segments binned in the point's row at or right of its cell, which must
  // give Sunday's sum over every segment — at points on cell lines, at loop vertices' heights,
  // on segments' ends and outside the loops' box included.
  std::mt19937 rng(1717);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int shape = 0; shape < 20; ++shape) {
    std::vector<TrimLoop> loops(2);
    const int n = 5 + shape * 7;  // a star around (0.5, 0.5) and a hole in it, clockwise
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * 3.14159265358979 * k / n, r = 0.25 + 0.2 * unit(rng);
      loops[0].uv.push_back({0.5 + r * std::cos(angle), 0.5 + r * std::sin(angle)});
      loops[1].uv.push_back({0.5 + 0.1 * std::cos(-angle), 0.5 + 0.1 * std::sin(-angle)});
    }
    if (shape % 3 == 0) loops[1].uv[0].y = loops[0].uv[1].y;  // vertices at one height
    for (TrimLoop& loop : loops) loop.pointIds.assign(loop.uv.size(), 0);
    const TrimSegmentIndex index(loops);
    std::vector<glm::dvec2> probes;
    for (int k = 0; k < 400; ++k) probes.push_back({1.4 * unit(rng) - 0.2, 1.4 * unit(rng) - 0.2});
    for (const TrimLoop& loop : loops)
      for (size_t k = 0; k < loop.uv.size(); ++k) {
        const glm::dvec2 a = loop.uv[k], b = loop.uv[(k + 1) % loop.uv.size()];
        probes.push_back({unit(rng), a.y});         // a vertex's height
        probes.push_back({std::max(a.x, b.x), 0.5 * (a.y + b.y)});  // level with an end
        probes.push_back({0.5 * (a.x + b.x) + 1e-12, 0.5 * (a.y + b.y)});  // next to it
      }
    const int side = std::clamp(int(std::sqrt(double(index.segments().size()))), 1, 256);
    const glm::dvec2 cell = (index.hi() - index.lo()) / double(side);
    for (int k = 0; k <= side; ++k)  // on the cell lines
      probes.push_back(index.lo() + double(k) * cell * glm::dvec2(1.0, 1.0 - 1e-3 * k));
    int inside = 0;
    for (const glm::dvec2& p : probes) {
      const int expected = trimWindingNumber(index.segments(), p);
      REQUIRE(index.windingNumber(p) == expected);
      inside += expected > 0;
    }
    CHECK(inside > 0);
    CHECK(inside < int(probes.size()));
  }
}

TEST_CASE("segmentsFartherThan answers segmentDistance > d", "[trim]") {
  // The gap's hole bridges test visibility with it: the same answer as the distance itself on
  // segments far apart, touching, crossing, nearly collinear (where the crossing test's signs
  // are rounding and the distance says 0 however far apart the boxes), at an offset of 10⁴.
  std::mt19937 rng(1718);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  size_t far = 0, near = 0, checked = 0;
  for (int k = 0; k < 20000; ++k) {
    const glm::dvec2 offset = k % 2 ? glm::dvec2(1e4, -1e4) : glm::dvec2(0.0);
    const double size = k % 3 ? 1.0 : 1e-6;
    const glm::dvec2 p0 = offset + size * glm::dvec2(unit(rng), unit(rng));
    glm::dvec2 p1 = offset + size * glm::dvec2(unit(rng), unit(rng));
    glm::dvec2 q0 = offset + size * glm::dvec2(unit(rng), unit(rng));
    glm::dvec2 q1 = offset + size * glm::dvec2(unit(rng), unit(rng));
    switch (k % 5) {
      case 1:  // on the line through p0 and p1, beyond p1: collinear and apart
        q0 = p0 + (1.0 + 0.5 * unit(rng)) * (p1 - p0), q1 = p0 + (2.0 + unit(rng)) * (p1 - p0);
        break;
      case 2:  // an end on the other segment
        q0 = p0 + unit(rng) * (p1 - p0);
        break;
      case 3:  // axis-parallel, one above the other
        p1.y = p0.y, q0.y = q1.y = p0.y + size * 1e-9 * unit(rng);
        break;
      default: break;
    }
    const double distance = segmentDistance(p0, p1, q0, q1);
    for (const double d : {0.0, 1e-13 * size, 1e-9 * size, 0.5 * distance, distance,
                           std::nextafter(distance, 0.0), 0.3 * size, 2.0 * size}) {
      REQUIRE(segmentsFartherThan(p0, p1, q0, q1, d) == (distance > d));
      ++checked;
    }
    (distance > 1e-3 * size ? far : near) += 1;
  }
  CHECK(checked == 160000);
  CHECK(far > 1000);
  CHECK(near > 1000);
}

TEST_CASE("Trim classification: the faces' v bins decide as the whole scan", "[trim]") {
  // A face of many segments is read through its v bins (TrimFace::binCount, packTrimSet): each
  // node reads the bins its v range reaches, each segment once. The same set without bins
  // scans the face whole. A wavy arc of 600 segments closed by a chord long in v (in every
  // bin), and a small hole: nodes of levels 2..9 anywhere on the piece, and the face's
  // rectangle itself.
  std::vector<glm::dvec2> wavy, hole;
  for (int k = 0; k < 600; ++k) {
    const double angle = M_PI * (k / 600.0 - 0.5), r = 0.4 + 0.05 * std::sin(17.0 * angle);
    wavy.push_back({0.5 + r * std::cos(angle), 0.5 + r * std::sin(angle)});
  }
  for (int k = 0; k < 40; ++k) {
    const double angle = -2.0 * M_PI * k / 40;
    hole.push_back({0.5 + 0.1 * std::cos(angle), 0.6 + 0.1 * std::sin(angle)});
  }
  const TrimSet set = packTrimSet({{wavy, hole}}, {{0, {0, 0, 1, 1}}, {0, {0.25, 0.5, 0.75, 1}}});
  REQUIRE(set.faces[0].binCount > 1);
  TrimSet whole = set;
  whole.faces[0].binCount = 0;
  whole.binWords.clear();
  std::mt19937 rng(17);
  std::vector<gpu::TrimQuery> queries = {{{0, 0, 1, 1}, 0, 0, 0, 0}};
  for (int k = 0; k < 4000; ++k) {
    const uint32_t cells = 1u << (2 + rng() % 8);
    const float size = 1.0f / float(cells), i = float(rng() % cells), j = float(rng() % cells);
    queries.push_back({{i * size, j * size, (i + 1) * size, (j + 1) * size}, uint32_t(rng() % 2), 0, 0, 0});
  }
  auto mirror = makeMirrorTrimClassifier();
  const std::vector<uint32_t> binned = mirror->classify(set, queries);
  const std::vector<uint32_t> scanned = mirror->classify(whole, queries);
  std::array<size_t, 3> counts{};
  size_t differ = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    ++counts[binned[i]];
    differ += binned[i] != scanned[i];
  }
  CHECK(differ == 0);
  // Every class occurs: the bins are not trivially all of the face, nor empty.
  CHECK(counts[gpu::kTrimInside] > 100);
  CHECK(counts[gpu::kTrimOutside] > 100);
  CHECK(counts[gpu::kTrimCrossing] > 100);
}
