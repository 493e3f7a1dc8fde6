// The trimming pass of the quad-tree frontier (host/trim/trim_frontier.h): on a curved square
// face trimmed to a disc, rule T's tree splits no node outside the loop, every such node ends as
// a kCauseTrimmedAway leaf, the other leaves are exactly the untrimmed tree's, and they cover
// the disc.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <tuple>

#include "gpu_test_context.h"
#include "patch_samples.h"
#include "trim/trim_frontier.h"
#include "trim_samples.h"

using namespace tessera;
using namespace tessera::test;

namespace {

// Records every node of every batch with its final decision (after the trimming pass).
class RecordingClassifier final : public NodeClassifier {
 public:
  explicit RecordingClassifier(NodeClassifier& inner) : inner_(inner) {}
  std::string name() const override { return inner_.name(); }
  void beginTree(const PatchSet& patches) override { inner_.beginTree(patches); }
  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) override {
    inner_.classify(patches, nodes, options, decisions, stats);
    for (size_t i = 0; i < nodes.size(); ++i) seen.push_back({nodes[i], decisions[i]});
  }
  std::vector<std::pair<gpu::QuadNode, gpu::NodeDecision>> seen;

 private:
  NodeClassifier& inner_;
};

using LeafKey = std::tuple<uint32_t, uint64_t, uint32_t>;  // patch, path, level
LeafKey keyOf(const QuadLeaf& leaf) { return {leaf.patchIndex, leaf.path, leaf.level}; }

// Field by field, floats by their bits (QuadLeaf has padding).
bool sameLeaf(const QuadLeaf& a, const QuadLeaf& b) {
  const auto bits = [](const void* x, const void* y, size_t n) { return std::memcmp(x, y, n) == 0; };
  return bits(&a.rect, &b.rect, sizeof a.rect) && a.patchIndex == b.patchIndex &&
         a.level == b.level && a.cause == b.cause && a.path == b.path &&
         bits(&a.linearity, &b.linearity, sizeof(float)) &&
         bits(&a.flatness, &b.flatness, sizeof(float)) && bits(&a.split, &b.split, sizeof a.split);
}

// One face over [0, 2] × [0, 1], two curved pieces side by side, trimmed to a disc; rule T at
// 2·10⁻⁴ of the patches' size.
struct TrimmedSquare {
  std::vector<BezierPatch> patches = randomBicubicPatches(2, 77);
  std::vector<std::vector<glm::dvec2>> loops = {circleLoop({1.0, 0.5}, 0.42, 300, false)};
  TrimSet set = packTrimSet({loops}, {{0, {0, 0, 1, 1}}, {0, {1, 0, 2, 1}}});
  PatchSet patchSet = toPatchSet(patches);
  QuadtreeOptions options;
  TrimmedSquare() {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const BezierPatch& p : patches)
      for (const glm::dvec3& c : p.cp) lo = glm::min(lo, c), hi = glm::max(hi, c);
    options = toleranceOptions(2e-4 * glm::length(hi - lo));
  }
};

}  // namespace

