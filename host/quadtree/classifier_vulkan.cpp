// The Vulkan backend of NodeClassifier: one dispatch of shaders/quadtree.comp.glsl (bicubic)
// or quadtree_general.comp.glsl (general patches) per level, or of their rule-B-only variants
// quadtree_midpoint.comp.glsl and quadtree_general_midpoint.comp.glsl, or rule-T-only ones:
// quadtree_general_tolerance.comp.glsl, and for bicubic patches two dispatches a level,
// quadtree_tolerance_nets.comp.glsl then quadtree_tolerance.comp.glsl, whose pipelines are built
// on two threads and which read the patches, the nodes and the nets as uniform texel buffers
// (shaders/lib/tolerance_texels.glsl); from a second rule T tree on, once its pipeline has built
// in the background, one dispatch a level of quadtree_tolerance_fused.comp.glsl, the same
// decisions (runBicubic). Rule T on general patches sends the nodes of polynomial
// patches of degree ≤ 3 × 3 and of rational ones of degree 2 × 1, 1 × 2, 2 × 2 and 3 × 3 to
// the variant built for their degree pair (quadtree_general_tolerance_{p,r}<n>x<m>.comp,
// shaders/CMakeLists.txt), each shader's nodes one range of the node buffer, all dispatched in
// one submission. Pipelines are made once per (shader, rule, S), when first needed, and
// buffers grow and are kept between levels.
#include <algorithm>
#include <array>
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t
#include <map>
#include <tuple>
#include <stdexcept>
#include <utility>

#include "common/stopwatch.h"
#include "quadtree/quadtree.h"
#include "quadtree_comp.h"
#include "quadtree_general_comp.h"
#include "quadtree_general_midpoint_comp.h"
#include "quadtree_general_tolerance_comp.h"
#include "quadtree_general_tolerance_p1x1_comp.h"
#include "quadtree_general_tolerance_p1x2_comp.h"
#include "quadtree_general_tolerance_p1x3_comp.h"
#include "quadtree_general_tolerance_p2x1_comp.h"
#include "quadtree_general_tolerance_p2x2_comp.h"
#include "quadtree_general_tolerance_p2x3_comp.h"
#include "quadtree_general_tolerance_p3x1_comp.h"
#include "quadtree_general_tolerance_p3x2_comp.h"
#include "quadtree_general_tolerance_p3x3_comp.h"
#include "quadtree_general_tolerance_r1x2_comp.h"
#include "quadtree_general_tolerance_r2x1_comp.h"
#include "quadtree_general_tolerance_r2x2_comp.h"
#include "quadtree_general_tolerance_r3x3_comp.h"
#include "quadtree_midpoint_comp.h"
#include "quadtree_tolerance_comp.h"
#include "quadtree_tolerance_fused_comp.h"
#include "quadtree_tolerance_nets_comp.h"
#include "vk/background_pipeline.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"
#include "vk/texel_view.h"

