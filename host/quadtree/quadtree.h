// Adaptive quad-tree tessellation of Bézier patches (Moriyama & Harada): bicubic ones on a
// fast path, general ones (degree 1..7, rational) through the same algorithm.
// The CPU owns the frontier: each level's nodes go to a NodeClassifier (GPU or CPU) in one
// batch; the decisions come back; leaves are emitted and the children of split nodes form the
// next level. Split rules: A uniform N×M grid, B midpoint, C sampled κ maximum, D true κ
// maximum (docs/quadtree.md).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "eval/patch_set.h"
#include "tessera/errors.h"
#include "shaders/layout.h"

namespace tessera {
namespace vk {
class Context;
}

// A, B, C, D of the paper; T (beyond it, issue 15): leaf when the node's proven deviation
// bound is within QuadtreeOptions::tolerance, anisotropic midpoint splits otherwise.
enum class SplitRule { UniformGrid, Midpoint, SampledMax, TrueMax, Tolerance };

// Parses "A".."D" (or "uniform", "midpoint", "sampled", "true"); throws std::invalid_argument.
SplitRule parseSplitRule(const std::string& name);
char splitRuleLetter(SplitRule rule);

struct LevelStats {
  uint32_t level = 0;
  size_t nodes = 0, splits = 0, leaves = 0;
  double classifyMs = 0;  // the classifier: GPU dispatch + transfers, or CPU work
  double gpuMs = 0;       // GPU time of the dispatch by timestamps (0 on CPU backends and
                          // without QuadtreeOptions::timeGpu)
  double frontierMs = 0;  // host: emitting leaves and building the next level
  size_t hostNodes = 0;   // of `nodes`, those a device backend left to the host's fp32 mirror
                          // (withSmallLevelsOnHost; 0 on CPU backends)
  size_t fusedNodes = 0;  // of `nodes`, those the Vulkan classifier decided by rule T's fused
                          // dispatch, the same decisions as its two (classifier_vulkan.cpp)
};

// Rule T's maximum depth: a level may split one direction only, so a patch needs up to about
// twice the levels of a four-way tree (the tea set at δ = 10⁻⁴ of its size stays well within).
constexpr uint32_t kToleranceMaxDepth = 30;
// Rule T's default cap on equal children per direction (QuadtreeOptions::toleranceSplitCap),
// the cap with the fewest tea-set triangles (docs/quadtree.md, "Rule T: tolerance").
constexpr uint32_t kToleranceSplitCap = 4;
// makeVulkanBackend's classifier decides a batch of fewer nodes than this on the host with the
// fp32 mirror under rule T (withSmallLevelsOnHost). Rule T on the tea set, warm, without
// timestamps (which add ~0.05 ms a level): a level costs lavapipe 0.03-0.09 ms whatever its
// size (a submission, its fence, two dispatches), the mirror ~1 µs a node (74 nodes: 0.050 ms
// on the device, 0.085 on the host; 16 nodes: 0.032 and 0.013; 8: 0.032 and 0.007), so they
// break even at 30-90 nodes (bench/HISTORY.md, "Small levels on the host"). A real GPU's
// submission costs no less, and the mirror's time does not depend on the device.
constexpr size_t kHostLevelNodes = 64;

struct QuadtreeOptions {
  SplitRule rule = SplitRule::Midpoint;
  float linearity = 0.1f;          // leaf when every 1 − Ti·Tj < linearity ...
  float flatness = 0.1f;           // ... and every 1 − Ni·Nj < flatness
  uint32_t maxDepth = 12;          // nodes at this depth are leaves (≤ 24; ≤ 32 for rule T)
  float minSize = 1.0f / 65536.0f; // nodes narrower than this (in u or v) are leaves
  int samples = 5;                 // S of rules C and D
  int gridU = 8, gridV = 8;        // N×M of rule A
  double tolerance = 0;            // δ of rule T in model units: every emitted triangle within δ
  // Rule T: a node that fails δ splits into the fewest k_u × k_v equal children whose
  // estimated bound is within δ when both counts are ≤ this cap (1..16; 1: midpoint splits
  // only), else at its midpoint along u, v or both.
  uint32_t toleranceSplitCap = kToleranceSplitCap;
  size_t nodeBudget = 1u << 24;    // most nodes in the tree, all levels together
  // Most bytes the frontier may hold at once: nodes waiting for classification, the batch in
  // flight with its decisions, and that batch's children. A level larger than that is
  // classified in batches, depth first (docs/quadtree.md, "Bounded frontier").
  size_t frontierBudgetBytes = size_t(256) << 20;
  // Time each level's dispatches by GPU timestamps (LevelStats::gpuMs, else 0): for reports
  // and level profiles. Off by default: on lavapipe a timestamp is a scene for its rasterizer
  // threads, ~0.4 ms and ~145 thread switches of the tea set's 6 levels at δ 0.01
  // (bench/HISTORY.md, "Timestamps and the command pool on lavapipe").
  bool timeGpu = false;
  // Called after each level (for progress display); may be empty.
  std::function<void(const LevelStats&)> onLevel;
};

// Rule T at δ = `tolerance` (model units) with its default depth, kToleranceMaxDepth.
QuadtreeOptions toleranceOptions(double tolerance);

// One leaf: the node rectangle, its depth, why it ended, the split point and test values its
// classification found (the split point is where the node would have been split).
struct QuadLeaf {
  gpu::vec4 rect;  // u0, v0, u1, v1
  uint32_t patchIndex;
  uint32_t level;
  uint32_t cause;  // gpu::kCause*
  uint64_t path;   // the child codes from the root, for comparing trees: a node split
                   // k_u × k_v gives child (i, j) the code i | j << ⌈log₂k_u⌉ in the next
                   // ⌈log₂k_u⌉ + ⌈log₂k_v⌉ bits (node_split.h). Rules B–D: 2 bits a level,
                   // the quadrant (0: u-low v-low, 1: u-high v-low, 2: u-low v-high, 3: both high)
  float linearity;  // rule T: A/(A + B), the u share of the bound (tolerance_bound.h)
  float flatness;   // rule T: the node's proven deviation bound, in the units of the patches
                    // the tree was built on (× QuadtreeResult::boundScale: model units)
  gpu::vec2 split;  // (us, vs) the classification chose (rule T: the centre, a fallback fan apex)
  uint32_t diagonal = gpu::kToleranceAnyDiagonal;  // rule T: the diagonal the leaf's bound
                                                   // holds for (NodeDecision.pad), which its
                                                   // triangles keep to (ring_triangulation.h)
};


struct QuadtreeResult {
  std::vector<QuadLeaf> leaves;
  std::vector<LevelStats> levels;
  uint32_t depth = 0;  // deepest leaf level
  size_t batches = 0;            // classifier calls (one per level when nothing was split up)
  size_t patchGroups = 0;        // trees built over patch subsets the classifier could hold
  size_t peakFrontierNodes = 0;  // most nodes held at once (see frontierBudgetBytes)
  // Model units per unit of rule T's leaf bounds: tessellate() builds the tree on the patches
  // in a local frame (geometry/model_frame.h) and leaves the bounds in its units, which fp32
  // holds at any model scale; 1 for a tree built on model coordinates (or pixels).
  double boundScale = 1.0;
};

// What one node of the tree costs by the end of a tessellation, for the memory budget
// (common/memory_budget.h): its QuadLeaf and its share of the mesh. Per vertex: the
// triangulation's (patch, u, v), the evaluation query (16 bytes) and sample (64), and the
// mesh's position, normal, uv and patch id (36); per triangle: indices, patch and three corner
// uvs, in the triangulation and again in the Tessellation (2 × 40). A leaf makes at most about
// 1.7 vertices and 3.3 triangles (measured on the teapot, rules A–D and T: 6,305 vertices and
// 12,370 triangles for 4,712 leaves at B; 105,001 and 208,601 for 65,267 at D 0.02), so 2 and 4.
constexpr size_t kTessellationBytesPerNode =
    sizeof(QuadLeaf) + 2 * (12 + 16 + 64 + 36) + 4 * 2 * (3 * 4 + 4 + 3 * 8);

// The frontier's bytes per node it holds (a QuadNode, its path and the path's bit count; a
// classified node also has a NodeDecision), for QuadtreeOptions::frontierBudgetBytes.
constexpr size_t kFrontierBytesPerNode = sizeof(gpu::QuadNode) + sizeof(uint64_t) + 1;
// The most children one node can make under `options`: 4, or toleranceSplitCap² for rule T.
size_t maxChildrenPerNode(const QuadtreeOptions& options);
// Nodes per classifier batch under `options` and a classifier that takes at most
// `classifierLimit` nodes at once. Depth-first batching leaves at most c − 1 batches of
// children waiting per level (c = maxChildrenPerNode), so batch = budget /
// ((c − 1)·maxDepth + c + 1) nodes keeps the whole frontier within the budget (c = 4:
// 3·maxDepth + 5). Throws std::invalid_argument when it would be < 1.
size_t frontierBatchNodes(const QuadtreeOptions& options, size_t classifierLimit);

// Throws std::invalid_argument naming the first option out of its range (thresholds, depth,
// samples, grid, node budget, rule T's tolerance). tessellate() calls it first; the CLI calls
// it before reading the input, so a bad option is a bad command line (exit 1).
void validateQuadtreeOptions(const QuadtreeOptions& options);

// The node budget would be exceeded: names the patch with the most frontier nodes and the level.
// A LimitError of the public API (include/tessera/errors.h).
class TessellationLimitError : public LimitError {
 public:
  using LimitError::LimitError;
};

// One level's classification, behind one interface so tests can swap backends.
class NodeClassifier {
 public:
  virtual ~NodeClassifier() = default;
  virtual std::string name() const = 0;
  // Called once per tree before its first level (the GPU backend uploads the patches here).
  virtual void beginTree(const PatchSet& patches) { (void)patches; }
  // Decides each node of one level: bicubic sets on the BicubicPatch fast path, general ones
  // (degree 1..7, polynomial or rational; general_patch.h) on the general path.
  virtual void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                        const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                        LevelStats& stats) = 0;
  // Most nodes one classify call may take, and most bytes of one patch array (BicubicPatch,
  // GeneralPatch or control points: PatchSet::bufferBytes) one tree may use: a GPU's largest storage buffer. The
  // frontier splits levels and patch sets to stay within them.
  virtual size_t maxBatchNodes() const { return SIZE_MAX; }
  virtual size_t maxPatchBufferBytes() const { return SIZE_MAX; }
};

std::unique_ptr<NodeClassifier> makeMirrorClassifier();            // fp32, shader's twin
std::unique_ptr<NodeClassifier> makeParallelMirrorClassifier();    // the same on all cores
std::unique_ptr<NodeClassifier> makeReferenceClassifier();         // double precision
std::unique_ptr<NodeClassifier> makeVulkanClassifier(vk::Context& context);  // device alone
// `device`, with rule T batches of fewer than `hostLevelNodes` nodes decided by the fp32 mirror
// on the host (LevelStats::hostNodes counts them; 0: every batch on the device).
std::unique_ptr<NodeClassifier> withSmallLevelsOnHost(std::unique_ptr<NodeClassifier> device,
                                                      size_t hostLevelNodes = kHostLevelNodes);

QuadtreeResult buildQuadtree(const PatchSet& patches, const QuadtreeOptions& options,
                             NodeClassifier& classifier);

// The push-constant block for `options` (shared by every backend).
gpu::ClassifyPush classifyParams(const QuadtreeOptions& options, uint32_t nodeCount);
uint32_t ruleConstant(SplitRule rule);

}  // namespace tessera
