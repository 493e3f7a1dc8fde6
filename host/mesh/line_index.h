// The leaf corners on each line u = const or v = const of a patch, for the triangulator
// (line_points.cpp fills it, leaf_walk.cpp reads it): a line's points are the vertices a
// leaf edge along it passes.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/hash_map.h"
#include "mesh/near_points.h"

namespace tessera {

struct LineKeyHash {
  size_t operator()(uint64_t key) const { return size_t(key); }
};

// Per line (u = const or v = const inside a patch, keyed by lineKey, detail/vertex_key.h), the
// leaf corners on it, sorted; once near points are merged (near_points.h), only those that
// are vertices of their own. Lines are numbered in the order they were first met.
class LineIndex {
 public:
  explicit LineIndex(size_t expected) { numbers_.reserve(expected); }

  // The line's number, the line added if new.
  uint32_t number(uint64_t key) {
    const auto [number, added] = numbers_.try_emplace(key, uint32_t(keys_.size()));
    if (added) {
      keys_.push_back(key);
      points_.emplace_back();
    }
    return number->second;
  }

  const std::vector<LinePoint>* find(uint64_t key) const {
    const auto number = numbers_.find(key);
    return number == numbers_.end() ? nullptr : &points_[number->second];
  }

  size_t size() const { return keys_.size(); }
  uint64_t key(size_t line) const { return keys_[line]; }
  std::vector<LinePoint>& points(size_t line) { return points_[line]; }

  // The lines in the order a std::unordered_map<uint64_t, …> reserved for `reserved` entries
  // and filled in this index's order walks them. Merging near points hands out position ids
  // in the order the lines are walked (SeamVertices::positionId), and a merge of two patch
  // corners keeps the one with the smaller id: walked in this order, the merges stay those
  // of the node-based index this class replaced, so meshes keep their bytes. Only asked for
  // when a line has something to merge.
  std::vector<uint32_t> unorderedMapOrder(size_t reserved) const {
    std::unordered_map<uint64_t, uint32_t> order;
    order.reserve(reserved);
    for (uint32_t line = 0; line < keys_.size(); ++line) order.emplace(keys_[line], line);
    std::vector<uint32_t> lines;
    lines.reserve(keys_.size());
    for (const auto& entry : order) lines.push_back(entry.second);
    return lines;
  }

 private:
  HashMap<uint64_t, uint32_t, LineKeyHash> numbers_;
  std::vector<uint64_t> keys_;
  std::vector<std::vector<LinePoint>> points_;
};

}  // namespace tessera
