// Trimmed quad-trees: a NodeClassifier decorator that, after each level's decisions (rules
// B–D or T), classifies the level's nodes against their faces' trim loops and ends every node
// outside as a leaf with cause gpu::kCauseTrimmedAway, never split further; inside and
// crossing nodes keep their decisions. A separate pass: without it the tree is exactly the
// untrimmed one. Patch k of the tree is piece k of the TrimSet.
#pragma once
#include <memory>

#include "quadtree/quadtree.h"
#include "quadtree/revising_classifier.h"
#include "trim/trim_classifier.h"

namespace tessera {

class TrimmingClassifier final : public RevisingClassifier {
 public:
  // `inner` decides the nodes, `trim` classifies them against `set`; all three must outlive it.
  TrimmingClassifier(NodeClassifier& inner, const TrimSet& set, TrimClassifier& trim);

  std::string name() const override;

  size_t trimmedAway() const { return trimmedAway_; }  // nodes ended as kCauseTrimmedAway
  double trimMs() const { return trimMs_; }             // time in the trim classifier

 private:
  // The trim classification starts before the inner classifier's (its queries are the nodes
  // alone) and is read in revise(): on Vulkan both dispatches then cost one wait.
  void beforeInner(const std::vector<gpu::QuadNode>& nodes,
                   const QuadtreeOptions& options) override;
  void revise(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions& options,
              std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) override;

  const TrimSet& set_;
  TrimClassifier& trim_;
  size_t trimmedAway_ = 0;
  double trimMs_ = 0;
  double startMs_ = 0;  // the current batch's beforeInner
  std::vector<gpu::TrimQuery> queries_;
};

// buildQuadtree with the trimming pass. Throws std::invalid_argument when the set's piece
// count is not the patch count.
QuadtreeResult buildTrimmedQuadtree(const PatchSet& patches, const QuadtreeOptions& options,
                                    NodeClassifier& classifier, const TrimSet& set,
                                    TrimClassifier& trim);

}  // namespace tessera
