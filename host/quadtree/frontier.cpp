// The level-synchronous frontier of the adaptive quad-tree (CPU side).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "common/memory_budget.h"
#include "common/stopwatch.h"
#include "eval/evaluator.h"
#include "geometry/general_patch.h"
#include "quadtree/node_split.h"
#include "quadtree/quadtree.h"

namespace tessera {
namespace {

QuadtreeResult uniformGrid(size_t patchCount, const QuadtreeOptions& o) {
  QuadtreeResult result;
  size_t cells = size_t(o.gridU) * size_t(o.gridV);
  if (patchCount * cells > o.nodeBudget)
    throw TessellationLimitError("rule A: " + std::to_string(patchCount) + " patches × " +
                                 std::to_string(cells) + " cells exceed the node budget of " +
                                 std::to_string(o.nodeBudget));
  requireWithinMemoryBudget(
      saturatingMultiply(saturatingMultiply(patchCount, cells), kTessellationBytesPerNode),
      "rule A's " + std::to_string(patchCount) + " patches × " + std::to_string(cells) +
          " cells and their mesh");
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

// What to change, in the rule's own terms: rule T refines until its tolerance is met, the
// others until their angle thresholds are.
std::string budgetAdvice(SplitRule rule) {
  return rule == SplitRule::Tolerance
             ? "Raise the tolerance, lower the maximum depth, or raise the node budget."
             : "Raise the thresholds, lower the maximum depth, or raise the node budget.";
}

[[noreturn]] void throwBudgetExceeded(const std::vector<gpu::QuadNode>& next, uint32_t level,
                                      size_t total, size_t budget, SplitRule rule) {
  std::unordered_map<uint32_t, size_t> perPatch;
  for (const auto& n : next) ++perPatch[n.patchIndex];
  auto worst = std::max_element(perPatch.begin(), perPatch.end(),
                                [](const auto& a, const auto& b) { return a.second < b.second; });
  throw TessellationLimitError(
      "node budget of " + std::to_string(budget) + " exceeded at level " +
      std::to_string(level + 1) + " (" + std::to_string(total) + " nodes); patch " +
      std::to_string(worst->first) + " alone has " + std::to_string(worst->second) +
      " nodes there. " + budgetAdvice(rule));
}

// A threshold as a message shows it: as short as "%g" makes it (0.1, -1, nan).
std::string shownNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

void validateQuadtreeOptions(const QuadtreeOptions& o) {
  auto positiveFinite = [](float x) { return std::isfinite(x) && x > 0.0f; };
  if (!positiveFinite(o.linearity) || !positiveFinite(o.flatness))
    throw std::invalid_argument("linearity and flatness must be finite and > 0 (got " +
                                shownNumber(o.linearity) + " and " + shownNumber(o.flatness) + ")");
  if (!(o.minSize >= 0.0f) || !std::isfinite(o.minSize))
    throw std::invalid_argument("the minimum node size must be finite and >= 0");
  // Paths keep 2 bits per level in 64 bits; fp32 parameters stop resolving long before.
  // Rule T's levels may split one direction only, so it may go deeper (kToleranceMaxDepth).
  const uint32_t depthCap = o.rule == SplitRule::Tolerance ? 32 : 24;
  if (o.maxDepth > depthCap)
    throw std::invalid_argument("the maximum depth is at most " + std::to_string(depthCap) +
                                (o.rule == SplitRule::Tolerance ? " for rule T" : "") + " (got " +
                                std::to_string(o.maxDepth) + ")");
  if (o.samples < 1 || o.samples > 32)
    throw std::invalid_argument("the sample count S of rules C and D must be 1..32 (got " +
                                std::to_string(o.samples) + ")");
  if (o.gridU < 1 || o.gridV < 1 || o.gridU > 4096 || o.gridV > 4096)
    throw std::invalid_argument("the uniform grid of rule A must be 1..4096 cells per side");
  if (o.nodeBudget == 0) throw std::invalid_argument("the node budget must be > 0");
  if (o.rule == SplitRule::Tolerance &&
      (o.toleranceSplitCap < 1 || o.toleranceSplitCap > gpu::kToleranceSplitCapMax))
    throw std::invalid_argument("rule T's split cap must be 1.." +
                                std::to_string(gpu::kToleranceSplitCapMax) + " children per direction");
  if (o.rule == SplitRule::Tolerance && !(o.tolerance > 0 && std::isfinite(o.tolerance) &&
                                           float(o.tolerance) > 0.0f))
    throw std::invalid_argument("the tolerance of rule T must be finite and > 0 in fp32");
}

SplitRule parseSplitRule(const std::string& name) {
  if (name == "A" || name == "a" || name == "uniform") return SplitRule::UniformGrid;
  if (name == "B" || name == "b" || name == "midpoint") return SplitRule::Midpoint;
  if (name == "C" || name == "c" || name == "sampled") return SplitRule::SampledMax;
  if (name == "D" || name == "d" || name == "true") return SplitRule::TrueMax;
  if (name == "T" || name == "t" || name == "tolerance") return SplitRule::Tolerance;
  throw std::invalid_argument("unknown split rule '" + name + "' (expected A, B, C, D or T)");
}

QuadtreeOptions toleranceOptions(double tolerance) {
  QuadtreeOptions options;
  options.rule = SplitRule::Tolerance;
  options.tolerance = tolerance;
  options.maxDepth = kToleranceMaxDepth;
  return options;
}

char splitRuleLetter(SplitRule rule) { return "ABCDT"[static_cast<int>(rule)]; }

uint32_t ruleConstant(SplitRule rule) {
  switch (rule) {
    case SplitRule::SampledMax: return gpu::kSplitRuleSampledMax;
    case SplitRule::TrueMax: return gpu::kSplitRuleTrueMax;
    case SplitRule::Tolerance: return gpu::kSplitRuleTolerance;
    default: return gpu::kSplitRuleMidpoint;
  }
}

gpu::ClassifyPush classifyParams(const QuadtreeOptions& o, uint32_t nodeCount) {
  return {o.linearity, o.flatness, o.minSize, kDegenerateEpsFp32, o.maxDepth, nodeCount,
          static_cast<float>(o.tolerance),
          o.rule == SplitRule::Tolerance ? o.toleranceSplitCap : 0u};
}

size_t maxChildrenPerNode(const QuadtreeOptions& options) {
  if (options.rule != SplitRule::Tolerance) return 4;
  return std::max<size_t>(4, size_t(options.toleranceSplitCap) * options.toleranceSplitCap);
}

size_t frontierBatchNodes(const QuadtreeOptions& options, size_t classifierLimit) {
  // Held at the peak, with c = the most children a node makes: ≤ c − 1 waiting batches for
  // each level 1..maxDepth, the batch in flight (with its decisions) and its ≤ c batches of
  // children (c = 4: 3·maxDepth + 5 batches).
  const size_t c = maxChildrenPerNode(options);
  const size_t bytesPerBatchNode =
      kFrontierBytesPerNode * ((c - 1) * size_t(options.maxDepth) + c + 1) +
      sizeof(gpu::NodeDecision);
  const size_t byBudget = options.frontierBudgetBytes / bytesPerBatchNode;
  if (byBudget < 1)
    throw std::invalid_argument("the frontier budget of " +
                                std::to_string(options.frontierBudgetBytes) +
                                " bytes holds no batch: at least " +
                                std::to_string(bytesPerBatchNode) + " bytes are needed at depth " +
                                std::to_string(options.maxDepth));
  return std::max<size_t>(1, std::min(byBudget, classifierLimit));
}

namespace {

// Patch groups: the patches one tree may take at once (what the classifier's patch buffer
// holds, and no more roots than one batch). Usually one group, the whole set, uncopied.

// Nodes of one level waiting for the classifier, with their paths and the bits each path uses.
struct Batch {
  uint32_t level = 0;
  std::vector<gpu::QuadNode> nodes;
  std::vector<uint64_t> paths;
  std::vector<uint8_t> pathBits;
};

// Pushes `nodes` as batches of at most `batchNodes`, the first on top (so it runs next).
void pushBatches(std::vector<Batch>& stack, uint32_t level, std::vector<gpu::QuadNode>& nodes,
                 std::vector<uint64_t>& paths, std::vector<uint8_t>& pathBits,
                 size_t batchNodes) {
  const size_t count = (nodes.size() + batchNodes - 1) / batchNodes;
  for (size_t k = count; k-- > 0;) {
    const size_t first = k * batchNodes, last = std::min(nodes.size(), first + batchNodes);
    Batch batch;
    batch.level = level;
    if (count == 1) {
      batch.nodes.swap(nodes);
      batch.paths.swap(paths);
      batch.pathBits.swap(pathBits);
    } else {
      batch.nodes.assign(nodes.begin() + long(first), nodes.begin() + long(last));
      batch.paths.assign(paths.begin() + long(first), paths.begin() + long(last));
      batch.pathBits.assign(pathBits.begin() + long(first), pathBits.begin() + long(last));
    }
    stack.push_back(std::move(batch));
  }
  nodes.clear();
  paths.clear();
  pathBits.clear();
}

// Room for what a batch adds, so that no vector grows while it is taken: its children (the
// splits the decisions ask for; a split fp32 cannot place gives none) and its leaves. Every node
// ends as one leaf or more, so the leaves so far, this batch's nodes and the `waiting` ones are
// never more than the tree's leaves: reserved by that count and a quarter more (or 1.5× the
// room held when it grows), the leaves are moved a few times in a tree, not at every doubling
// of a growing vector. The quarter is for the last levels, which add few nodes: without it the
// tea set's level 4 at δ 0.01 moved all 4,050 leaves so far to make room for 8 more.
void reserveForLevel(const Batch& batch, const std::vector<gpu::NodeDecision>& decisions,
                     size_t waiting, std::vector<QuadLeaf>& leaves,
                     std::vector<gpu::QuadNode>& next, std::vector<uint64_t>& nextPaths,
                     std::vector<uint8_t>& nextPathBits) {
  size_t children = 0;
  for (size_t i = 0; i < batch.nodes.size(); ++i) {
    const SplitCounts counts = splitCounts(decisions[i]);
    if (counts.splits()) children += size_t(counts.u) * counts.v;
  }
  next.reserve(children);
  nextPaths.reserve(children);
  nextPathBits.reserve(children);
  const size_t leastLeaves = leaves.size() + batch.nodes.size() + waiting;
  if (leaves.capacity() < leastLeaves)
    leaves.reserve(
        std::max(leastLeaves + leastLeaves / 4, leaves.capacity() + leaves.capacity() / 2));
}

void addLevelStats(LevelStats& total, const LevelStats& batch) {
  total.nodes += batch.nodes;
  total.splits += batch.splits;
  total.leaves += batch.leaves;
  total.classifyMs += batch.classifyMs;
  total.gpuMs += batch.gpuMs;
  total.frontierMs += batch.frontierMs;
  total.hostNodes += batch.hostNodes;
  total.fusedNodes += batch.fusedNodes;
}

// One tree over `patches` (a group; leaves name patch firstPatch + local index). Levels are
// classified whole while they fit in a batch — the level-synchronous algorithm of the paper —
// and split into batches taken depth first when they do not, which bounds the frontier.
void buildGroupTree(const PatchSet& patches, uint32_t firstPatch, const QuadtreeOptions& options,
                    NodeClassifier& classifier, size_t batchNodes, size_t& total,
                    QuadtreeResult& result) {
  std::vector<gpu::QuadNode> roots;
  std::vector<uint64_t> rootPaths;
  std::vector<uint8_t> rootPathBits;
  for (uint32_t p = 0; p < patches.size(); ++p) {
    roots.push_back({gpu::vec4(0.0f, 0.0f, 1.0f, 1.0f), p, 0, 0, 0});
    rootPaths.push_back(0);
    rootPathBits.push_back(0);
  }
  classifier.beginTree(patches);
  std::vector<Batch> stack;
  size_t waiting = roots.size();  // nodes in `stack`
  pushBatches(stack, 0, roots, rootPaths, rootPathBits, batchNodes);
  std::vector<gpu::NodeDecision> decisions;
  std::vector<gpu::QuadNode> next;
  std::vector<uint64_t> nextPaths;
  std::vector<uint8_t> nextPathBits;
  while (!stack.empty()) {
    Batch batch = std::move(stack.back());
    stack.pop_back();
    waiting -= batch.nodes.size();
    const uint32_t level = batch.level;
    LevelStats stats;
    stats.level = level;
    stats.nodes = batch.nodes.size();
    classifier.classify(patches, batch.nodes, options, decisions, stats);
    ++result.batches;

    const Stopwatch stopwatch;
    next.clear();
    nextPaths.clear();
    nextPathBits.clear();
    reserveForLevel(batch, decisions, waiting, result.leaves, next, nextPaths, nextPathBits);
    for (size_t i = 0; i < batch.nodes.size(); ++i) {
      const gpu::QuadNode& n = batch.nodes[i];
      const gpu::NodeDecision& d = decisions[i];
      const SplitCounts counts = splitCounts(d);
      uint32_t cause = d.cause;
      // Child k = (i, j) of a k_u × k_v split gets the code i | j << bits(k_u) after its
      // parent's path: 2 bits a level for the 2 × 2 splits of rules B–D (the quadrant), fewer
      // or more for rule T's one-way and grid splits; siblings differ in the bits they add.
      const uint32_t used = batch.pathBits[i];
      const uint32_t bitsU = pathCodeBits(counts.u), bitsV = pathCodeBits(counts.v);
      // A path that would pass 64 bits, or lines fp32 cannot place strictly inside (its
      // resolution ran out), would not make distinct children: end the node here instead.
      if (counts.splits() && (used + bitsU + bitsV > 64 || !appendChildren(n, d, counts, next)))
        cause = gpu::kCauseMinSize;
      if (!counts.splits() || cause == gpu::kCauseMinSize) {
        result.leaves.push_back({n.rect, firstPatch + n.patchIndex, level, cause, batch.paths[i],
                                 d.linearity, d.flatness, gpu::vec2(d.split.x, d.split.y),
                                 cause == gpu::kCauseWithinTolerance ? d.pad
                                                                     : gpu::kToleranceAnyDiagonal});
        result.depth = std::max(result.depth, level);
        ++stats.leaves;
        continue;
      }
      ++stats.splits;
      // Row by row, as appendChildren appends them: no k mod k_u and k div k_u (a division a
      // child).
      const uint8_t childBits = uint8_t(used + bitsU + bitsV);
      for (uint32_t row = 0; row < counts.v; ++row)
        for (uint32_t column = 0; column < counts.u; ++column) {
          const uint64_t code = uint64_t(column) | (uint64_t(row) << bitsU);
          nextPaths.push_back(batch.paths[i] | (code << used));  // used < 64 here
          nextPathBits.push_back(childBits);
        }
    }
    total += next.size();
    if (total > options.nodeBudget) {
      for (auto& n : next) n.patchIndex += firstPatch;  // name the patch as the caller knows it
      throwBudgetExceeded(next, level, total, options.nodeBudget, options.rule);
    }
    requireWithinMemoryBudget(saturatingMultiply(total, kTessellationBytesPerNode),
                              "the quad-tree's " + std::to_string(total) + " nodes at level " +
                                  std::to_string(level + 1) + " and their mesh");
    result.peakFrontierNodes =
        std::max(result.peakFrontierNodes, waiting + batch.nodes.size() + next.size());
    waiting += next.size();
    pushBatches(stack, level + 1, next, nextPaths, nextPathBits, batchNodes);
    stats.frontierMs = stopwatch.elapsedMs();
    if (result.levels.size() <= level) result.levels.resize(level + 1);
    result.levels[level].level = level;
    addLevelStats(result.levels[level], stats);
    if (options.onLevel) options.onLevel(result.levels[level]);
  }
}

QuadtreeResult buildTree(const PatchSet& patches, const QuadtreeOptions& options,
                         NodeClassifier& classifier) {
  validateQuadtreeOptions(options);
  if (options.rule == SplitRule::UniformGrid) return uniformGrid(patches.size(), options);
  if (patches.size() > options.nodeBudget)
    throw TessellationLimitError(std::to_string(patches.size()) +
                                 " patches exceed the node budget of " +
                                 std::to_string(options.nodeBudget));
  requireWithinMemoryBudget(saturatingMultiply(patches.size(), kTessellationBytesPerNode),
                            "the quad-tree of " + std::to_string(patches.size()) +
                                " patches and their mesh");

  const size_t batchNodes = frontierBatchNodes(options, classifier.maxBatchNodes());
  const size_t bufferBytes = classifier.maxPatchBufferBytes();
  QuadtreeResult result;
  size_t total = 0;
  // One group when the whole set fits: the walk below would reach its end anyway (a group's
  // bytes only grow with it), but re-summing the group at every step is quadratic in patches.
  const bool oneGroup =
      patches.size() <= batchNodes && patches.bufferBytes(0, patches.size()) <= bufferBytes;
  for (size_t first = 0; first < patches.size();) {
    size_t last = oneGroup ? patches.size() : first + 1;
    while (last < patches.size() && last - first < batchNodes &&
           patches.bufferBytes(first, last + 1) <= bufferBytes)
      ++last;
    if (patches.bufferBytes(first, last) > bufferBytes)
      throw TessellationLimitError("patch " + std::to_string(first) + " alone needs " +
                                   std::to_string(patches.bufferBytes(first, last)) +
                                   " bytes, more than the device's largest storage buffer (" +
                                   std::to_string(bufferBytes) + " bytes)");
    total += last - first;
    ++result.patchGroups;
    if (first == 0 && last == patches.size())
      buildGroupTree(patches, 0, options, classifier, batchNodes, total, result);
    else
      buildGroupTree(patches.subset(first, last), uint32_t(first), options, classifier,
                     batchNodes, total, result);
    first = last;
  }
  return result;
}

}  // namespace

QuadtreeResult buildQuadtree(const PatchSet& patches, const QuadtreeOptions& options,
                             NodeClassifier& classifier) {
  return buildTree(patches, options, classifier);
}

}  // namespace tessera
