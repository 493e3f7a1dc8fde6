// A NodeClassifier that lets another one decide each batch of nodes and then revises some of
// the decisions: the screen-space view test (mesh/screen_tolerance.cpp), the trim pass
// (trim/trim_frontier.h) and the distance bound on surfaces of revolution
// (trim/revolution_bound.h). buildQuadtree may build one tree over several patch groups
// (a device's buffer limits), calling beginTree once per group, in order: patch k of the
// current group is patch groupFirst() + k of the whole set the decorator was made for.
#pragma once
#include <stdexcept>
#include <string>

#include "quadtree/quadtree.h"

namespace tessera {

class RevisingClassifier : public NodeClassifier {
 public:
  // `patchCount`: the patches the revision knows (over all groups); `inner` must outlive it.
  RevisingClassifier(NodeClassifier& inner, size_t patchCount)
      : inner_(inner), patchCount_(patchCount) {}

  void beginTree(const PatchSet& patches) override {
    groupFirst_ += groupSize_;
    groupSize_ = patches.size();
    if (groupFirst_ + groupSize_ > patchCount_)
      throw std::logic_error(name() + ": more patches than the " + std::to_string(patchCount_) +
                             " it was made for");
    inner_.beginTree(patches);
  }
  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) final {
    inner_.classify(patches, nodes, options, decisions, stats);
    revise(nodes, options, decisions, stats);
  }
  size_t maxBatchNodes() const override { return inner_.maxBatchNodes(); }
  size_t maxPatchBufferBytes() const override { return inner_.maxPatchBufferBytes(); }

 protected:
  // Rewrites decisions[i] where the revision applies to nodes[i] (its patch: groupFirst() +
  // nodes[i].patchIndex).
  virtual void revise(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& options,
                      std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) = 0;
  size_t groupFirst() const { return groupFirst_; }
  const NodeClassifier& inner() const { return inner_; }

 private:
  NodeClassifier& inner_;
  size_t patchCount_;
  size_t groupFirst_ = 0, groupSize_ = 0;
};

}  // namespace tessera
