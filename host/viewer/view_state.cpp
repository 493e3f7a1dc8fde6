#include "viewer/view_state.h"

#include <cstdio>

namespace tessera::viewer {
namespace {

std::string formatTolerance(double pixels) {
  char text[64];
  std::snprintf(text, sizeof text, "tolerance %g px", pixels);
  return text;
}

}  // namespace

std::string applyKey(KeyAction key, ViewState& state) {
  switch (key) {
    case KeyAction::Wireframe:
      state.wireframe = !state.wireframe;
      return state.wireframe ? "wireframe on" : "wireframe off";
    case KeyAction::Colour:
      state.colouring = state.colouring == Colouring::Shaded  ? Colouring::Patch
                        : state.colouring == Colouring::Patch ? Colouring::Depth
                                                              : Colouring::Shaded;
      return std::string("colour ") + colouringName(state.colouring);
    case KeyAction::Finer:
    case KeyAction::Coarser: {
      const double next = state.tolerancePixels * (key == KeyAction::Finer ? 0.5 : 2.0);
      if (next < kMinTolerancePixels || next > kMaxTolerancePixels)
        return formatTolerance(state.tolerancePixels) + " (the limit)";
      state.tolerancePixels = next;
      state.frozen = false;
      return formatTolerance(next);
    }
    case KeyAction::Freeze:
      state.frozen = !state.frozen;
      return state.frozen ? "frozen" : "unfrozen";
    case KeyAction::Quit: state.quit = true; return "quit";
  }
  return "";
}

const char* colouringName(Colouring c) {
  return c == Colouring::Patch ? "patch" : c == Colouring::Depth ? "level" : "shaded";
}

std::string statusLine(double fps, size_t triangles, double errorPixels, const ViewState& s) {
  char line[256];
  std::snprintf(line, sizeof line,
                "%.1f frames/s  %zu triangles  error %.2f px (tolerance %.3g px)  %s%s%s", fps,
                triangles, errorPixels, s.tolerancePixels, colouringName(s.colouring),
                s.wireframe ? " wire" : "", s.frozen ? "  FROZEN" : "");
  return line;
}

}  // namespace tessera::viewer
