#include <CLI/CLI.hpp>

#include <cstdio>

#include "cli/commands.h"
#include "vk/context.h"

namespace tessera::cli {

void addDevicesCommand(CLI::App& app, int& exitCode) {
  CLI::App* cmd = app.add_subcommand("devices", "List Vulkan devices and which one is chosen");
  cmd->callback([&exitCode] {
    try {
      auto devices = vk::listDevices();
      for (const auto& d : devices)
        std::printf("[%u] %s (%s, %s %s)%s%s\n", d.index, d.name.c_str(), d.typeName().c_str(),
                    d.driverName.c_str(), d.driverInfo.c_str(), d.usable ? "" : " unusable: ",
                    d.unusableReason.c_str());
      if (devices.empty()) std::printf("no Vulkan devices\n");
    } catch (const vk::VulkanUnavailable& e) {
      std::fprintf(stderr, "tessera: %s\n", e.what());
      exitCode = kExitNoVulkan;
    }
  });
}

}  // namespace tessera::cli
