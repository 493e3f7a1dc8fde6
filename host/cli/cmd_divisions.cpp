// tessera divisions: paper 002's comparison table of division counts for rational surfaces
// with zero weights (host/experiments/division_table.h, docs/rational_division.md).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cli/cli_support.h"
#include "cli/commands.h"
#include "experiments/division_table.h"

namespace tessera::cli {

void addDivisionsCommand(CLI::App& app, int& exitCode) {
  static DivisionTableOptions options;
  static bool perView = false;
  CLI::App* cmd = app.add_subcommand(
      "divisions",
      "Paper 002's table: average division number N_u*N_v of the split method, zero weights "
      "replaced by 0.001 and 0.01, the subdivided, cellwise and directional bounds and the true "
      "value, with over-division ratios, on quarter cylinders and torus patches seen from a "
      "control point's plane");
  cmd->add_option("--tolerance", options.tolerance, "TOL in pixels")->capture_default_str();
  cmd->add_option("--viewport", options.viewport, "square viewport side in pixels")
      ->capture_default_str();
  cmd->add_flag("--full", options.full, "more surfaces and viewpoints (slower)");
  cmd->add_flag("--per-view", perView, "also print one row per surface and viewpoint");
  cmd->callback([&exitCode] {
    exitCode = runReportingErrors(
        [] {
          checkCommandLine([] {
            if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
              throw std::invalid_argument("--tolerance must be a finite number > 0");
            if (options.viewport < 16 || options.viewport > 16384)
              throw std::invalid_argument("--viewport must be 16..16384 pixels");
          });
          const DivisionTable table = divisionComparison(options);
          std::printf("%s", formatDivisionTable(table, perView).c_str());
          return int(kExitOk);
        },
        {});
  });
}

}  // namespace tessera::cli