TEST_CASE("Trimmed quad-tree: nodes outside the loops end as kCauseTrimmedAway leaves, the rest "
          "is the untrimmed tree, and its leaves cover the trim region",
          "[trim][quadtree]") {
  const TrimmedSquare face;
  const std::vector<std::vector<glm::dvec2>>& loops = face.loops;
  const TrimSet& set = face.set;
  const QuadtreeOptions& options = face.options;
  const PatchSet& patchSet = face.patchSet;

  auto plainClassifier = makeMirrorClassifier();
  const QuadtreeResult plain = buildQuadtree(patchSet, options, *plainClassifier);
  auto inner = makeMirrorClassifier();
  auto trim = makeMirrorTrimClassifier();
  TrimmingClassifier trimming(*inner, set, *trim);
  RecordingClassifier recording(trimming);
  const QuadtreeResult trimmed = buildQuadtree(patchSet, options, recording);

  // No node the mirror calls outside was split; the double reference agrees it is outside.
  std::vector<gpu::TrimQuery> queries;
  for (const auto& [node, decision] : recording.seen)
    queries.push_back({node.rect, node.patchIndex, 0, 0, 0});
  const auto where = makeMirrorTrimClassifier()->classify(set, queries);
  size_t outsideNodes = 0, outsideSplit = 0, notReferenceOutside = 0;
  for (size_t i = 0; i < where.size(); ++i) {
    if (where[i] != gpu::kTrimOutside) {
      CHECK(recording.seen[i].second.cause != gpu::kCauseTrimmedAway);
      continue;
    }
    ++outsideNodes;
    if (recording.seen[i].second.cause != gpu::kCauseTrimmedAway) ++outsideSplit;
    if (classifyTrimNodeReference(set, queries[i]) != gpu::kTrimOutside) ++notReferenceOutside;
  }
  // Every leaf not trimmed away is a leaf of the untrimmed tree, bit for bit.
  std::map<LeafKey, QuadLeaf> plainLeaves;
  for (const QuadLeaf& leaf : plain.leaves) plainLeaves[keyOf(leaf)] = leaf;
  size_t kept = 0, trimmedLeaves = 0, notInPlain = 0;
  double area = 0;
  for (const QuadLeaf& leaf : trimmed.leaves) {
    area += double(leaf.rect.z - leaf.rect.x) * double(leaf.rect.w - leaf.rect.y);
    if (leaf.cause == gpu::kCauseTrimmedAway) {
      ++trimmedLeaves;
      continue;
    }
    ++kept;
    const auto found = plainLeaves.find(keyOf(leaf));
    if (found == plainLeaves.end() || !sameLeaf(found->second, leaf))
      ++notInPlain;
  }
  // Random points of the disc lie in kept leaves; points of trimmed leaves lie outside it.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  size_t discPoints = 0, uncovered = 0, trimmedButInside = 0;
  for (int k = 0; k < 4000; ++k) {
    const glm::dvec2 p(2.0 * unit(rng), unit(rng));
    const bool inDisc = insideLoops(loops, p);
    const uint32_t patch = p.x < 1.0 ? 0 : 1;
    const glm::dvec2 s(p.x - patch, p.y);
    for (const QuadLeaf& leaf : trimmed.leaves) {
      if (leaf.patchIndex != patch || s.x < leaf.rect.x || s.x >= leaf.rect.z ||
          s.y < leaf.rect.y || s.y >= leaf.rect.w)
        continue;
      if (leaf.cause == gpu::kCauseTrimmedAway && inDisc) ++trimmedButInside;
      break;
    }
    if (!inDisc) continue;
    ++discPoints;
    bool covered = false;
    for (const QuadLeaf& leaf : trimmed.leaves)
      if (leaf.cause != gpu::kCauseTrimmedAway && leaf.patchIndex == patch &&
          s.x >= leaf.rect.x && s.x <= leaf.rect.z && s.y >= leaf.rect.y && s.y <= leaf.rect.w) {
        covered = true;
        break;
      }
    if (!covered) ++uncovered;
  }
  std::printf("trimmed rule T tree: %zu leaves (%zu kept, %zu trimmed away) against %zu "
              "untrimmed; %zu nodes outside, %zu of them split, %zu not outside by the double "
              "reference; %zu kept leaves not in the untrimmed tree; leaf area %.9f of 2; %zu of "
              "%zu disc points uncovered, %zu in trimmed leaves\n",
              trimmed.leaves.size(), kept, trimmedLeaves, plain.leaves.size(), outsideNodes,
              outsideSplit, notReferenceOutside, notInPlain, area, uncovered, discPoints,
              trimmedButInside);
  CHECK(trimming.trimmedAway() == trimmedLeaves);
  CHECK(trimmedLeaves > 0);
  CHECK(trimmed.leaves.size() < plain.leaves.size());
  CHECK(outsideSplit == 0);
  CHECK(notReferenceOutside == 0);
  CHECK(notInPlain == 0);
  CHECK(area == Approx(2.0).epsilon(1e-9));
  CHECK(discPoints > 1000);
  CHECK(uncovered == 0);
  CHECK(trimmedButInside == 0);
}

TEST_CASE("Trimmed quad-tree: the Vulkan trim classifier gives the mirror's tree bit for bit",
          "[trim][quadtree][gpu]") {
  const TrimmedSquare face;
  auto inner = makeMirrorClassifier();
  auto mirrorTrim = makeMirrorTrimClassifier();
  auto vulkanTrim = makeVulkanTrimClassifier(gpuContext());
  const QuadtreeResult mirror =
      buildTrimmedQuadtree(face.patchSet, face.options, *inner, face.set, *mirrorTrim);
  const QuadtreeResult vulkan =
      buildTrimmedQuadtree(face.patchSet, face.options, *inner, face.set, *vulkanTrim);
  REQUIRE(vulkan.leaves.size() == mirror.leaves.size());
  size_t differ = 0;
  for (size_t i = 0; i < mirror.leaves.size(); ++i)
    if (!sameLeaf(mirror.leaves[i], vulkan.leaves[i])) ++differ;
  std::printf("trimmed tree with %s: %zu leaves, %zu differ from the mirror's\n",
              vulkanTrim->name().c_str(), mirror.leaves.size(), differ);
  CHECK(differ == 0);
  CHECK_THROWS_WITH(buildTrimmedQuadtree(toPatchSet(randomBicubicPatches(3, 1)), face.options,
                                         *inner, face.set, *mirrorTrim),
                    Catch::Contains("3 patches but 2 trim pieces"));
  requireValidationClean();
}
