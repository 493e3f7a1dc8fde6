#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>

#include "cli/cli_support.h"
#include "cli/commands.h"
#include "io/surface_reader.h"
#include "experiments/paper_table.h"
#include "vk/context.h"

namespace tessera::cli {

void addPaperTableCommand(CLI::App& app, int& exitCode) {
  static std::vector<std::string> inputs;
  static std::vector<float> thresholds = {0.3f, 0.2f, 0.1f, 0.05f};
  static std::string backendName = "auto";
  CLI::App* cmd = app.add_subcommand(
      "paper-table",
      "The quad-tree paper's table: depth and leaves of B, C, D per threshold, with the "
      "measured maximum deviation and the uniform grid (A) that matches it");
  cmd->add_option("inputs", inputs, "surfaces (.grid point data or .bpt); default: data/grid_*.grid");
  cmd->add_option("--thresholds", thresholds, "linearity = flatness values")->delimiter(',');
  cmd->add_option("--backend", backendName, "vulkan, cpu or auto")->capture_default_str();
  cmd->callback([&exitCode] {
    if (inputs.empty())
      inputs = {"data/grid_hill.grid", "data/grid_ridge.grid", "data/grid_bumps.grid"};
    exitCode = runReportingErrors(
        [] {
          checkCommandLine([] {
            for (const float t : thresholds) {
              QuadtreeOptions q;
              q.linearity = q.flatness = t;
              validateQuadtreeOptions(q);
            }
          });
          ChosenBackend chosen = chooseBackend(backendName, "");
          std::printf("Deviation: parametric (a point inside a triangle against the surface at "
                      "the same mix of (u,v)), sampled 15 points per triangle; backend %s.\n\n",
                      chosen.backend.name.c_str());
          for (const std::string& input : inputs) {
            auto patches = readSurfaceFile(input);
            auto rows = paperTable(patches, thresholds, chosen.backend);
            std::printf("%s\n", formatPaperTable(input + " (" + std::to_string(patches.size()) +
                                                       " patches)",
                                                   rows)
                                      .c_str());
          }
          return int(kExitOk);
        },
        {});
  });
}

}  // namespace tessera::cli
