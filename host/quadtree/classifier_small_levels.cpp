// A device classifier that leaves small batches to the host (withSmallLevelsOnHost): a batch
// of fewer than hostLevelNodes nodes goes to the fp32 mirror, the same shader text compiled as
// C++, so the decisions are the device's where it rounds as the mirror does (lavapipe) and
// elsewhere differ by fp32 rounding only, each side's bound carrying the same guards
// (docs/quadtree.md, "Small levels on the host"). A submission costs lavapipe a fixed
// 0.03-0.09 ms, more than the mirror takes for a batch this small (kHostLevelNodes).
#include <memory>
#include <utility>

#include "quadtree/quadtree.h"

namespace tessera {
namespace {

// Rule T: the mirror takes ~0.6 µs a leaf, ~2 µs a node that splits, so below kHostLevelNodes
// it beats the device's fixed cost. Rules C and D search each node for the κ maximum, ~3 and
// ~25 µs a node on the host, so lavapipe's fixed 0.03-0.09 ms pays for itself from ~10-30 and
// ~2-4 nodes. Rule B's nodes cost the host ~0.5 µs and would gain as T's do, but it is left as
// the paper's experiment has it, every level on the device (bench_quadtree and the CLI's Vulkan
// summary count those submissions). Tea set, warm, per level: bench/HISTORY.md, "Small levels
// on the host".
bool hostDecides(SplitRule rule) { return rule == SplitRule::Tolerance; }

class SmallLevelsOnHost final : public NodeClassifier {
 public:
  SmallLevelsOnHost(std::unique_ptr<NodeClassifier> device, size_t hostLevelNodes)
      : device_(std::move(device)),
        host_(makeParallelMirrorClassifier()),
        hostLevelNodes_(hostLevelNodes) {}

  std::string name() const override { return device_->name(); }

  // The device gets the patches only when a batch first needs it: a tree whose every level is
  // small uploads nothing and builds no pipeline.
  void beginTree(const PatchSet& patches) override {
    host_->beginTree(patches);
    deviceHasTree_ = false;
  }

  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) override {
    if (nodes.size() < hostLevelNodes_ && hostDecides(options.rule)) {
      host_->classify(patches, nodes, options, decisions, stats);
      stats.hostNodes += nodes.size();
      return;
    }
    if (!deviceHasTree_) {
      device_->beginTree(patches);
      deviceHasTree_ = true;
    }
    device_->classify(patches, nodes, options, decisions, stats);
  }

  size_t maxBatchNodes() const override { return device_->maxBatchNodes(); }
  size_t maxPatchBufferBytes() const override { return device_->maxPatchBufferBytes(); }

 private:
  std::unique_ptr<NodeClassifier> device_;
  std::unique_ptr<NodeClassifier> host_;
  size_t hostLevelNodes_;
  bool deviceHasTree_ = false;
};

}  // namespace

std::unique_ptr<NodeClassifier> withSmallLevelsOnHost(std::unique_ptr<NodeClassifier> device,
                                                      size_t hostLevelNodes) {
  return std::make_unique<SmallLevelsOnHost>(std::move(device), hostLevelNodes);
}

}  // namespace tessera