namespace tessera {
namespace {

// Buffers that rule T's bicubic shaders read as texel buffers (the other shaders as storage
// buffers).
constexpr VkBufferUsageFlags kTexelUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
// Rule T's bicubic shaders (lib/tolerance_texels.glsl): the nets shader reads patches and nodes
// as texel buffers (bindings 0, 1) and writes the nets (2, a storage buffer); the deciding
// shader reads patches, nodes and nets (0-2) and writes the decisions (3).
constexpr uint32_t kNetsTexelBindings = 0b011u;
constexpr uint32_t kDecidingTexelBindings = 0b0111u;
// The fused shader reads patches and nodes (0, 1) and writes the decisions (2).
constexpr uint32_t kFusedTexelBindings = 0b011u;

struct ShaderCode {
  const char* name;
  const uint32_t* spirv;
  size_t bytes;
};

#define TESSERA_GENERAL_VARIANT(kind, n, m)                                   \
  ShaderCode {                                                                \
    "quadtree_general_tolerance_" #kind #n "x" #m ".comp",                    \
        kSpirv_quadtree_general_tolerance_##kind##n##x##m##_comp,             \
        sizeof(kSpirv_quadtree_general_tolerance_##kind##n##x##m##_comp)      \
  }
// Rule T's general shader for one degree pair (shaders/CMakeLists.txt): polynomial (n, m) up to
// 3 × 3 at (n − 1)·3 + m − 1, then the rational pairs of conics and lines, then rational 3 × 3
// (every patch of rule T's tree in pixels: bicubic patches under the perspective map,
// host/mesh/screen_tolerance.cpp).
constexpr uint32_t kVariantMaxDegree = 3;
constexpr size_t kPolynomialVariants = kVariantMaxDegree * kVariantMaxDegree;
const std::array<ShaderCode, kPolynomialVariants + 4> kGeneralToleranceVariants = {
    TESSERA_GENERAL_VARIANT(p, 1, 1), TESSERA_GENERAL_VARIANT(p, 1, 2),
    TESSERA_GENERAL_VARIANT(p, 1, 3), TESSERA_GENERAL_VARIANT(p, 2, 1),
    TESSERA_GENERAL_VARIANT(p, 2, 2), TESSERA_GENERAL_VARIANT(p, 2, 3),
    TESSERA_GENERAL_VARIANT(p, 3, 1), TESSERA_GENERAL_VARIANT(p, 3, 2),
    TESSERA_GENERAL_VARIANT(p, 3, 3), TESSERA_GENERAL_VARIANT(r, 2, 1),
    TESSERA_GENERAL_VARIANT(r, 1, 2), TESSERA_GENERAL_VARIANT(r, 2, 2),
    TESSERA_GENERAL_VARIANT(r, 3, 3)};
#undef TESSERA_GENERAL_VARIANT
constexpr size_t kGeneralVariants = kGeneralToleranceVariants.size();
// The generic shader's place after the variants (variantOf's answer for the other patches).
constexpr size_t kGenericShader = kGeneralVariants;

// Which rule T shader classifies a patch's nodes: its variant, or the generic shader.
size_t variantOf(const gpu::GeneralPatch& patch) {
  const uint32_t n = patch.degreeU, m = patch.degreeV;
  if (patch.rational == 0u)
    return n >= 1 && m >= 1 && n <= kVariantMaxDegree && m <= kVariantMaxDegree
               ? (n - 1) * kVariantMaxDegree + (m - 1)
               : kGenericShader;
  if (n == 2 && m == 1) return kPolynomialVariants;
  if (n == 1 && m == 2) return kPolynomialVariants + 1;
  if (n == 2 && m == 2) return kPolynomialVariants + 2;
  if (n == 3 && m == 3) return kPolynomialVariants + 3;
  return kGenericShader;
}

class VulkanClassifier final : public NodeClassifier {
 public:
  explicit VulkanClassifier(vk::Context& context) : context_(context), timer_(context, 2) {}

  std::string name() const override { return "vulkan:" + context_.info().name; }

  // Every buffer is bound whole as one storage buffer, so none may exceed the device's
  // maxStorageBufferRange (128 MiB on lavapipe): nodes and decisions are 32 bytes each.
  // Rule T's bicubic shaders see nodes and nets through texel views, which
  // maxTexelBufferElements bounds too (not the binding on lavapipe or NVIDIA's GPUs).
  size_t maxBatchNodes() const override {
    return std::min(size_t(context_.info().maxStorageBufferRange) /
                        std::max(sizeof(gpu::QuadNode), sizeof(gpu::NodeDecision)),
                    size_t(vk::maxTexelViewBytes(context_)) / sizeof(gpu::ToleranceNetBounds));
  }
  size_t maxPatchBufferBytes() const override {
    return std::min(size_t(context_.info().maxStorageBufferRange),
                    size_t(vk::maxTexelViewBytes(context_)));
  }

  void beginTree(const PatchSet& patches) override {
    ++treesBegun_;
    uploadedCount_ = patches.size();
    uploadedGeneral_ = !patches.isBicubic();
    if (patches.size() == 0) return;
    if (patches.isBicubic()) {
      vk::ensureCapacity(context_, patches_, patches.size() * sizeof(gpu::BicubicPatch),
                         vk::BufferUse::Upload, kTexelUsage);
      patches_.upload(patches.bicubic());
      return;
    }
    const GeneralPatchSet& general = patches.general();
    patchShader_.resize(general.patches.size());
    for (size_t p = 0; p < general.patches.size(); ++p)
      patchShader_[p] = variantOf(general.patches[p]);
    vk::ensureCapacity(context_, patches_, general.patches.size() * sizeof(gpu::GeneralPatch),
                       vk::BufferUse::Upload, kTexelUsage);
    vk::ensureCapacity(context_, points_, general.points.size() * sizeof(gpu::vec4),
                       vk::BufferUse::Upload);
    patches_.upload(general.patches);
    points_.upload(general.points);
  }

  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) override {
    const bool general = !patches.isBicubic();
    if (uploadedCount_ != patches.size() || uploadedGeneral_ != general)
      throw std::logic_error("VulkanClassifier: classify() without beginTree() for these patches");
    if (general)
      runGeneral(nodes, options, decisions, stats);
    else
      runBicubic(nodes, options, decisions, stats);
  }

 private:
  // General patches: each shader's nodes (for rule T a variant's or the generic shader's, for
  // the other rules all the generic shader's) one range of the node and decision buffers, in
  // their order, starting where the device can bind it; one dispatch a range, one submission,
  // the decisions put back in the nodes' order.
  void runGeneral(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& options,
                  std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) {
    static_assert(sizeof(gpu::QuadNode) == sizeof(gpu::NodeDecision),
                  "one slot holds a node, then its decision");
    const Stopwatch stopwatch;
    decisions.resize(nodes.size());
    if (nodes.empty()) return;
    constexpr size_t kShaders = kGeneralVariants + 1;
    const bool variants = options.rule == SplitRule::Tolerance;
    const auto shaderOf = [&](const gpu::QuadNode& node) {
      return variants ? patchShader_[node.patchIndex] : kGenericShader;
    };
    std::array<size_t, kShaders> count{};
    for (const gpu::QuadNode& node : nodes) ++count[shaderOf(node)];
    const size_t slotAlignment = std::max<size_t>(
        1, size_t(context_.minStorageBufferOffsetAlignment()) / sizeof(gpu::QuadNode));
    std::array<size_t, kShaders> first{};
    size_t slots = 0;
    for (size_t k = 0; k < kShaders; ++k) {
      if (count[k] == 0) continue;
      slots = (slots + slotAlignment - 1) / slotAlignment * slotAlignment;
      first[k] = slots;
      slots += count[k];
    }
    // One shader: the nodes as they are. Else each node's slot, in the nodes' order per shader.
    const bool oneShader = slots == nodes.size() &&
                           std::count(count.begin(), count.end(), size_t(0)) == kShaders - 1;
    std::vector<uint32_t> slotOf;
    if (!oneShader) {
      slotOf.resize(nodes.size());
      sortedNodes_.assign(slots, gpu::QuadNode{});
      std::array<size_t, kShaders> next = first;
      for (size_t i = 0; i < nodes.size(); ++i) {
        slotOf[i] = uint32_t(next[shaderOf(nodes[i])]++);
        sortedNodes_[slotOf[i]] = nodes[i];
      }
    }
    std::array<vk::ComputePipeline*, kShaders> pipelines{};
    for (size_t k = 0; k < kShaders; ++k)
      if (count[k]) pipelines[k] = &generalPipeline(k, options);
    vk::ensureCapacity(context_, nodes_, slots * sizeof(gpu::QuadNode), vk::BufferUse::Upload,
                       kTexelUsage);
    vk::ensureCapacity(context_, decisions_, slots * sizeof(gpu::NodeDecision),
                       vk::BufferUse::Readback);
    if (oneShader)
      nodes_.upload(nodes);
    else
      nodes_.upload(sortedNodes_);
    const auto whole = [](const vk::Buffer& b) {
      return VkDescriptorBufferInfo{b.handle(), 0, VK_WHOLE_SIZE};
    };
    const auto range = [](const vk::Buffer& b, size_t firstSlot, size_t slotCount) {
      return VkDescriptorBufferInfo{b.handle(), firstSlot * sizeof(gpu::QuadNode),
                                    slotCount * sizeof(gpu::QuadNode)};
    };
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      if (options.timeGpu) {
        timer_.reset(cmd);
        timer_.mark(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
      }
      for (size_t k = 0; k < kShaders; ++k) {
        if (count[k] == 0) continue;
        const gpu::ClassifyPush push = classifyParams(options, uint32_t(count[k]));
        pipelines[k]->dispatch(cmd,
                               {whole(patches_), range(nodes_, first[k], count[k]),
                                range(decisions_, first[k], count[k]), whole(points_)},
                               &push, push.nodeCount);
      }
      if (options.timeGpu) timer_.mark(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
      vk::computeToHostBarrier(context_, cmd);
    });
    if (oneShader) {
      decisions_.download(decisions.data(), nodes.size() * sizeof(gpu::NodeDecision));
    } else {
      sortedDecisions_.resize(slots);
      decisions_.download(sortedDecisions_.data(), slots * sizeof(gpu::NodeDecision));
      for (size_t i = 0; i < nodes.size(); ++i) decisions[i] = sortedDecisions_[slotOf[i]];
    }
    if (options.timeGpu) addGpuMs(stats);
    stats.classifyMs += stopwatch.elapsedMs();
  }

  // The pipeline for general patches: rule T's variant k, or the generic shader of the rule
  // (kGenericShader). Rule T reads no S (the rule-T-only shaders leave rules C and D out): a
  // variant is made once.
  vk::ComputePipeline& generalPipeline(size_t k, const QuadtreeOptions& options) {
    if (k == kGenericShader)
      return pipelineFor(true, ruleConstant(options.rule), options.samples);
    std::unique_ptr<vk::ComputePipeline>& pipeline = variantPipelines_[k];
    if (!pipeline) {
      const ShaderCode& code = kGeneralToleranceVariants[k];
      pipeline = std::make_unique<vk::ComputePipeline>(
          context_, vk::ComputePipelineDesc{code.name,
                                            code.spirv,
                                            code.bytes,
                                            4u,
                                            sizeof(gpu::ClassifyPush),
                                            {{0, gpu::kSplitRuleTolerance}},
                                            0u});
    }
    return *pipeline;
  }

  // Bicubic patches: one dispatch, or rule T's two (the nets, then the decisions), or its fused
  // one once that pipeline is ready.
  void runBicubic(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& options,
                  std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) {
    const Stopwatch stopwatch;
    decisions.resize(nodes.size());
    if (nodes.empty()) return;
    const bool tolerance = options.rule == SplitRule::Tolerance;
    vk::ComputePipeline* fused = tolerance ? readyFusedPipeline() : nullptr;
    // Rule T on bicubic patches: the nets' pipeline builds on a worker thread while this one
    // builds the deciding pipeline.
    const bool twoDispatches = tolerance && !fused;
    if (twoDispatches) toleranceNets_.start();
    vk::ComputePipeline* pipeline =
        fused ? nullptr : &pipelineFor(false, ruleConstant(options.rule), options.samples);
    vk::ComputePipeline* nets = twoDispatches ? &toleranceNets_.get() : nullptr;
    if (nets)
      vk::ensureCapacity(context_, netBounds_, nodes.size() * sizeof(gpu::ToleranceNetBounds),
                         vk::BufferUse::Upload, kTexelUsage);
    vk::ensureCapacity(context_, nodes_, nodes.size() * sizeof(gpu::QuadNode),
                       vk::BufferUse::Upload, kTexelUsage);
    vk::ensureCapacity(context_, decisions_, nodes.size() * sizeof(gpu::NodeDecision),
                       vk::BufferUse::Readback);
    nodes_.upload(nodes);
    gpu::ClassifyPush push = classifyParams(options, uint32_t(nodes.size()));
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      if (options.timeGpu) {
        timer_.reset(cmd);
        timer_.mark(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
      }
      if (fused) {
        fused->dispatchBindings(
            cmd, {patchTexels_.viewOf(patches_), nodeTexels_.viewOf(nodes_), &decisions_}, &push,
            push.nodeCount);
      } else if (nets) {
        const VkBufferView points = patchTexels_.viewOf(patches_);
        const VkBufferView nodeTexels = nodeTexels_.viewOf(nodes_);
        const VkBufferView netTexels = netTexels_.viewOf(netBounds_);
        nets->dispatchBindings(cmd, {points, nodeTexels, &netBounds_}, &push, push.nodeCount);
        vk::computeToComputeBarrier(context_, cmd);
        pipeline->dispatchBindings(cmd, {points, nodeTexels, netTexels, &decisions_}, &push,
                                   push.nodeCount);
      } else {
        pipeline->dispatch(cmd, {&patches_, &nodes_, &decisions_}, &push, push.nodeCount);
      }
      if (options.timeGpu) timer_.mark(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
      vk::computeToHostBarrier(context_, cmd);
    });
    decisions_.download(decisions.data(), nodes.size() * sizeof(gpu::NodeDecision));
    if (fused) stats.fusedNodes += nodes.size();
    if (options.timeGpu) addGpuMs(stats);
    stats.classifyMs += stopwatch.elapsedMs();
  }

  // Rule T's fused pipeline where its background build has finished, else nullptr (the level
  // takes the two dispatches; nothing waits). The build starts in the second tree that runs
  // rule T on bicubic patches, so a process that tessellates once (README's command 1) neither
  // pays for it nor shares the CPU with it while its own two pipelines build. Under a thread cap
  // of 1 it never starts (BackgroundPipeline::start): on the caller's thread its compile (~20-30
  // ms of CPU, optimized as the two are: bench/HISTORY.md, session 43) would
  // cost one tree more than the fused dispatch saves many (~0.2-0.5 ms each).
  vk::ComputePipeline* readyFusedPipeline() {
    if (firstToleranceTree_ == 0) firstToleranceTree_ = treesBegun_;
    if (firstToleranceTree_ < treesBegun_) toleranceFused_.start();
    return toleranceFused_.ifReady();
  }

  // The GPU time between the submission's two timestamps (QuadtreeOptions::timeGpu).
  void addGpuMs(LevelStats& stats) const {
    const std::vector<double> intervals = timer_.intervalsNs();
    if (!intervals.empty()) stats.gpuMs += intervals[0] * 1e-6;
  }

  vk::ComputePipeline& pipelineFor(bool general, uint32_t rule, int samples) {
    auto key = std::make_tuple(general, rule, samples);
    auto it = pipelines_.find(key);
    if (it == pipelines_.end()) {
      const ShaderCode code = shaderFor(general, rule);
      const bool texels = !general && rule == gpu::kSplitRuleTolerance;
      vk::ComputePipelineDesc desc{code.name,
                                   code.spirv,
                                   code.bytes,
                                   general || texels ? 4u : 3u,
                                   sizeof(gpu::ClassifyPush),
                                   {{0, rule}, {1, uint32_t(samples)}},
                                   texels ? kDecidingTexelBindings : 0u};
      it = pipelines_.emplace(key, std::make_unique<vk::ComputePipeline>(context_, desc)).first;
    }
    return *it->second;
  }

  // Rules B and T run the variants built for them alone (without rules C and D's searches;
  // without the frames and rules B-D): the driver compiles a pipeline at every run, and the whole
  // shader costs it several times as long.
  static ShaderCode shaderFor(bool general, uint32_t rule) {
    if (rule == gpu::kSplitRuleMidpoint)
      return general ? ShaderCode{"quadtree_general_midpoint.comp",
                                  kSpirv_quadtree_general_midpoint_comp,
                                  sizeof(kSpirv_quadtree_general_midpoint_comp)}
                     : ShaderCode{"quadtree_midpoint.comp", kSpirv_quadtree_midpoint_comp,
                                  sizeof(kSpirv_quadtree_midpoint_comp)};
    if (rule == gpu::kSplitRuleTolerance)
      return general ? ShaderCode{"quadtree_general_tolerance.comp",
                                  kSpirv_quadtree_general_tolerance_comp,
                                  sizeof(kSpirv_quadtree_general_tolerance_comp)}
                     : ShaderCode{"quadtree_tolerance.comp", kSpirv_quadtree_tolerance_comp,
                                  sizeof(kSpirv_quadtree_tolerance_comp)};
    return general ? ShaderCode{"quadtree_general.comp", kSpirv_quadtree_general_comp,
                                sizeof(kSpirv_quadtree_general_comp)}
                   : ShaderCode{"quadtree.comp", kSpirv_quadtree_comp,
                                sizeof(kSpirv_quadtree_comp)};
  }

  vk::Context& context_;
  vk::GpuTimer timer_;
  vk::BackgroundPipeline toleranceNets_{
      context_,
      {"quadtree_tolerance_nets.comp", kSpirv_quadtree_tolerance_nets_comp,
       sizeof(kSpirv_quadtree_tolerance_nets_comp), 3, sizeof(gpu::ClassifyPush), {},
       kNetsTexelBindings}};
  vk::BackgroundPipeline toleranceFused_{context_,
                                         {"quadtree_tolerance_fused.comp",
                                          kSpirv_quadtree_tolerance_fused_comp,
                                          sizeof(kSpirv_quadtree_tolerance_fused_comp),
                                          3,
                                          sizeof(gpu::ClassifyPush),
                                          {},
                                          kFusedTexelBindings}};
  std::map<std::tuple<bool, uint32_t, int>, std::unique_ptr<vk::ComputePipeline>> pipelines_;
  // Rule T's general variants (kGeneralToleranceVariants), built when a level first needs one.
  std::array<std::unique_ptr<vk::ComputePipeline>, kGeneralVariants> variantPipelines_;
  std::vector<size_t> patchShader_;  // per uploaded general patch: variantOf
  std::vector<gpu::QuadNode> sortedNodes_;  // a level's nodes by shader (runGeneral)
  std::vector<gpu::NodeDecision> sortedDecisions_;
  vk::Buffer patches_, nodes_, decisions_, points_, netBounds_;
  // Rule T's bicubic shaders' views of the buffers, all RGBA32UI (lib/tolerance_texels.glsl).
  vk::TexelView patchTexels_{context_, VK_FORMAT_R32G32B32A32_UINT};
  vk::TexelView nodeTexels_{context_, VK_FORMAT_R32G32B32A32_UINT};
  vk::TexelView netTexels_{context_, VK_FORMAT_R32G32B32A32_UINT};
  size_t uploadedCount_ = 0;
  bool uploadedGeneral_ = false;
  size_t treesBegun_ = 0;          // beginTree calls
  size_t firstToleranceTree_ = 0;  // treesBegun_ at the first rule T bicubic level (0: none yet)
};

}  // namespace

std::unique_ptr<NodeClassifier> makeVulkanClassifier(vk::Context& context) {
  return std::make_unique<VulkanClassifier>(context);
}

}  // namespace tessera
