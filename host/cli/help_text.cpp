#include "cli/help_text.h"

#include "cli/commands.h"

namespace tessera::cli {

std::string helpFooter() {
  // The codes are the ExitCode values; tests/CMakeLists.txt checks that they are listed.
  const auto code = [](int value, const char* meaning) {
    std::string number = std::to_string(value);
    return "  " + number + std::string(4 - number.size(), ' ') + meaning + "\n";
  };
  return "\nEnvironment:\n"
         "  TESSERA_DEVICE=<index|name>     the Vulkan device (as --device)\n"
         "  TESSERA_PIPELINE_CACHE=<file>   the Vulkan pipeline cache file, or off (default: "
         "$XDG_CACHE_HOME/tessera/, else ~/.cache/tessera/)\n"
         "  TESSERA_PROGRESS_INTERVAL=<s>   seconds between progress lines on stderr (default 2)\n"
         "  TESSERA_VULKAN_LOADER=<path>    the Vulkan loader library to open\n"
         "  TESSERA_VK_FAULT=<fault>        inject a Vulkan fault for testing: alloc[:N], "
         "device-lost[:N], no-device, no-push-descriptor\n"
         "\nExit codes:\n" +
         code(kExitOk, "success") + code(kExitUsage, "bad command line") +
         code(kExitBadInput, "unreadable or invalid input (file:line: reason)") +
         code(kExitNoVulkan, "--backend vulkan and no usable Vulkan device") +
         code(kExitLimit, "a resource limit was reached (node budget, --memory-budget, --max-input-size)") +
         code(kExitOutput, "the output could not be written (nothing left behind)") +
         code(kExitDevice, "the Vulkan device failed mid-run") +
         code(kExitInternal, "internal error (a bug: please report it)") +
         "\nDocumentation: docs/cli.md (commands, options, exit codes), README.md,\n"
         "  docs/stats_schema.md (--json, --stats), docs/scene_format.md (.json scenes).\n";
}

}  // namespace tessera::cli
