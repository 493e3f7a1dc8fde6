// A list of 32-bit ids whose first two live inline: the triangles of one mesh edge (two where
// the mesh is manifold) or the vertices under one weld key (nearly always one). The trimmed
// mesher keeps one per edge in hashed maps; a std::vector there cost a heap block per edge,
// and the allocator a fifth of the mesher's time (perf, bench_cad --tessera-only).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tessera {

class SmallIdList {
 public:
  SmallIdList() = default;
  SmallIdList(uint32_t a, uint32_t b) : count_(2), first_{a, b} {}

  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  uint32_t operator[](size_t k) const { return k < 2 ? first_[k] : rest_[k - 2]; }
  uint32_t& operator[](size_t k) { return k < 2 ? first_[k] : rest_[k - 2]; }
  void push_back(uint32_t id) {
    if (count_ < 2) first_[count_] = id;
    else rest_.push_back(id);
    ++count_;
  }
  // Every entry equal to `from` becomes `to`, in place.
  void replace(uint32_t from, uint32_t to) {
    for (size_t k = 0; k < count_; ++k)
      if ((*this)[k] == from) (*this)[k] = to;
  }

 private:
  uint32_t count_ = 0;
  std::array<uint32_t, 2> first_{};
  std::vector<uint32_t> rest_;  // the third entry on (empty: no allocation)
};

}  // namespace tessera
