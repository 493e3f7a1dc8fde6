// The subcommands of the `tessera` tool (one file each) and the exit codes they share.
#pragma once
// CLI::App by name only: <CLI/CLI.hpp> costs ~5 s of CPU in every file that includes it
// (CMakeLists.txt), and cad_job.cpp, compiled on its own, needs none of it.
namespace CLI {
class App;
}  // namespace CLI

namespace tessera::cli {

// Exit codes (docs/cli.md).
enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 1,        // bad command line
  kExitBadInput = 2,     // unreadable or invalid input file
  kExitNoVulkan = 3,     // --backend vulkan and no usable Vulkan device
  kExitLimit = 4,        // node budget or another resource limit reached
  kExitOutput = 5,       // the output could not be written (nothing was left behind)
  kExitDevice = 6,       // the Vulkan device failed mid-run (device lost, out of device memory)
  kExitInternal = 70,    // a bug: please report
};

void addTessellateCommand(CLI::App& app, int& exitCode);
void addStatsCommand(CLI::App& app, int& exitCode);
void addDevicesCommand(CLI::App& app, int& exitCode);
void addInfoCommand(CLI::App& app, int& exitCode);
void addRenderCommand(CLI::App& app, int& exitCode);
void addPaperTableCommand(CLI::App& app, int& exitCode);
void addReduceCommand(CLI::App& app, int& exitCode);
void addDivisionsCommand(CLI::App& app, int& exitCode);
void addLoopCommands(CLI::App& app, int& exitCode);  // loop, limit, fit, join
void addViewCommand(CLI::App& app, int& exitCode);

}  // namespace tessera::cli
