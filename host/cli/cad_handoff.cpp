// tessera's side of the CAD seam (cad_job.h). tessera links no Open CASCADE: loading its ~30
// libraries cost every run ~27 ms, CAD model or not. A CAD command replaces this process with
// tessera-cad, which does; the entry points are called before the command reads or writes
// anything, so tessera-cad starts the command afresh on the same command line.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "cli/cad_job.h"
#include "cli/command_line.h"
#include "io/errors.h"

namespace tessera::cli {
namespace {

[[noreturn]] void cannotHandOff(const std::string& input, const std::string& why) {
  throw InputError(InputErrorKind::Syntax, input, 0,
                   "this tessera was built without Open CASCADE's data exchange (host/cad/); it "
                   "hands CAD models to " + why);
}

// execv of the tessera-cad in the running executable's directory, with main's argv and this
// environment; returns only by throwing.
[[noreturn]] void runInCadExecutable(const std::string& input) {
  if (!keptCommandLine())
    cannotHandOff(input, std::string(kCadExecutableName) + ", but main kept no command line");
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) cannotHandOff(input, std::string(kCadExecutableName) + ", but /proc/self/exe, which "
                                   "says where to look, cannot be read: " + ec.message());
  const std::string helper = (self.parent_path() / kCadExecutableName).string();
  // A copy of this tessera under the helper's name would exec itself for ever.
  if (self.filename() == kCadExecutableName)
    cannotHandOff(input, helper + ", and that is this executable (a copy of tessera, not "
                             "tessera-cad)");
  std::fflush(nullptr);  // nothing is printed yet; were it, the new image would lose it
  execv(helper.c_str(), keptCommandLine());
  const int error = errno;
  cannotHandOff(input, helper + ", which " +
                           (error == ENOENT ? std::string("is not there (a build without Open "
                                                          "CASCADE, or not installed)")
                                            : "cannot run: " + std::string(std::strerror(error))));
}

}  // namespace

int tessellateCadModel(const CadCommand& c) { runInCadExecutable(c.input); }

int renderCadModel(const CadRenderCommand& c) { runInCadExecutable(c.input); }

int describeCadModel(const std::string& input) { runInCadExecutable(input); }

}  // namespace tessera::cli
