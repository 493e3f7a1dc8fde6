// The level-synchronous frontier of the adaptive quad-tree (CPU side).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "evaluator.h"
#include "quadtree.h"

namespace tessera {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

void validateOptions(const QuadtreeOptions& o) {
  auto positiveFinite = [](float x) { return std::isfinite(x) && x > 0.0f; };
  if (!positiveFinite(o.linearity) || !positiveFinite(o.flatness))
    throw std::invalid_argument("linearity and flatness must be finite and > 0");
  if (!(o.minSize >= 0.0f) || !std::isfinite(o.minSize))
    throw std::invalid_argument("the minimum node size must be finite and >= 0");
  // Paths keep 2 bits per level in 64 bits; fp32 parameters stop resolving long before.
  if (o.maxDepth > 24) throw std::invalid_argument("the maximum depth is at most 24");
  if (o.samples < 1 || o.samples > 32)
    throw std::invalid_argument("the sample count S of rules C and D must be 1..32");
  if (o.gridU < 1 || o.gridV < 1 || o.gridU > 4096 || o.gridV > 4096)
    throw std::invalid_argument("the uniform grid of rule A must be 1..4096 cells per side");
  if (o.nodeBudget == 0) throw std::invalid_argument("the node budget must be > 0");
}

QuadtreeResult uniformGrid(size_t patchCount, const QuadtreeOptions& o) {
  QuadtreeResult result;
  size_t cells = size_t(o.gridU) * size_t(o.gridV);
  if (patchCount * cells > o.nodeBudget)
    throw TessellationLimitError("rule A: " + std::to_string(patchCount) + " patches × " +
                                 std::to_string(cells) + " cells exceed the node budget of " +
                                 std::to_string(o.nodeBudget));
  result.leaves.reserve(patchCount * cells);
  for (uint32_t p = 0; p < patchCount; ++p)
    for (int i = 0; i < o.gridU; ++i)
      for (int j = 0; j < o.gridV; ++j) {
        QuadLeaf leaf{};
        leaf.rect = gpu::vec4(float(i) / float(o.gridU), float(j) / float(o.gridV),
                              float(i + 1) / float(o.gridU), float(j + 1) / float(o.gridV));
        leaf.patchIndex = p;
        leaf.cause = gpu::kCauseUniform;
        leaf.path = uint64_t(i) * uint64_t(o.gridV) + uint64_t(j);
        leaf.split = gpu::vec2(0.5f * (leaf.rect.x + leaf.rect.z), 0.5f * (leaf.rect.y + leaf.rect.w));
        result.leaves.push_back(leaf);
      }
  LevelStats stats;
  stats.nodes = stats.leaves = result.leaves.size();
  result.levels.push_back(stats);
  return result;
}

[[noreturn]] void throwBudgetExceeded(const std::vector<gpu::QuadNode>& next, uint32_t level,
                                      size_t total, size_t budget) {
  std::unordered_map<uint32_t, size_t> perPatch;
  for (const auto& n : next) ++perPatch[n.patchIndex];
  auto worst = std::max_element(perPatch.begin(), perPatch.end(),
                                [](const auto& a, const auto& b) { return a.second < b.second; });
  throw TessellationLimitError(
      "node budget of " + std::to_string(budget) + " exceeded at level " +
      std::to_string(level + 1) + " (" + std::to_string(total) + " nodes); patch " +
      std::to_string(worst->first) + " alone has " + std::to_string(worst->second) +
      " nodes there. Raise the thresholds, lower the maximum depth, or raise the budget.");
}

}  // namespace

SplitRule parseSplitRule(const std::string& name) {
  if (name == "A" || name == "a" || name == "uniform") return SplitRule::UniformGrid;
  if (name == "B" || name == "b" || name == "midpoint") return SplitRule::Midpoint;
  if (name == "C" || name == "c" || name == "sampled") return SplitRule::SampledMax;
  if (name == "D" || name == "d" || name == "true") return SplitRule::TrueMax;
  throw std::invalid_argument("unknown split rule '" + name + "' (expected A, B, C or D)");
}

char splitRuleLetter(SplitRule rule) { return "ABCD"[static_cast<int>(rule)]; }

uint32_t ruleConstant(SplitRule rule) {
  switch (rule) {
    case SplitRule::SampledMax: return gpu::kSplitRuleSampledMax;
    case SplitRule::TrueMax: return gpu::kSplitRuleTrueMax;
    default: return gpu::kSplitRuleMidpoint;
  }
}

