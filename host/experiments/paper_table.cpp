#include "experiments/paper_table.h"

#include <cstdio>
#include <map>

#include "mesh/deviation.h"

namespace tessera {
namespace {

struct UniformResult {
  size_t triangles;
  double deviation;
};

UniformResult uniformAt(const std::vector<BezierPatch>& patches, int n, Backend& backend,
                        std::map<int, UniformResult>& cache) {
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  QuadtreeOptions options;
  options.rule = SplitRule::UniformGrid;
  options.gridU = options.gridV = n;
  Tessellation t = tessellate(patches, options, backend);
  UniformResult r{t.stats.triangles, measureDeviation(t, patches).maxDeviation};
  cache[n] = r;
  return r;
}

// The smallest N with deviation ≤ target: doubling, then bisection (the deviation of a
// uniform grid falls roughly as 1/N²; the search only assumes it falls).
int smallestUniformN(const std::vector<BezierPatch>& patches, double target, Backend& backend,
                     std::map<int, UniformResult>& cache) {
  const int kMaxN = 1024;
  int hi = 1;
  while (hi < kMaxN && uniformAt(patches, hi, backend, cache).deviation > target) hi *= 2;
  if (hi == 1) return 1;
  int lo = hi / 2;  // deviation(lo) > target
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (uniformAt(patches, mid, backend, cache).deviation > target)
      lo = mid;
    else
      hi = mid;
  }
  return hi;
}

}  // namespace

std::vector<PaperTableRow> paperTable(const std::vector<BezierPatch>& patches,
                                      const std::vector<float>& thresholds, Backend& backend) {
  std::vector<PaperTableRow> rows;
  std::map<int, UniformResult> uniformCache;
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax})
    for (float threshold : thresholds) {
      QuadtreeOptions options;
      options.rule = rule;
      options.linearity = options.flatness = threshold;
      Tessellation t = tessellate(patches, options, backend);
      PaperTableRow row;
      row.method = splitRuleLetter(rule);
      row.threshold = threshold;
      row.depth = t.stats.depth;
      row.leaves = t.stats.leaves;
      row.triangles = t.stats.triangles;
      row.maxDeviation = measureDeviation(t, patches).maxDeviation;
      row.uniformN = smallestUniformN(patches, row.maxDeviation, backend, uniformCache);
      UniformResult u = uniformAt(patches, row.uniformN, backend, uniformCache);
      row.uniformTriangles = u.triangles;
      row.uniformDeviation = u.deviation;
      rows.push_back(row);
    }
  return rows;
}

std::string formatPaperTable(const std::string& title, const std::vector<PaperTableRow>& rows) {
  std::string out = "### " + title + "\n\n";
  out +=
      "| method | threshold | depth | leaves | triangles | max deviation | A: N | A: triangles "
      "(same deviation) | triangles / A's |\n|---|---|---|---|---|---|---|---|---|\n";
  char line[512];
  for (const PaperTableRow& r : rows) {
    std::snprintf(line, sizeof line, "| %c | %.2f | %u | %zu | %zu | %.3g | %d | %zu | %.2f |\n",
                  r.method, r.threshold, r.depth, r.leaves, r.triangles, r.maxDeviation,
                  r.uniformN, r.uniformTriangles,
                  r.uniformTriangles ? double(r.triangles) / double(r.uniformTriangles) : 0.0);
    out += line;
  }
  return out;
}

}  // namespace tessera
