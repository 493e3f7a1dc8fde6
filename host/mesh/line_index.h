// The leaf corners on each line u = const or v = const of a patch, for the triangulator
// (line_points.cpp fills it, leaf_walk.cpp reads it): a line's points are the vertices a
// leaf edge along it passes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <unordered_map>
#include <vector>

#include "common/hash_map.h"
#include "mesh/near_points.h"

namespace tessera {

struct LineKeyHash {
  size_t operator()(uint64_t key) const { return size_t(key); }
};

// Folds `point` into `last` when both have the same t bit for bit, keeping the shorter spacing
// (as nearPairs folds equal t after sorting); false: they differ, nothing changed. A leaf's
// corner is on its line once more for the next leaf along it, most often right after.
inline bool foldedInto(LinePoint& last, const LinePoint& point) {
  uint32_t a, b;
  std::memcpy(&a, &last.t, sizeof a);
  std::memcpy(&b, &point.t, sizeof b);
  if (a != b) return false;
  last.spacing = std::min(last.spacing, point.spacing);
  return true;
}

// A line's points: a range of LineIndex's one array (Point: LinePoint or const LinePoint).
template <typename Point>
struct PointRange {
  Point* first = nullptr;
  Point* last = nullptr;
  Point* begin() const { return first; }
  Point* end() const { return last; }
  size_t size() const { return size_t(last - first); }
  bool empty() const { return first == last; }
  Point& operator[](size_t k) const { return first[k]; }
};
using LinePointRange = PointRange<LinePoint>;

// Per line (u = const or v = const inside a patch, keyed by lineKey, detail/vertex_key.h), the
// leaf corners on it, sorted; once near points are merged (near_points.h), only those that
// are vertices of their own. Lines are numbered in the order they were first met. Their points
// share one array, each line a range sized before it is filled (allocatePoints), so that the
// tens of thousands of lines of a fine mesh cost no allocation each.
class LineIndex {
 public:
  explicit LineIndex(size_t expected) { numbers_.reserve(expected); }

  // The line's number, the line added if new.
  uint32_t number(uint64_t key) {
    const auto [number, added] = numbers_.try_emplace(key, uint32_t(keys_.size()));
    if (added) keys_.push_back(key);
    return number->second;
  }

  // The line's number, or UINT32_MAX when it has none.
  uint32_t find(uint64_t key) const {
    const auto it = numbers_.find(key);
    return it != numbers_.end() ? it->second : UINT32_MAX;
  }

  // Room for pointCounts[line] points on each line, all empty; lines numbered later have none.
  void allocatePoints(const std::vector<uint32_t>& pointCounts) {
    offsets_.assign(keys_.size() + 1, 0);
    for (size_t line = 0; line < pointCounts.size() && line < keys_.size(); ++line)
      offsets_[line + 1] = pointCounts[line];
    for (size_t line = 0; line < keys_.size(); ++line) offsets_[line + 1] += offsets_[line];
    ends_.assign(offsets_.begin(), offsets_.end() - 1);
    // Not value-initialized: every point is written (add) before it is read, and zeroing
    // the room first took ~2 M instructions a direction at 10⁻³.
    points_.reset(new LinePoint[offsets_.back()]);
  }
  // Appends a point to the line, within the room allocatePoints gave it.
  void add(size_t line, const LinePoint& point) { points_[ends_[line]++] = point; }
  // The same, folded into the line's last point (foldedInto): half the points to sort.
  void addOrFold(size_t line, const LinePoint& point) {
    if (ends_[line] > offsets_[line] && foldedInto(points_[ends_[line] - 1], point)) return;
    add(line, point);
  }
  // Keeps the line's first `count` points.
  void shrink(size_t line, size_t count) { ends_[line] = offsets_[line] + count; }

  // Frees the keys and the key → number table once no line is looked up or named by its key
  // again (the leaf walk finds its lines by number): a huge mesh's are hundreds of MiB. Only
  // the points stay: find() finds nothing then, and size() and key() answer for no line.
  void releaseLookup() {
    decltype(numbers_)().swap(numbers_);
    std::vector<uint64_t>().swap(keys_);
  }

  size_t size() const { return keys_.size(); }
  uint64_t key(size_t line) const { return keys_[line]; }
  LinePointRange points(size_t line) {
    if (line >= ends_.size()) return {};
    return {points_.get() + offsets_[line], points_.get() + ends_[line]};
  }
  PointRange<const LinePoint> points(size_t line) const {
    if (line >= ends_.size()) return {};
    return {points_.get() + offsets_[line], points_.get() + ends_[line]};
  }

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
  std::unique_ptr<LinePoint[]> points_;       // every line's points, line after line
  std::vector<size_t> offsets_, ends_;        // per line: its first point, one past its last
};

}  // namespace tessera
