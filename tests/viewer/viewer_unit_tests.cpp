// The viewer's input without a window: GLFW's key codes to the viewer's actions (the bindings
// docs/cli.md lists), what each action does to the view state, the status line, the orbit
// camera under a drag and the wheel, and --script files. The window's own handlers, and the
// picture each key gives, are checked under Xvfb (keys_script.txt, viewer_check keys).
#include <catch2/catch.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <fstream>

#include "scratch_dir.h"
#include "tessera/errors.h"
#include "viewer/input_script.h"
#include "viewer/orbit_camera.h"
#include "viewer/view_state.h"
#include "viewer/window.h"

using namespace tessera;
using namespace tessera::viewer;

TEST_CASE("viewer keys: each bound GLFW key gives its action, other keys none") {
  const std::pair<int, KeyAction> bound[] = {
      {GLFW_KEY_W, KeyAction::Wireframe},   {GLFW_KEY_C, KeyAction::Colour},
      {GLFW_KEY_EQUAL, KeyAction::Coarser}, {GLFW_KEY_KP_ADD, KeyAction::Coarser},
      {GLFW_KEY_MINUS, KeyAction::Finer},   {GLFW_KEY_KP_SUBTRACT, KeyAction::Finer},
      {GLFW_KEY_F, KeyAction::Freeze},      {GLFW_KEY_ESCAPE, KeyAction::Quit},
      {GLFW_KEY_Q, KeyAction::Quit}};
  for (const auto& [key, action] : bound) {
    INFO("GLFW key " << key);
    REQUIRE(keyActionFor(key).has_value());
    CHECK(*keyActionFor(key) == action);
  }
  for (int key : {GLFW_KEY_A, GLFW_KEY_SPACE, GLFW_KEY_ENTER, GLFW_KEY_0, GLFW_KEY_UNKNOWN})
    CHECK_FALSE(keyActionFor(key).has_value());
}

TEST_CASE("viewer keys: a script's key names are GLFW's keys, so they reach the same bindings") {
  CHECK(glfwKeyNamed("W") == GLFW_KEY_W);
  CHECK(glfwKeyNamed("w") == GLFW_KEY_W);
  CHECK(glfwKeyNamed("Z") == GLFW_KEY_Z);
  CHECK(glfwKeyNamed("+") == GLFW_KEY_EQUAL);
  CHECK(glfwKeyNamed("=") == GLFW_KEY_EQUAL);
  CHECK(glfwKeyNamed("-") == GLFW_KEY_MINUS);
  CHECK(glfwKeyNamed("KP+") == GLFW_KEY_KP_ADD);
  CHECK(glfwKeyNamed("KP-") == GLFW_KEY_KP_SUBTRACT);
  CHECK(glfwKeyNamed("Esc") == GLFW_KEY_ESCAPE);
  for (const char* name : {"", "WW", "1", "Escape", "plus", "KP*"}) {
    INFO(name);
    CHECK(glfwKeyNamed(name) == -1);
  }
  // The keys docs/cli.md lists, by name, end to end.
  CHECK(keyActionFor(glfwKeyNamed("W")) == KeyAction::Wireframe);
  CHECK(keyActionFor(glfwKeyNamed("C")) == KeyAction::Colour);
  CHECK(keyActionFor(glfwKeyNamed("+")) == KeyAction::Coarser);
  CHECK(keyActionFor(glfwKeyNamed("-")) == KeyAction::Finer);
  CHECK(keyActionFor(glfwKeyNamed("F")) == KeyAction::Freeze);
  CHECK(keyActionFor(glfwKeyNamed("Esc")) == KeyAction::Quit);
  CHECK(keyActionFor(glfwKeyNamed("Q")) == KeyAction::Quit);
}

TEST_CASE("viewer keys: W toggles the wireframe, C cycles shaded, patch, level") {
  ViewState s;
  CHECK(applyKey(KeyAction::Wireframe, s) == "wireframe on");
  CHECK(s.wireframe);
  CHECK(applyKey(KeyAction::Wireframe, s) == "wireframe off");
  CHECK_FALSE(s.wireframe);
  CHECK(applyKey(KeyAction::Colour, s) == "colour patch");
  CHECK(s.colouring == Colouring::Patch);
  CHECK(applyKey(KeyAction::Colour, s) == "colour level");
  CHECK(s.colouring == Colouring::Depth);
  CHECK(applyKey(KeyAction::Colour, s) == "colour shaded");
  CHECK(s.colouring == Colouring::Shaded);
  CHECK_FALSE(s.quit);
  CHECK(applyKey(KeyAction::Quit, s) == "quit");
  CHECK(s.quit);
}

TEST_CASE("viewer keys: + doubles the tolerance, - halves it, within 0.125..64 px") {
  ViewState s;
  CHECK(applyKey(KeyAction::Coarser, s) == "tolerance 2 px");
  CHECK(s.tolerancePixels == 2.0);
  CHECK(applyKey(KeyAction::Finer, s) == "tolerance 1 px");
  CHECK(applyKey(KeyAction::Finer, s) == "tolerance 0.5 px");
  CHECK(s.tolerancePixels == 0.5);
  s.tolerancePixels = kMinTolerancePixels;
  CHECK(applyKey(KeyAction::Finer, s) == "tolerance 0.125 px (the limit)");
  CHECK(s.tolerancePixels == kMinTolerancePixels);
  s.tolerancePixels = kMaxTolerancePixels;
  CHECK(applyKey(KeyAction::Coarser, s) == "tolerance 64 px (the limit)");
  CHECK(s.tolerancePixels == kMaxTolerancePixels);
}

