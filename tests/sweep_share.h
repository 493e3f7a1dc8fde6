// The share of a statistical sweep's samples a run takes: 1 in the Release suite, less under
// the sanitizers (scripts/sanitize.sh sets TESSERA_TEST_SWEEP_SHARE=0.25). The sanitizers look
// for memory errors and undefined behaviour, which a share of the same samples reaches; the
// statistics (coverage, ratios, "never above δ") are asserted in full by the Release run.
#pragma once
#include <cstdlib>
#include <vector>

namespace tessera::test {

inline double sweepShare() {
  const char* text = std::getenv("TESSERA_TEST_SWEEP_SHARE");
  const double share = text ? std::atof(text) : 1.0;
  return share > 0.0 && share <= 1.0 ? share : 1.0;
}

// Every k-th item, k = round(1 / share): spread over the whole sequence, not its head.
template <typename T>
std::vector<T> sweptSubset(const std::vector<T>& items) {
  const double share = sweepShare();
  if (share == 1.0) return items;
  const size_t stride = static_cast<size_t>(1.0 / share + 0.5);
  std::vector<T> subset;
  for (size_t k = 0; k < items.size(); k += stride) subset.push_back(items[k]);
  return subset;
}

// sweptSubset, plus the last item where the stride passes it: for sweeps whose ends are the
// point (the largest scale, the farthest offset).
template <typename T>
std::vector<T> sweptSubsetWithEnds(const std::vector<T>& items) {
  std::vector<T> subset = sweptSubset(items);
  if (!items.empty() && subset.size() < items.size() && !(subset.back() == items.back()))
    subset.push_back(items.back());
  return subset;
}

}  // namespace tessera::test
