#include "cli/tessellate_summary.h"

namespace tessera::cli {

void printRunLine(FILE* to, const std::string& input, const TessellationStats& s, SplitRule rule,
                  const std::string& thresholds, const std::string& backend,
                  const std::string& device) {
  std::fprintf(to, "%s: %zu patches, method %c, %s, backend %s%s%s\n", input.c_str(), s.patches,
               splitRuleLetter(rule), thresholds.c_str(), backend.c_str(),
               device.empty() ? "" : " on ", device.c_str());
}

void printCountsLine(FILE* to, const TessellationStats& s) {
  std::fprintf(to, "depth %u, leaves %zu, triangles %zu, vertices %zu (%zu zero-area dropped)\n",
               s.depth, s.leaves, s.triangles, s.vertices, s.degenerateTrianglesDropped);
}

void printProvenLine(FILE* to, double bound, double tolerance, size_t fannedLeaves) {
  std::fprintf(to, "proven within %.4g of the surface (largest leaf bound; tolerance %.4g)%s",
               bound, tolerance, bound <= tolerance ? "" : " — ABOVE the tolerance");
  // A leaf proven for one diagonal but fanned holds only its any-triangle bound.
  if (fannedLeaves > 0)
    std::fprintf(to, ", except %zu leaves fanned off their diagonal (warning diagonal-fan)",
                 fannedLeaves);
  std::fprintf(to, "\n");
}

void printLowerBoundLine(FILE* to, const TriangleLowerBound& bound, size_t triangles) {
  std::fprintf(to,
               "lower bound at δ %.3g: %.0f triangles (asymptotic, any interpolating mesh); "
               "this mesh has %.2fx that (%.1f ms)\n",
               bound.tolerance, bound.triangles,
               bound.triangles > 0.0 ? double(triangles) / bound.triangles : 0.0, bound.ms);
}

void printTimesLine(FILE* to, const TessellationStats& s) {
  std::fprintf(to, "time: tree %.1f ms, triangulation %.1f ms, vertices %.1f ms, total %.1f ms\n",
               s.treeMs, s.triangulateMs, s.evaluateMs, s.totalMs);
}

}  // namespace tessera::cli
