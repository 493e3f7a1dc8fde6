// `tessera reduce`: the control-point reduction paper's table (docs/reduction.md) on the
// synthetic shoe-last surface — curvature-chosen against random knots per threshold — and the
// before/after surfaces as JSON scenes for `tessera render`.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_support.h"
#include "cli/commands.h"
#include "reduction/curve_product.h"
#include "io/bspline_scene_writer.h"
#include "experiments/reduction_table.h"
#include "experiments/synthetic_surfaces.h"

namespace tessera::cli {
namespace {

struct ReduceArgs {
  int countU = kLargeSurfaceCount;
  int countV = kLargeSurfaceCount;
  std::vector<double> thresholds = {0.01, 0.05};
  std::vector<std::string> choices = {"curvature", "curv-fixed", "random"};
  std::string aggregate = "max";
  std::string measure = "mean";
  std::string backend = "cpu";
  std::string sceneDir;
  bool quiet = false;
};

// One line on stderr, redrawn in place: only on a terminal (logs and CI stay clean).
std::function<void(const ReductionProgress&)> progressBar(const std::string& label) {
  return [label](const ReductionProgress& p) {
    if (p.tried % 16 != 0 && p.tried != p.removable) return;
    const int width = 30;
    const int filled = p.removable == 0 ? width : width * p.tried / p.removable;
    std::fprintf(stderr, "\r%s pass %d/2 (%s) [%s%s] %d/%d knots tried, %d removed, error %.4g  ",
                 label.c_str(), p.pass + 1, directionName(p.direction),
                 std::string(static_cast<size_t>(filled), '#').c_str(),
                 std::string(static_cast<size_t>(width - filled), '.').c_str(), p.tried,
                 p.removable, p.removed, p.error);
    std::fflush(stderr);
  };
}

int runReduce(const ReduceArgs& a) {
  ChosenBackend chosen = chooseBackend(a.backend, "");
  std::unique_ptr<CurveProduct> product;
  if (chosen.context) product = makeVulkanCurveProduct(*chosen.context);
  const BSplineSurface surface = syntheticLast(a.countU, a.countV);
  std::printf("Synthetic last %d x %d = %zu control points (millimetres); row product: %s.\n"
              "Error: mean and max |d| of the control-net difference (the threshold bounds the "
              "%s); max |d| bounds the surface deviation.\n\n",
              a.countU, a.countV, surface.cp.size(),
              product ? product->name().c_str() : "cpu (double)", a.measure.c_str());
  std::vector<KnotChoice> choices;
  for (const std::string& name : a.choices) {
    for (KnotChoice c : {KnotChoice::Curvature, KnotChoice::CurvatureFixed,
                         KnotChoice::CurvatureSweeps, KnotChoice::Random}) {
      if (name == knotChoiceName(c)) choices.push_back(c);
    }
  }
  const bool bar = !a.quiet && isatty(fileno(stderr));
  std::vector<ReductionTableRow> rows;
  for (double threshold : a.thresholds) {
    ReductionOptions o;
    o.aggregate = a.aggregate == "mean" ? CurvatureAggregate::Mean : CurvatureAggregate::Max;
    o.measure = a.measure == "max" ? ErrorMeasure::Max : ErrorMeasure::Mean;
    if (bar) o.progress = progressBar("reducing at " + std::to_string(threshold).substr(0, 6));
    for (auto& row : reductionTable(surface, {threshold}, o, product.get(), choices)) rows.push_back(std::move(row));
    if (bar) std::fprintf(stderr, "\r\033[K");
  }
  std::printf("%s", formatReductionTable(rows, waviness(surface)).c_str());
  if (!a.sceneDir.empty()) {
    writeBSplineScene(a.sceneDir + "/reduce_before.json", {{"synthetic last", &surface}});
    for (const ReductionTableRow& r : rows) {
      char name[96];
      std::snprintf(name, sizeof name, "reduce_%s_%g.json", knotChoiceName(r.choice),
                    r.threshold);
      writeBSplineScene(a.sceneDir + "/" + name, {{name, &r.result.surface}});
    }
    std::printf("wrote %s/reduce_before.json and %zu reduced scenes\n", a.sceneDir.c_str(),
                rows.size());
  }
  return kExitOk;
}

}  // namespace

void addReduceCommand(CLI::App& app, int& exitCode) {
  static ReduceArgs args;
  CLI::App* cmd = app.add_subcommand(
      "reduce",
      "Control-point reduction by inverse Oslo (Hayashimoto et al.): curvature-chosen vs random "
      "knots per threshold on the synthetic last, with compression ratio, waviness, errors and "
      "the limit that stopped each pass");
  cmd->add_option("--count-u", args.countU, "control points around the cross-section")
      ->check(CLI::Range(4, 4000))->capture_default_str();
  cmd->add_option("--count-v", args.countV, "control points heel to toe")
      ->check(CLI::Range(4, 4000))->capture_default_str();
  cmd->add_option("--thresholds", args.thresholds, "thresholds in mm (on the --measure error)")
      ->delimiter(',')->check(CLI::NonNegativeNumber);
  cmd->add_option("--choices", args.choices,
                  "knot choices: curvature (re-ranked by bending x span^2), curv-fixed (fixed "
                  "curvature order), curv-sweeps (fixed order, spread in sweeps), random")
      ->delimiter(',')
      ->check(CLI::IsMember({"curvature", "curv-fixed", "curv-sweeps", "random"}))
      ->capture_default_str();
  cmd->add_option("--aggregate", args.aggregate,
                  "curvature over the rows of a direction: max (default) or mean")
      ->check(CLI::IsMember({"max", "mean"}))->capture_default_str();
  cmd->add_option("--measure", args.measure,
                  "error the threshold bounds: mean (the paper) or max of the control-net difference")
      ->check(CLI::IsMember({"mean", "max"}))->capture_default_str();
  cmd->add_option("--backend", args.backend, "row product on vulkan, cpu or auto")
      ->capture_default_str();
  cmd->add_option("--scene-dir", args.sceneDir,
                  "write reduce_before.json and one reduce_<choice>_<threshold>.json per row "
                  "(JSON scenes for tessera render)");
  cmd->add_flag("--quiet", args.quiet, "no progress bar");
  cmd->callback([&exitCode] {
    std::vector<std::string> outputs;
    if (!args.sceneDir.empty()) outputs.push_back(args.sceneDir);
    exitCode = runReportingErrors([] { return runReduce(args); }, outputs);
  });
}

}  // namespace tessera::cli
