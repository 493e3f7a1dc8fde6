#include <cstdio>

#include "cli/commands.h"
#include "io/surface_reader.h"
#include "io/errors.h"

namespace tessera::cli {

void addInfoCommand(CLI::App& app, int& exitCode) {
  CLI::App* cmd = app.add_subcommand("info", "Describe an input file (patches, degrees, bounds)");
  static std::string input;
  cmd->add_option("input", input, "input surface file (.bpt or .grid)")->required();
  cmd->callback([&exitCode] {
    try {
      auto patches = readSurfaceFile(input);
      glm::dvec3 lo(1e300), hi(-1e300);
      for (const auto& p : patches)
        for (const auto& c : p.cp) lo = glm::min(lo, c), hi = glm::max(hi, c);
      std::printf("%s: %zu patches\n", input.c_str(), patches.size());
      if (!patches.empty())
        std::printf("bounds: (%g, %g, %g) .. (%g, %g, %g)\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    } catch (const InputError& e) {
      std::fprintf(stderr, "tessera: %s\n", e.what());
      exitCode = kExitBadInput;
    }
  });
}

}  // namespace tessera::cli
