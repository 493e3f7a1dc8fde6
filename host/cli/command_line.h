// main's argv as given (null-terminated; it lives until exit), kept before parsing: tessera
// hands a CAD command to tessera-cad on exactly this command line (cad_job.h). A header of its
// own so that cad_handoff.cpp compiles without CLI11.
#pragma once

namespace tessera::cli {

// main sets it once: keptCommandLine() = argv. Null until then.
inline char**& keptCommandLine() {
  static char** argv = nullptr;
  return argv;
}

}  // namespace tessera::cli
