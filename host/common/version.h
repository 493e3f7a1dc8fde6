// Tessera's version, the project(... VERSION) of the top CMakeLists.txt.
#pragma once

namespace tessera {

// "MAJOR.MINOR.PATCH", e.g. "0.1.0".
const char* versionString();

}  // namespace tessera
