// tessera: tessellate free-form surfaces on the GPU. See docs/cli.md.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "cli/cli_support.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/help_text.h"
#include "common/version.h"
#include "io/pending_temp_files.h"

int main(int argc, char** argv) {
  tessera::cli::keptCommandLine() = argv;  // for handing a CAD command to tessera-cad
  CLI::App app{"tessera: adaptive tessellation of free-form surfaces on Vulkan compute"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tessera ") + tessera::versionString(),
                       "print the version and exit");
  app.footer(tessera::cli::helpFooter());
  int exitCode = tessera::cli::kExitOk;
  tessera::cli::addTessellateCommand(app, exitCode);
  tessera::cli::addStatsCommand(app, exitCode);
  tessera::cli::addDevicesCommand(app, exitCode);
  tessera::cli::addInfoCommand(app, exitCode);
  tessera::cli::addRenderCommand(app, exitCode);
  tessera::cli::addPaperTableCommand(app, exitCode);
  tessera::cli::addReduceCommand(app, exitCode);
  tessera::cli::addDivisionsCommand(app, exitCode);
  tessera::cli::addLoopCommands(app, exitCode);
  tessera::cli::addViewCommand(app, exitCode);
  tessera::cli::refuseBadNumbers(app);
  // Ctrl-C or kill during a write: no temporary file left behind (host/io/atomic_file.h).
  tessera::removePendingTempFilesOnSignals();
  // Every command's --help ends with the environment variables, exit codes and docs.
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    command->footer(tessera::cli::helpFooter());
    // Every command reads input and can allocate a lot (docs/hardening.md, memory budget).
    tessera::cli::addResourceLimitOptions(*command);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : tessera::cli::kExitUsage;
  }
  return exitCode;
}
