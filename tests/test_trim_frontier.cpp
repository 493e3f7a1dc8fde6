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

}  // namespace

TEST_CASE("Trimmed quad-tree: nodes outside the loops end as kCauseTrimmedAway leaves, the rest "
          "is the untrimmed tree, and its leaves cover the trim region",
          "[trim][quadtree]") {
  // One face over [0, 2] × [0, 1], two curved pieces side by side, trimmed to a disc.
  const std::vector<BezierPatch> patches = randomBicubicPatches(2, 77);
  const std::vector<std::vector<glm::dvec2>> loops = {circleLoop({1.0, 0.5}, 0.42, 300, false)};
  const TrimSet set = packTrimSet({loops}, {{0, {0, 0, 1, 1}}, {0, {1, 0, 2, 1}}});
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const BezierPatch& p : patches)
    for (const glm::dvec3& c : p.cp) lo = glm::min(lo, c), hi = glm::max(hi, c);
  const QuadtreeOptions options = toleranceOptions(2e-4 * glm::length(hi - lo));
  const PatchSet patchSet = toPatchSet(patches);

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
    if (found == plainLeaves.end() || std::memcmp(&found->second, &leaf, sizeof leaf) != 0)
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
