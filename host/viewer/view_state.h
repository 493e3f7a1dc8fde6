// What the viewer's keys change (docs/cli.md, `tessera view`) and the status line that shows
// it: kept apart from the window and the GPU so that each key's effect can be tested alone.
#pragma once
#include <cstddef>
#include <string>

#include "viewer/frame_source.h"
#include "viewer/window.h"

namespace tessera::viewer {

// The pixel tolerances the + and - keys reach.
constexpr double kMinTolerancePixels = 0.125, kMaxTolerancePixels = 64.0;

struct ViewState {
  bool wireframe = false;
  bool frozen = false;  // the tessellation is kept while the camera moves
  Colouring colouring = Colouring::Shaded;
  double tolerancePixels = 1.0;
  bool quit = false;
};

// Applies one key to `state` and says what it did, for the log ("wireframe on",
// "colour patch", "tolerance 2 px", "frozen", ...). A new tolerance unfreezes: the frozen
// mesh belongs to the old one. At the tolerance's ends + and - change nothing.
std::string applyKey(KeyAction key, ViewState& state);

// "shaded", "patch" or "level", as --colour names them.
const char* colouringName(Colouring colouring);

// The status line's first line: frames/s, the frame's triangles, the measured error, and the
// state. The overlay draws it (with a second line of key help) and --script logs it.
std::string statusLine(double framesPerSecond, size_t triangles, double errorPixels,
                       const ViewState& state);

}  // namespace tessera::viewer
