#include <algorithm>
#include <cctype>
#include <cstdio>

#include "cli/cli_support.h"
#include "cli/commands.h"
#include "io/errors.h"
#include "io/surface_reader.h"
#ifdef TESSERA_HAVE_CAD
#include "cad/to_trimmed.h"
#endif

namespace tessera::cli {
namespace {

bool isCadFile(std::string path) {
  std::transform(path.begin(), path.end(), path.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* ext : {".step", ".stp", ".iges", ".igs", ".brep"}) {
    const std::string e = ext;
    if (path.size() >= e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0) return true;
  }
  return false;
}

#ifdef TESSERA_HAVE_CAD
// A CAD model: its faces, edges and shared points once converted to trimmed faces at the
// default δ (0.1% of the diagonal), with every face that failed and every edge warning.
void describeCad(const std::string& path) {
  const CadFile file = readCadFile(path);
  const double delta = defaultCadTolerance(file.shape);
  const CadImport in = toTrimmedModel(file, delta);
  std::printf("%s: %d faces (%zu converted, %zu failed), %d edges, %d vertices, %zu shared points at δ %g\n",
              path.c_str(), in.faces.Extent(), in.model.faces.size(), in.failures.size(),
              in.edges.Extent(), in.vertices.Extent(), in.model.sharedPoints.size(), delta);
  for (const auto& failure : in.failures) std::printf("failed: %s\n", failure.message.c_str());
  for (const auto& warning : in.warnings) std::printf("warning: %s\n", warning.message.c_str());
}
#endif

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
  CLI::App* cmd = app.add_subcommand("info", "Describe an input file (patches, degrees, bounds)");
  static std::string input;
  cmd->add_option("input", input, "input surface file (.bpt or .grid), or a CAD model (.step, .iges, .brep)")
      ->required();
  cmd->callback([&exitCode] {
    // Every error through the one mapping to exit codes (a limit is 4, not an abort).
    exitCode = runReportingErrors([] {
      if (isCadFile(input)) {
#ifdef TESSERA_HAVE_CAD
        describeCad(input);
        return int(kExitOk);
#else
        throw InputError(InputErrorKind::Syntax, input, 0,
                         "this tessera was built without Open CASCADE's data exchange (host/cad/)");
#endif
      }
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
