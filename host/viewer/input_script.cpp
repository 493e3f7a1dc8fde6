#include "viewer/input_script.h"

#include <cmath>

#include "io/text_lines.h"
#include "viewer/window.h"

namespace tessera::viewer {
namespace {

constexpr long long kMaxScriptFrame = 1000000;
constexpr double kMaxScriptMove = 1e6;  // pixels or wheel steps

bool endsWith(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

double moveNumber(const TextLines& lines, std::string_view token, const std::string& what) {
  const double value = parseCoordinate(lines, token, what);
  if (std::fabs(value) > kMaxScriptMove)
    lines.fail(InputErrorKind::Range, quotedToken(token) + " is beyond ±1e6 (" + what + ")");
  return value;
}

ScriptStep parseStep(const TextLines& lines, int previousFrame) {
  const std::vector<std::string_view>& t = lines.tokens();
  ScriptStep step;
  step.line = lines.line();
  long long frame = 0;
  bool outOfRange = false;
  if (!parseInteger(t[0], frame, outOfRange) || outOfRange || frame < 0 ||
      frame > kMaxScriptFrame)
    lines.fail(InputErrorKind::Syntax, quotedToken(t[0]) + " is not a frame number 0..1000000");
  if (frame < previousFrame)
    lines.fail(InputErrorKind::Syntax, "frame " + std::to_string(frame) +
                                           " comes after frame " + std::to_string(previousFrame) +
                                           " (steps go in frame order)");
  step.frame = int(frame);
  const std::string kind = t.size() > 1 ? std::string(t[1]) : "";
  const size_t words = kind == "drag" ? 4 : 3;
  if (kind != "key" && kind != "drag" && kind != "wheel" && kind != "screenshot" &&
      kind != "dump")
    lines.fail(InputErrorKind::Syntax,
               "expected a step (key, drag, wheel, screenshot, dump) after the frame, got " +
                   quotedToken(kind));
  if (t.size() != words)
    lines.fail(InputErrorKind::Syntax, quotedToken(kind) + " takes " + std::to_string(words - 2) +
                                           (words == 4 ? " numbers" : " word") + ", got " +
                                           std::to_string(t.size() - 2) + commentHint(t));
  step.word = std::string(t[2]);
  if (kind == "key") {
    step.kind = ScriptStep::Kind::Key;
    step.glfwKey = glfwKeyNamed(step.word);
    if (step.glfwKey < 0)
      lines.fail(InputErrorKind::Syntax, "unknown key " + quotedToken(step.word) +
                                             " (W, C, F, Q, +, -, KP+, KP-, Esc, a letter)");
  } else if (kind == "drag") {
    step.kind = ScriptStep::Kind::Drag;
    step.x = moveNumber(lines, t[2], "dx");
    step.y = moveNumber(lines, t[3], "dy");
  } else if (kind == "wheel") {
    step.kind = ScriptStep::Kind::Wheel;
    step.x = moveNumber(lines, t[2], "wheel steps");
  } else if (kind == "screenshot") {
    step.kind = ScriptStep::Kind::Screenshot;
    if (!endsWith(step.word, ".png"))
      lines.fail(InputErrorKind::Syntax, "a screenshot is a .png, got " + quotedToken(step.word));
  } else {
    step.kind = ScriptStep::Kind::Dump;
    if (!endsWith(step.word, ".glb"))
      lines.fail(InputErrorKind::Syntax, "a dump is a .glb, got " + quotedToken(step.word));
  }
  return step;
}

}  // namespace

std::vector<ScriptStep> readInputScript(const std::string& path) {
  std::ifstream in = openForReading(path, "an input script");
  TextLines lines(in, path);
  std::vector<ScriptStep> steps;
  while (lines.next())
    steps.push_back(parseStep(lines, steps.empty() ? 0 : steps.back().frame));
  return steps;
}

}  // namespace tessera::viewer
