#include "common/version.h"

// CMakeLists.txt defines TESSERA_VERSION_STRING from project(... VERSION) for this file only.
#ifndef TESSERA_VERSION_STRING
#error "TESSERA_VERSION_STRING must be defined by the build (CMakeLists.txt)"
#endif

namespace tessera {

const char* versionString() { return TESSERA_VERSION_STRING; }

}  // namespace tessera
