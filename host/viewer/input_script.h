// `tessera view --script FILE`: input and pictures at given frames, for tests and
// demonstrations. Keys and drags go into the window through the handlers real input goes
// through (Window::injectKey, injectDrag, injectWheel). One step a line, frames ascending:
//   <frame> key <name>        a key press: W, C, F, Q, +, -, KP+, KP-, Esc, any letter
//   <frame> drag <dx> <dy>    a drag with the left button, in pixels
//   <frame> wheel <steps>     wheel steps (positive: nearer)
//   <frame> screenshot <png>  frame <frame> as drawn, overlay included
//   <frame> dump <glb>        frame <frame>'s mesh as drawn (as --dump-frame)
// Input steps act before their frame is drawn; '#' starts a comment line (docs/cli.md).
#pragma once
#include <string>
#include <vector>

namespace tessera::viewer {

struct ScriptStep {
  enum class Kind { Key, Drag, Wheel, Screenshot, Dump };
  int frame = 0;
  Kind kind = Kind::Key;
  int line = 0;           // in the script, for messages
  std::string word;       // the key's name, or the output path
  int glfwKey = -1;       // Key
  double x = 0, y = 0;    // Drag: dx, dy; Wheel: steps in x
};

// Reads a script. Throws InputError naming the file and line: an unknown step or key, a
// missing or extra word, a frame that is not a whole number 0..1000000 or comes before the
// previous step's, a number that is not finite or beyond ±1e6, a screenshot not .png, a dump
// not .glb.
std::vector<ScriptStep> readInputScript(const std::string& path);

}  // namespace tessera::viewer
