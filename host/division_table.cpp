#include "division_table.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "division_count.h"
#include "division_deviation.h"
#include "homogeneous_net.h"

namespace tessera {
namespace {

// Division numbers of the substitution alternative reach 10^10: no cap short of overflow.
constexpr int kUncapped = 1 << 30;

long long divisionsWith(const RationalBezierPatch& screen, DivisionMethod method,
                        double tolerance, Divisions* out = nullptr) {
  DivisionOptions o;
  o.method = method;
  o.tolerance = tolerance;
  o.maxPerDirection = kUncapped;
  const Divisions d = patchDivisions(screen, o);
  if (out) *out = d;
  return d.divisionNumber();
}

}  // namespace

DivisionTable divisionComparison(const DivisionTableOptions& options) {
  DivisionTable table;
  table.tolerance = options.tolerance;
  table.viewport = options.viewport;
  const double tol = options.tolerance;
  for (const SampleView& view : zeroWeightViews(options.full, options.viewport, options.viewport)) {
    const RationalBezierPatch screen = screenSpacePatch(view.patch, view.camera);
    const HomogeneousNet net = toNet(screen);
    DivisionViewRow row;
    row.name = view.name;
    Divisions split, subdivided, cellwise, directional;
    row.split = divisionsWith(screen, DivisionMethod::Split, tol, &split);
    row.sub001 = divisionsWith(substituteZeroWeights(screen, 0.001), DivisionMethod::AbiEzzi, tol);
    row.sub01 = divisionsWith(substituteZeroWeights(screen, 0.01), DivisionMethod::AbiEzzi, tol);
    const auto t0 = std::chrono::steady_clock::now();
    row.subdivided = divisionsWith(screen, DivisionMethod::Subdivided, tol, &subdivided);
    const auto t1 = std::chrono::steady_clock::now();
    row.cellwise = divisionsWith(screen, DivisionMethod::CellWise, tol, &cellwise);
    const auto t2 = std::chrono::steady_clock::now();
    row.directional = divisionsWith(screen, DivisionMethod::Directional, tol, &directional);
    const auto t3 = std::chrono::steady_clock::now();
    table.subdividedSeconds += std::chrono::duration<double>(t1 - t0).count();
    table.cellwiseSeconds += std::chrono::duration<double>(t2 - t1).count();
    table.directionalSeconds += std::chrono::duration<double>(t3 - t2).count();
    row.splitDeviation = uniformGridDeviation(net, split.nu, split.nv);
    row.subdividedDeviation = uniformGridDeviation(net, subdivided.nu, subdivided.nv);
    row.cellwiseDeviation = uniformGridDeviation(net, cellwise.nu, cellwise.nv);
    row.directionalDeviation = uniformGridDeviation(net, directional.nu, directional.nv);
    // Search the true value below the smallest of the grids known to pass.
    const Divisions& known = std::min({split, subdivided, cellwise, directional},
                                      [](const Divisions& a, const Divisions& b) {
                                        return a.divisionNumber() < b.divisionNumber();
                                      });
    row.truth = smallestUniformGrid(net, tol, known.nu, known.nv, {8, 64}).divisionNumber();
    table.views.push_back(row);
  }
  const double n = double(std::max<size_t>(1, table.views.size()));
  for (const DivisionViewRow& r : table.views) {
    const long long values[7] = {r.split,    r.sub001,      r.sub01, r.subdivided,
                                 r.cellwise, r.directional, r.truth};
    for (int k = 0; k < 7; ++k) table.average[k] += double(values[k]) / n;
    table.worstSubdividedRatio =
        std::max(table.worstSubdividedRatio, double(r.subdivided) / double(r.truth));
    table.worstCellwiseRatio =
        std::max(table.worstCellwiseRatio, double(r.cellwise) / double(r.truth));
    table.worstDirectionalRatio =
        std::max(table.worstDirectionalRatio, double(r.directional) / double(r.truth));
    table.worstDeviation = std::max({table.worstDeviation, r.splitDeviation,
                                     r.subdividedDeviation, r.cellwiseDeviation,
                                     r.directionalDeviation});
  }
  return table;
}

std::string formatDivisionTable(const DivisionTable& table, bool perView) {
  std::string out;
  char line[512];
  auto perSecond = [&](double seconds) {
    return seconds > 0 ? double(table.views.size()) / seconds : 0.0;
  };
  std::snprintf(line, sizeof line,
                "Division numbers N_u*N_v at TOL %.3g px on a %dx%d viewport, averaged over %zu "
                "views with zero weights (paper 002, table 1)\n",
                table.tolerance, table.viewport, table.viewport, table.views.size());
  out += line;
  std::snprintf(line, sizeof line, "%-28s %18s %16s\n", "method", "division number",
                "over-division");
  out += line;
  const char* names[7] = {"split (this method)", "weight 0 -> 0.001", "weight 0 -> 0.01",
                          "subdivided (beyond)", "cellwise (beyond)", "directional (beyond)",
                          "true value"};
  const double truth = table.average[6];
  for (int k = 0; k < 7; ++k) {
    if (k == 6)
      std::snprintf(line, sizeof line, "%-28s %18.2f %16s\n", names[k], table.average[k], "-");
    else
      std::snprintf(line, sizeof line, "%-28s %18.2f %16.3f\n", names[k], table.average[k],
                    table.average[k] / truth);
    out += line;
  }
  std::snprintf(line, sizeof line,
                "largest measured deviation of split, subdivided, cellwise and directional "
                "grids: %.4f px (TOL %.3g); largest ratio to the true value of one view: "
                "subdivided %.3f, cellwise %.3f, directional %.3f; patches/s (one thread): "
                "subdivided %.1f, cellwise %.1f, directional %.1f\n",
                table.worstDeviation, table.tolerance, table.worstSubdividedRatio,
                table.worstCellwiseRatio, table.worstDirectionalRatio,
                perSecond(table.subdividedSeconds), perSecond(table.cellwiseSeconds),
                perSecond(table.directionalSeconds));
  out += line;
  if (perView) {
    std::snprintf(line, sizeof line, "\n%-64s %8s %14s %12s %8s %8s %8s %8s\n", "view",
                  "split", "0->0.001", "0->0.01", "subdiv", "cellwise", "direct", "true");
    out += line;
    for (const DivisionViewRow& r : table.views) {
      std::snprintf(line, sizeof line, "%-64s %8lld %14lld %12lld %8lld %8lld %8lld %8lld\n",
                    r.name.c_str(), r.split, r.sub001, r.sub01, r.subdivided, r.cellwise,
                    r.directional, r.truth);
      out += line;
    }
  }
  return out;
}

}  // namespace tessera
