#include "quadtree/node_split.h"

#include <stdexcept>
#include <string>

namespace tessera {

void throwBadGridCounts(uint32_t pad) {
  const uint32_t u = pad & 0xFFu, v = pad >> 8;
  throw std::logic_error("classifier returned a split into " + std::to_string(u) + " x " +
                         std::to_string(v) + " children (pad " + std::to_string(pad) + ")");
}

float equalSplitLine(float lo, float hi, uint32_t i, uint32_t count) {
  if (i == 0) return lo;
  if (i == count) return hi;
  return lo + (hi - lo) * (float(i) / float(count));
}

namespace {

// The count + 1 lines of one direction into `lines`; false unless strictly increasing.
bool splitLines(float lo, float hi, uint32_t count, bool equal, float point, float* lines) {
  for (uint32_t i = 0; i <= count; ++i)
    lines[i] = equal ? equalSplitLine(lo, hi, i, count) : (i == 0 ? lo : i == count ? hi : point);
  for (uint32_t i = 0; i < count; ++i)
    if (!(lines[i] < lines[i + 1])) return false;
  return true;
}

}  // namespace

bool appendChildren(const gpu::QuadNode& n, const gpu::NodeDecision& d, SplitCounts counts,
                    std::vector<gpu::QuadNode>& out) {
  // Two-way splits (rules B–D, rule T's fallback) cut at the classifier's split point; rule
  // T's grid at equal parts (its two-way midpoint lo + (hi − lo)·0.5 is the same line).
  const bool equal = d.cause == gpu::kCauseSplitGrid;
  float u[gpu::kToleranceSplitCapMax + 1], v[gpu::kToleranceSplitCapMax + 1];
  if (!splitLines(n.rect.x, n.rect.z, counts.u, equal, d.split.x, u) ||
      !splitLines(n.rect.y, n.rect.w, counts.v, equal, d.split.y, v))
    return false;
  for (uint32_t j = 0; j < counts.v; ++j)
    for (uint32_t i = 0; i < counts.u; ++i)
      out.push_back({gpu::vec4(u[i], v[j], u[i + 1], v[j + 1]), n.patchIndex, n.level + 1, 0, 0});
  return true;
}

}  // namespace tessera
