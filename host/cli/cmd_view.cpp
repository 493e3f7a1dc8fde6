// `tessera view`: the real-time tessellation in a window (host/viewer/), or scripted frames
// for tests and pictures. Built only with TESSERA_BUILD_VIEWER (GLFW); without it the command
// says so and exits 3, as when no window system is present.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/bench_scenes.h"
#include "cli/cli_support.h"
#include "cli/commands.h"
#include "cli/outputs.h"
#include "io/surface_reader.h"
#if TESSERA_HAVE_VIEWER
#include "viewer/input_script.h"
#include "viewer/view_state.h"
#include "viewer/viewer.h"
#include "viewer/window.h"
#endif

namespace tessera::cli {
namespace {

struct ViewArgs {
  std::string input;
  int teapots = 0;
  double tolerance = 1.0;
  std::string size = "960x540";
  int frames = 0;
  std::string cameraPath = "orbit";
  std::string screenshot;
  std::vector<std::string> dumpFrame;  // k, path
  std::string script;
  bool wireframe = false;
  std::string colour = "shaded";
  std::string device;
  bool validation = false;
  bool quiet = false;
};

// `outputs`: the files written, for exit 5 (runReportingErrors); the script's are added.
int run(const ViewArgs& a, std::vector<std::string>& outputPaths) {
#if !TESSERA_HAVE_VIEWER
  (void)a;
  (void)outputPaths;
  std::fprintf(stderr, "tessera: view: this tessera was built without the viewer "
                       "(GLFW was not found when it was configured: apt-get install "
                       "libglfw3-dev, then configure again)\n");
  return kExitNoVulkan;
#else
  viewer::ViewerOptions o;
  char extra = 0;
  if (std::sscanf(a.size.c_str(), "%dx%d%c", &o.width, &o.height, &extra) != 2 || o.width < 16 ||
      o.height < 16 || o.width > 4096 || o.height > 4096)
    throw CLI::ValidationError("--size", "expected WxH with each in 16..4096, got '" + a.size + "'");
  if (a.cameraPath != "orbit")
    throw CLI::ValidationError("--camera-path", "the one path is 'orbit', got '" + a.cameraPath + "'");
  if (!(a.tolerance >= viewer::kMinTolerancePixels && a.tolerance <= viewer::kMaxTolerancePixels))
    throw CLI::ValidationError("--tolerance", "expected 0.125..64 pixels");
  if (a.colour == "shaded" || a.colour == "patch" || a.colour == "level")
    o.colouring = a.colour == "shaded" ? 0 : a.colour == "patch" ? 1 : 2;
  else
    throw CLI::ValidationError("--colour", "expected shaded, patch or level, got '" + a.colour + "'");
  if (!a.screenshot.empty() && a.frames < 1)
    throw CLI::ValidationError("--screenshot", "needs --frames N (the last frame is saved)");
  if (!a.dumpFrame.empty()) {
    size_t used = 0;
    try {
      o.dumpFrame = std::stoi(a.dumpFrame[0], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != a.dumpFrame[0].size() || o.dumpFrame < 0 ||
        (a.frames > 0 && o.dumpFrame >= a.frames))
      throw CLI::ValidationError("--dump-frame", "frame '" + a.dumpFrame[0] +
                                                     "' is not a frame number below --frames");
    o.dumpPath = a.dumpFrame[1];
    checkMeshFormat(o.dumpPath, "glb");
  }
  std::vector<NamedFile> outputs = {{"--screenshot", a.screenshot}, {"--dump-frame", o.dumpPath}};
  if (!a.script.empty()) {
    o.script = viewer::readInputScript(a.script);
    for (const viewer::ScriptStep& step : o.script) {
      if (a.frames > 0 && step.frame >= a.frames)
        throw CLI::ValidationError("--script", a.script + ":" + std::to_string(step.line) +
                                                   ": frame " + std::to_string(step.frame) +
                                                   " is not below --frames " +
                                                   std::to_string(a.frames));
      if (step.kind == viewer::ScriptStep::Kind::Screenshot ||
          step.kind == viewer::ScriptStep::Kind::Dump) {
        outputs.push_back({a.script + ":" + std::to_string(step.line), step.word});
        outputPaths.push_back(step.word);
      }
    }
  }
  checkOutputs({{"input", a.input}, {"--script", a.script}}, outputs);
  // The real-time path draws untrimmed patches; a CAD model's trimmed faces are meshed once.
  if (isCadInput(a.input))
    throw InputError(InputErrorKind::Syntax, a.input, 0,
                     "tessera view draws Bézier patches (.bpt, .grid or .json); a CAD model's "
                     "trimmed faces are meshed by `tessera tessellate` (e.g. to .glb) or drawn "
                     "by `tessera render`");
  o.patches = readSurfaceFile(a.input);
  if (a.teapots > 0)
    o.patches = bench::perturbedCopies(o.patches, a.teapots,
                                       int(std::ceil(std::sqrt(double(a.teapots)))));
  o.title = "tessera view " + a.input;
  o.tolerancePixels = a.tolerance;
  o.device = a.device;
  o.validation = a.validation;
  o.frames = a.frames;
  o.screenshot = a.screenshot;
  o.wireframe = a.wireframe;
  viewer::ViewerReport report;
  try {
    report = viewer::runViewer(o);
  } catch (const viewer::WindowSystemUnavailable& e) {
    std::fprintf(stderr, "tessera: view: %s\n", e.what());
    return kExitNoVulkan;
  }
  if (report.validationMessages > 0) {
    std::fprintf(stderr, "tessera: view: %zu validation messages (above)\n",
                 report.validationMessages);
    return kExitInternal;
  }
  if (!a.quiet) {
    std::printf("view: %d frames, %.1f frames/s, %zu triangles in the last, error %.2f px\n",
                report.frames, report.framesPerSecond, report.lastTriangles,
                report.lastErrorPixels);
    if (!a.screenshot.empty()) std::printf("wrote %s\n", a.screenshot.c_str());
    if (!o.dumpPath.empty() && o.dumpFrame < report.frames)
      std::printf("wrote %s (frame %d)\n", o.dumpPath.c_str(), o.dumpFrame);
  }
  return kExitOk;
#endif
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
  static ViewArgs args;
  CLI::App* cmd = app.add_subcommand(
      "view", "Show the real-time tessellation in a window (needs Vulkan and an X server)");
  cmd->add_option("input", args.input, "scene (.bpt, .grid or .json)")->required();
  cmd->add_option("--teapots", args.teapots,
                  "show N perturbed copies of the scene on a grid (data/teapot.bpt --teapots 100 "
                  "is the bench's scene)")
      ->check(CLI::Range(0, 10000));
  cmd->add_option("--tolerance", args.tolerance, "screen-space tolerance in pixels (+/- halve or double it)")
      ->capture_default_str();
  cmd->add_option("--size", args.size, "window size WxH")->capture_default_str();
  cmd->add_option("--frames", args.frames,
                  "scripted: draw N frames along --camera-path, then exit")
      ->check(CLI::Range(0, 1000000));
  cmd->add_option("--camera-path", args.cameraPath, "scripted camera path: orbit (one circle)")
      ->capture_default_str();
  cmd->add_option("--screenshot", args.screenshot, "save the last scripted frame as a PNG");
  cmd->add_option("--dump-frame", args.dumpFrame,
                  "K OUT.glb: write frame K's mesh as drawn (0-based)")
      ->expected(2);
  cmd->add_option("--script", args.script,
                  "FILE: keys, drags, wheel steps, screenshots and dumps at given frames "
                  "(docs/cli.md); every frame's status line is printed");
  cmd->add_flag("--wireframe", args.wireframe, "start with the wireframe on (key W)");
  cmd->add_option("--colour", args.colour,
                  "start colouring: shaded, patch, or level (each patch's ⌈log2 max(N_u, N_v)⌉; key C)")
      ->capture_default_str();
  cmd->add_option("--device", args.device, "Vulkan device index or part of its name");
  cmd->add_flag("--validation", args.validation,
                "run with the Khronos validation layer; any message makes the exit code 70");
  cmd->add_flag("-q,--quiet", args.quiet, "print nothing on success");
  cmd->callback([&exitCode] {
    const std::string dumpPath = args.dumpFrame.size() == 2 ? args.dumpFrame[1] : "";
    // run() adds the script's outputs to the list runReportingErrors holds by reference.
    std::vector<std::string> outputs = {args.screenshot, dumpPath};
    exitCode = runReportingErrors([&outputs] { return run(args, outputs); }, outputs,
                                  "view needs a Vulkan device that draws");
  });
}

}  // namespace tessera::cli