TEST_CASE("viewer keys: F freezes and thaws, a new tolerance thaws, one at the limit does not") {
  ViewState s;
  CHECK(applyKey(KeyAction::Freeze, s) == "frozen");
  CHECK(s.frozen);
  s.tolerancePixels = kMaxTolerancePixels;
  applyKey(KeyAction::Coarser, s);  // at the limit: the frozen mesh is still the one drawn
  CHECK(s.frozen);
  applyKey(KeyAction::Finer, s);
  CHECK_FALSE(s.frozen);
  applyKey(KeyAction::Freeze, s);
  CHECK(applyKey(KeyAction::Freeze, s) == "unfrozen");
  CHECK_FALSE(s.frozen);
}

TEST_CASE("viewer keys: the status line gives frames/s, triangles, error and the state") {
  ViewState s;
  s.tolerancePixels = 0.5;
  CHECK(statusLine(59.94, 12345, 0.4321, s) ==
        "59.9 frames/s  12345 triangles  error 0.43 px (tolerance 0.5 px)  shaded");
  s.colouring = Colouring::Depth;
  s.wireframe = true;
  s.frozen = true;
  CHECK(statusLine(0, 7, 2, s) ==
        "0.0 frames/s  7 triangles  error 2.00 px (tolerance 0.5 px)  level wire  FROZEN");
}

TEST_CASE("viewer mouse: a drag turns the orbit camera, the wheel moves it nearer") {
  OrbitCamera orbit;
  const glm::dvec3 eye = orbit.eye();
  const double distance = glm::length(eye - orbit.target);
  OrbitCamera turned = orbit;
  turned.drag(400, 0, 800);  // half the window's width: a quarter circle
  CHECK(turned.yaw == Approx(orbit.yaw - 0.5 * 3.14159265358979));
  CHECK(turned.pitch == orbit.pitch);
  CHECK(glm::length(turned.eye() - orbit.target) == Approx(distance));
  CHECK(glm::length(turned.eye() - eye) > 0.5 * distance);
  const Camera before = orbit.camera(800, 600), after = turned.camera(800, 600);
  CHECK(before.viewProjection != after.viewProjection);
  OrbitCamera raised = orbit;
  raised.drag(0, 100000, 800);  // stops short of the pole
  CHECK(raised.pitch == 1.5);
  OrbitCamera nearer = orbit;
  nearer.zoom(2);
  CHECK(nearer.distance == Approx(0.81 * orbit.distance));
  nearer.zoom(-2);
  CHECK(nearer.distance == Approx(orbit.distance));
}

namespace {

std::string scriptError(const std::string& text) {
  test::ScratchDir dir("viewer_script");
  const std::string path = (dir.path / "keys.txt").string();
  std::ofstream(path) << text;
  try {
    readInputScript(path);
  } catch (const InputError& e) {
    return std::string(e.what()).substr(path.size());
  }
  return "no error";
}

}  // namespace

TEST_CASE("viewer script: steps in frame order, keys by name, moves and outputs") {
  test::ScratchDir dir("viewer_script");
  const std::string path = (dir.path / "keys.txt").string();
  std::ofstream(path) << "# frame step\n0 key W\n0 key +\n3 drag -40 12.5\r\n"
                         "3 wheel 2\n7 screenshot a.png\n7 dump a.glb\n";
  const std::vector<ScriptStep> steps = readInputScript(path);
  REQUIRE(steps.size() == 6);
  CHECK((steps[0].kind == ScriptStep::Kind::Key && steps[0].frame == 0 &&
         steps[0].glfwKey == GLFW_KEY_W && steps[0].line == 2));
  CHECK(steps[1].glfwKey == GLFW_KEY_EQUAL);
  CHECK((steps[2].kind == ScriptStep::Kind::Drag && steps[2].frame == 3 && steps[2].x == -40 &&
         steps[2].y == 12.5));
  CHECK((steps[3].kind == ScriptStep::Kind::Wheel && steps[3].x == 2));
  CHECK((steps[4].kind == ScriptStep::Kind::Screenshot && steps[4].word == "a.png"));
  CHECK((steps[5].kind == ScriptStep::Kind::Dump && steps[5].word == "a.glb" &&
         steps[5].line == 7));
}

TEST_CASE("viewer script: a bad step is named by file and line") {
  CHECK(scriptError("1 key W\n2 key Space\n") ==
        ":2: unknown key 'Space' (W, C, F, Q, +, -, KP+, KP-, Esc, a letter)");
  CHECK(scriptError("5 key W\n4 key C\n") ==
        ":2: frame 4 comes after frame 5 (steps go in frame order)");
  CHECK(scriptError("-1 key W\n") == ":1: '-1' is not a frame number 0..1000000");
  CHECK(scriptError("1 press W\n") ==
        ":1: expected a step (key, drag, wheel, screenshot, dump) after the frame, got 'press'");
  CHECK(scriptError("1 drag 3\n") == ":1: 'drag' takes 2 numbers, got 1");
  CHECK(scriptError("1 key W # wires\n") ==
        ":1: 'key' takes 1 word, got 3 ('#' starts a comment only at the beginning of a line)");
  CHECK(scriptError("1 wheel nan\n") == ":1: 'nan' is not a finite number (wheel steps)");
  CHECK(scriptError("1 drag 2e6 0\n") == ":1: '2e6' is beyond ±1e6 (dx)");
  CHECK(scriptError("1 screenshot a.jpg\n") == ":1: a screenshot is a .png, got 'a.jpg'");
  CHECK(scriptError("1 dump a.obj\n") == ":1: a dump is a .glb, got 'a.obj'");
  CHECK(scriptError("1\n") ==
        ":1: expected a step (key, drag, wheel, screenshot, dump) after the frame, got ''");
}
