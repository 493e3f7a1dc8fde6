// `tessera info`: what an input file holds. A CAD model goes to describeCadModel (cad_job.h).
#include <CLI/CLI.hpp>

#include <cstdio>

#include "cli/cad_job.h"
#include "cli/cli_support.h"
#include "cli/commands.h"
#include "io/errors.h"
#include "io/surface_reader.h"

namespace tessera::cli {

void addInfoCommand(CLI::App& app, int& exitCode) {
  CLI::App* cmd = app.add_subcommand("info", "Describe an input file (patches, degrees, bounds)");
  static std::string input;
  cmd->add_option("input", input, "input surface file (.bpt or .grid), or a CAD model (.step, .iges, .brep)")
      ->required();
  cmd->callback([&exitCode] {
    // Every error through the one mapping to exit codes (a limit is 4, not an abort).
    exitCode = runReportingErrors([] {
      if (isCadInput(input)) return describeCadModel(input);
      auto patches = readSurfaceFile(input);
      glm::dvec3 lo(1e300), hi(-1e300);
      for (const auto& p : patches)
        for (const auto& c : p.cp) lo = glm::min(lo, c), hi = glm::max(hi, c);
      std::printf("%s: %zu patches\n", input.c_str(), patches.size());
      if (!patches.empty())
        std::printf("bounds: (%g, %g, %g) .. (%g, %g, %g)\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
      return int(kExitOk);
    }, {});
  });
}

}  // namespace tessera::cli
