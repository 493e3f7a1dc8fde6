#include "trim/trim_frontier.h"

#include <stdexcept>
#include <string>

#include "common/stopwatch.h"

namespace tessera {

TrimmingClassifier::TrimmingClassifier(NodeClassifier& inner, const TrimSet& set,
                                       TrimClassifier& trim)
    : RevisingClassifier(inner, set.pieces.size()), set_(set), trim_(trim) {
  const Stopwatch stopwatch;
  trim_.beginSet(set_);
  trimMs_ += stopwatch.elapsedMs();
}

std::string TrimmingClassifier::name() const {
  return inner().name() + " (trimmed by " + trim_.name() + ")";
}

void TrimmingClassifier::beforeInner(const std::vector<gpu::QuadNode>& nodes,
                                     const QuadtreeOptions&) {
  const Stopwatch stopwatch;
  queries_.resize(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i)
    queries_[i] = {nodes[i].rect, uint32_t(groupFirst() + nodes[i].patchIndex), 0u, 0u, 0u};
  trim_.startClassify(set_, queries_);
  startMs_ = stopwatch.elapsedMs();
}

void TrimmingClassifier::revise(const std::vector<gpu::QuadNode>& nodes, const QuadtreeOptions&,
                                std::vector<gpu::NodeDecision>& decisions, LevelStats& stats) {
  const Stopwatch stopwatch;
  const std::vector<uint32_t> where = trim_.finishClassify();
  if (where.size() != nodes.size())
    throw std::logic_error(name() + ": " + std::to_string(where.size()) + " trim classes for " +
                           std::to_string(nodes.size()) + " nodes");
  for (size_t i = 0; i < nodes.size(); ++i)
    if (where[i] == gpu::kTrimOutside) {
      decisions[i].cause = gpu::kCauseTrimmedAway;
      ++trimmedAway_;
    }
  const double ms = startMs_ + stopwatch.elapsedMs();
  trimMs_ += ms;
  stats.classifyMs += ms;
}

QuadtreeResult buildTrimmedQuadtree(const PatchSet& patches, const QuadtreeOptions& options,
                                    NodeClassifier& classifier, const TrimSet& set,
                                    TrimClassifier& trim) {
  if (set.pieces.size() != patches.size())
    throw std::invalid_argument("trimmed quad-tree: " + std::to_string(patches.size()) +
                                " patches but " + std::to_string(set.pieces.size()) +
                                " trim pieces");
  TrimmingClassifier trimming(classifier, set, trim);
  return buildQuadtree(patches, options, trimming);
}

}  // namespace tessera
