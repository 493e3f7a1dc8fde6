// The footer of `tessera --help` and of the subcommands' help: the environment variables, the
// exit codes and where the documentation is. Kept next to commands.h's exit codes.
#pragma once
#include <string>

namespace tessera::cli {

std::string helpFooter();

}  // namespace tessera::cli