gpu::ClassifyPush classifyParams(const QuadtreeOptions& o, uint32_t nodeCount) {
  return {o.linearity, o.flatness, o.minSize, kDegenerateEpsFp32, o.maxDepth, nodeCount, 0, 0};
}

namespace {

// The classifier's entry points for each patch representation.
void beginTree(NodeClassifier& c, const std::vector<gpu::BicubicPatch>& p) { c.beginTree(p); }
void beginTree(NodeClassifier& c, const GeneralPatchSet& p) { c.beginGeneralTree(p); }
void classifyLevel(NodeClassifier& c, const std::vector<gpu::BicubicPatch>& p,
                   const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& o,
                   std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) {
  c.classify(p, nodes, o, decisions, stats);
}
void classifyLevel(NodeClassifier& c, const GeneralPatchSet& p,
                   const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& o,
                   std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) {
  c.classifyGeneral(p, nodes, o, decisions, stats);
}

template <class Patches>
QuadtreeResult buildTree(const Patches& patches, const QuadtreeOptions& options,
                         NodeClassifier& classifier) {
  validateOptions(options);
  if (options.rule == SplitRule::UniformGrid) return uniformGrid(patches.size(), options);

  QuadtreeResult result;
  std::vector<gpu::QuadNode> nodes;
  std::vector<uint64_t> paths;
  for (uint32_t p = 0; p < patches.size(); ++p) {
    nodes.push_back({gpu::vec4(0.0f, 0.0f, 1.0f, 1.0f), p, 0, 0, 0});
    paths.push_back(0);
  }
  size_t total = nodes.size();
  if (total > options.nodeBudget)
    throw TessellationLimitError(std::to_string(total) + " patches exceed the node budget of " +
                                 std::to_string(options.nodeBudget));

  beginTree(classifier, patches);
  std::vector<gpu::NodeDecision> decisions;
  std::vector<gpu::QuadNode> next;
  std::vector<uint64_t> nextPaths;
  for (uint32_t level = 0; !nodes.empty(); ++level) {
    LevelStats stats;
    stats.level = level;
    stats.nodes = nodes.size();
    classifyLevel(classifier, patches, nodes, options, decisions, stats);

    auto start = std::chrono::steady_clock::now();
    next.clear();
    nextPaths.clear();
    for (size_t i = 0; i < nodes.size(); ++i) {
      const gpu::QuadNode& n = nodes[i];
      const gpu::NodeDecision& d = decisions[i];
      float us = d.split.x, vs = d.split.y;
      uint32_t cause = d.cause;
      // A split point that does not fall strictly inside (fp32 ran out of resolution)
      // would make empty children: end the node here instead.
      if (cause == gpu::kCauseSplit &&
          !(us > n.rect.x && us < n.rect.z && vs > n.rect.y && vs < n.rect.w))
        cause = gpu::kCauseMinSize;
      if (cause != gpu::kCauseSplit) {
        result.leaves.push_back(
            {n.rect, n.patchIndex, level, cause, paths[i], d.linearity, d.flatness,
             gpu::vec2(us, vs)});
        result.depth = std::max(result.depth, level);
        ++stats.leaves;
        continue;
      }
      ++stats.splits;
      const gpu::vec4 r = n.rect;
      const gpu::vec4 children[4] = {{r.x, r.y, us, vs}, {us, r.y, r.z, vs},
                                     {r.x, vs, us, r.w}, {us, vs, r.z, r.w}};
      for (uint64_t q = 0; q < 4; ++q) {
        next.push_back({children[q], n.patchIndex, level + 1, 0, 0});
        nextPaths.push_back(paths[i] | (q << (2 * level)));
      }
    }
    total += next.size();
    if (total > options.nodeBudget) throwBudgetExceeded(next, level, total, options.nodeBudget);
    stats.frontierMs = millisecondsSince(start);
    result.levels.push_back(stats);
    if (options.onLevel) options.onLevel(stats);
    nodes.swap(next);
    paths.swap(nextPaths);
  }
  return result;
}

}  // namespace

QuadtreeResult buildQuadtree(const std::vector<gpu::BicubicPatch>& patches,
                             const QuadtreeOptions& options, NodeClassifier& classifier) {
  return buildTree(patches, options, classifier);
}

QuadtreeResult buildQuadtree(const GeneralPatchSet& patches, const QuadtreeOptions& options,
                             NodeClassifier& classifier) {
  return buildTree(patches, options, classifier);
}

}  // namespace tessera
