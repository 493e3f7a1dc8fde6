#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "grid_interpolation.h"
#include "io/bpt_reader.h"
#include "io/errors.h"
#include "io/grid_reader.h"
#include "io/surface_reader.h"
#include "paper_table.h"
#include "vk/context.h"

namespace tessera::cli {
namespace {

std::vector<BezierPatch> readSurface(const std::string& path) { return readSurfaceFile(path); }

}  // namespace

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
    try {
      std::unique_ptr<vk::Context> context;
      Backend backend;
      if (backendName != "cpu") {
        try {
          context = std::make_unique<vk::Context>(vk::ContextOptions{});
          backend = makeVulkanBackend(*context);
        } catch (const vk::VulkanUnavailable& e) {
          if (backendName == "vulkan") throw;
          std::fprintf(stderr, "tessera: no Vulkan (%s); using the CPU backend\n", e.what());
          backend = makeCpuBackend();
        }
      } else {
        backend = makeCpuBackend();
      }
      std::printf("Deviation: parametric (a point inside a triangle against the surface at the "
                  "same mix of (u,v)), sampled 15 points per triangle; backend %s.\n\n",
                  backend.name.c_str());
      for (const std::string& input : inputs) {
        auto patches = readSurface(input);
        auto rows = paperTable(patches, thresholds, backend);
        std::printf("%s\n", formatPaperTable(input + " (" + std::to_string(patches.size()) +
                                                 " patches)",
                                             rows)
                                .c_str());
      }
    } catch (const InputError& e) {
      std::fprintf(stderr, "tessera: %s\n", e.what());
      exitCode = kExitBadInput;
    } catch (const vk::VulkanUnavailable& e) {
      std::fprintf(stderr, "tessera: %s\n", e.what());
      exitCode = kExitNoVulkan;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tessera: %s\n", e.what());
      exitCode = kExitInternal;
    }
  });
}

}  // namespace tessera::cli
