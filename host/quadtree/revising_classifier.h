// A NodeClassifier that lets another one decide each batch of nodes and then revises some of
// the decisions: the screen-space view test (mesh/screen_tolerance.cpp), the trim pass
// (trim/trim_frontier.h) and the distance bound on surfaces of revolution
// (trim/revolution_bound.h). buildQuadtree may build one tree over several patch groups
// (a device's buffer limits), calling beginTree once per group, in order: patch k of the
// current group is patch groupFirst() + k of the whole set the decorator was made for.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

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
    // Nodes whose decision revise() rewrites whole are not sent to the inner classifier: its
    // decision for them would never be read. Every classifier decides a node from that node
    // and its patch alone (the batch only groups the work), so the others' decisions are
    // those of the whole batch.
    beforeInner(nodes, options);
    innerNodes_.clear();
    innerIndex_.clear();
    for (size_t i = 0; i < nodes.size(); ++i)
      if (!skipRewritten_ || !rewritesWhole(groupFirst_ + nodes[i].patchIndex, options)) {
        innerNodes_.push_back(nodes[i]);
        innerIndex_.push_back(i);
      }
    if (innerNodes_.size() == nodes.size()) {
      inner_.classify(patches, nodes, options, decisions, stats);
    } else {
      if (!innerNodes_.empty())
        inner_.classify(patches, innerNodes_, options, innerDecisions_, stats);
      decisions.assign(nodes.size(), gpu::NodeDecision{});
      for (size_t k = 0; k < innerIndex_.size(); ++k)
        decisions[innerIndex_[k]] = innerDecisions_[k];
    }
    revise(nodes, options, decisions, stats);
  }
  size_t maxBatchNodes() const override { return inner_.maxBatchNodes(); }
  // On (the default), nodes whose decision revise() rewrites whole skip the inner classifier;
  // off, every node goes to it as before that skip: the tests compare the two trees.
  void setSkipRewritten(bool skip) { skipRewritten_ = skip; }
  size_t maxPatchBufferBytes() const override { return inner_.maxPatchBufferBytes(); }

 protected:
  // Rewrites decisions[i] where the revision applies to nodes[i] (its patch: groupFirst() +
  // nodes[i].patchIndex).
  virtual void revise(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& options,
                      std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) = 0;
  // Called with each batch before the inner classifier sees it: a revision that does not read
  // the inner decisions may start its own work here, to overlap the inner classification.
  virtual void beforeInner(const std::vector<gpu::QuadNode>& /*nodes*/,
                           const QuadtreeOptions& /*options*/) {}
  // True where revise() assigns decisions[i] whole, reading nothing of it, for every node of
  // patch `patch` (over all groups) under `options`: the inner classifier skips those nodes.
  virtual bool rewritesWhole(size_t /*patch*/, const QuadtreeOptions& /*options*/) const {
    return false;
  }
  size_t groupFirst() const { return groupFirst_; }
  const NodeClassifier& inner() const { return inner_; }

 private:
  NodeClassifier& inner_;
  size_t patchCount_;
  size_t groupFirst_ = 0, groupSize_ = 0;
  bool skipRewritten_ = true;
  // The batch the inner classifier sees when some nodes skip it, and where each came from.
  std::vector<gpu::QuadNode> innerNodes_;
  std::vector<size_t> innerIndex_;
  std::vector<gpu::NodeDecision> innerDecisions_;
};

}  // namespace tessera
