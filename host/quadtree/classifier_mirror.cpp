// CPU backends of NodeClassifier: the fp32 mirror of the shader, on one thread or on all.
#include <algorithm>

#include "common/parallel_for.h"
#include "common/stopwatch.h"
#include "eval/general_mirror.h"
#include "quadtree/detail/classify_mirror.h"
#include "quadtree/quadtree.h"

namespace tessera {
namespace {

gpu::NodeDecision classifyOne(const std::vector<gpu::BicubicPatch>& patches,
                              const gpu::QuadNode& node, uint32_t rule, int samples,
                              const gpu::ClassifyPush& params) {
  return mirror::classifyNode(patches[node.patchIndex], node, rule, samples, params);
}

gpu::NodeDecision classifyOne(const GeneralPatchSet& patches, const gpu::QuadNode& node,
                              uint32_t rule, int samples, const gpu::ClassifyPush& params) {
  return mirror::classifyGeneralNode(patches.patches[node.patchIndex], patches.points.data(),
                                     node, rule, samples, params);
}

template <class Patches>
void classifyRange(const Patches& patches, const std::vector<gpu::QuadNode>& nodes,
                   uint32_t rule, int samples, const gpu::ClassifyPush& params,
                   std::vector<gpu::NodeDecision>& decisions, size_t begin, size_t end) {
  for (size_t i = begin; i < end; ++i)
    decisions[i] = classifyOne(patches, nodes[i], rule, samples, params);
}

class MirrorClassifier final : public NodeClassifier {
  static constexpr size_t kChunkNodes = 64;

 public:
  explicit MirrorClassifier(unsigned threads) : threads_(std::max(1u, threads)) {}

  std::string name() const override {
    return threads_ == 1 ? "cpu-fp32" : "cpu-fp32-x" + std::to_string(threads_);
  }

  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) override {
    if (patches.isBicubic())
      run(patches.bicubic(), nodes, options, decisions, stats);
    else
      run(patches.general(), nodes, options, decisions, stats);
  }

 private:
  template <class Patches>
  void run(const Patches& patches, const std::vector<gpu::QuadNode>& nodes,
           const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
           LevelStats& stats) {
    const Stopwatch stopwatch;
    decisions.resize(nodes.size());
    gpu::ClassifyPush params = classifyParams(options, uint32_t(nodes.size()));
    uint32_t rule = ruleConstant(options.rule);
    // At least 256 nodes a thread: fewer are not worth a thread start. Chunks taken in turn:
    // a node that splits costs several that do not, and they cluster.
    const auto workers = unsigned(std::clamp<size_t>((nodes.size() + 255) / 256, 1, threads_));
    parallelForChunks(nodes.size(), kChunkNodes, workers, [&](size_t begin, size_t end) {
      classifyRange(patches, nodes, rule, options.samples, params, decisions, begin, end);
    });
    stats.classifyMs += stopwatch.elapsedMs();
  }

  unsigned threads_;
};

}  // namespace

std::unique_ptr<NodeClassifier> makeMirrorClassifier() {
  return std::make_unique<MirrorClassifier>(1);
}

std::unique_ptr<NodeClassifier> makeParallelMirrorClassifier() {
  return std::make_unique<MirrorClassifier>(resolveThreadCount(0));
}

}  // namespace tessera
