// The modes issue 18 asks the tea set to be watertight in: rule A on grids 4×4, 8×8, 16×16 and
// 3×5; rules B, C and D at thresholds 0.3, 0.1 and 0.02; rule T at δ = 1%, 0.1% and 0.01% of the
// model's size. Shared by the mirror's defect count and the Vulkan equality test.
#pragma once
#include <string>
#include <vector>

#include "geometry/patch.h"
#include "quadtree/quadtree.h"
#include "quadtree/tolerance.h"

namespace tessera::test {

struct TeaSetSetting {
  std::string name;
  QuadtreeOptions options;
};

inline std::vector<TeaSetSetting> teaSetSettings(const std::vector<BezierPatch>& patches) {
  std::vector<TeaSetSetting> settings;
  for (auto [n, m] : {std::pair{4, 4}, std::pair{8, 8}, std::pair{16, 16}, std::pair{3, 5}}) {
    QuadtreeOptions o;
    o.rule = SplitRule::UniformGrid;
    o.gridU = n;
    o.gridV = m;
    settings.push_back({"A " + std::to_string(n) + "x" + std::to_string(m), o});
  }
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax})
    for (const char* threshold : {"0.3", "0.1", "0.02"}) {
      QuadtreeOptions o;
      o.rule = rule;
      o.linearity = o.flatness = std::stof(threshold);
      settings.push_back({std::string(1, splitRuleLetter(rule)) + " " + threshold, o});
    }
  for (const char* given : {"1%", "0.1%", "0.01%"})
    settings.push_back({std::string("T ") + given,
                        toleranceOptions(resolveTolerance(parseTolerance(given), patches))});
  return settings;
}

}  // namespace tessera::test
