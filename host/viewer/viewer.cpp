#include "viewer/viewer.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "common/stopwatch.h"
#include "io/gltf_writer.h"
#include "io/png_writer.h"
#include "viewer/frame_source.h"
#include "viewer/orbit_camera.h"
#include "viewer/overlay_text.h"
#include "viewer/presenter.h"
#include "viewer/view_state.h"
#include "viewer/window.h"
#include "vk/loader.h"

namespace tessera::viewer {
namespace {

// Owns the window's surface: destroyed before the instance (the context) goes.
struct SurfaceHolder {
  const vk::Context& context;
  VkSurfaceKHR surface;
  ~SurfaceHolder() { destroySurface(context, surface); }
};

gpu::MeshDrawPush meshPush(const OrbitCamera& orbit, const Camera& camera, const ViewState& s) {
  gpu::MeshDrawPush push{};
  const glm::mat4 viewProjection(camera.viewProjection);
  for (int c = 0; c < 4; ++c) push.viewProjection[c] = viewProjection[c];
  push.eye = glm::vec4(glm::vec3(orbit.eye()), 1.0f);
  push.light = glm::vec4(orbit.lightDirection(), 0.2f);  // w: ambient
  push.colourMode = s.colouring == Colouring::Patch   ? gpu::kColourPatch
                    : s.colouring == Colouring::Depth ? gpu::kColourDepth
                                                      : gpu::kColourShaded;
  push.wireframe = s.wireframe ? 1u : 0u;
  push.wireWidth = 1.0f;
  return push;
}

// The log (stdout): "view: frame K: TEXT", flushed so that a reader sees it at once.
void logLine(bool quiet, int frame, const std::string& text) {
  if (quiet) return;
  std::printf("view: frame %d: %s\n", frame, text.c_str());
  std::fflush(stdout);
}

// Orders steps and frame numbers by frame, for std::equal_range.
struct ByFrame {
  bool operator()(const ScriptStep& step, int frame) const { return step.frame < frame; }
  bool operator()(int frame, const ScriptStep& step) const { return frame < step.frame; }
};

}  // namespace

ViewerReport runViewer(const ViewerOptions& options) {
  const bool scripted = options.frames > 0;
  const std::vector<ScriptStep>& script = options.script;
  const int lastStepFrame = script.empty() ? -1 : script.back().frame;
  bool screenshots = !options.screenshot.empty();
  for (const ScriptStep& step : script)
    screenshots = screenshots || step.kind == ScriptStep::Kind::Screenshot;
  Window window(options.width, options.height, options.title);
  vk::ContextOptions contextOptions;
  contextOptions.device = options.device;
  contextOptions.validation = options.validation ? vk::Validation::Required : vk::Validation::Off;
  contextOptions.instanceExtensions = window.requiredInstanceExtensions();
  contextOptions.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  vk::Context context(contextOptions);
  if (!context.queueSupportsGraphics())
    throw vk::VulkanUnavailable("device '" + context.info().name + "' has no queue that draws");
  SurfaceHolder surface{context, window.createSurface(context.instance())};
  if (!queueCanPresent(context, surface.surface))
    throw WindowSystemUnavailable("no window system: device '" + context.info().name +
                                  "' cannot present to this window");

  FrameSource source(context, options.patches, options.tolerancePixels);
  Presenter presenter(context, window, surface.surface, screenshots);
  const VkExtent2D first = presenter.extent();
  const OrbitCamera start =
      OrbitCamera::framing(options.patches, double(first.width) / double(first.height));
  OrbitCamera orbit = start;  // where the mouse has put it
  ViewState state;
  state.wireframe = options.wireframe;
  state.colouring = Colouring(options.colouring);
  state.tolerancePixels = options.tolerancePixels;

  vk::Buffer meshVertices, overlayVertices;
  std::vector<uint8_t> screenshot;
  ViewerReport report;
  Stopwatch sinceStart, sinceFps, sinceError;
  int framesSinceFps = 0;
  bool fpsWindowDone = false;
  double fps = 0, errorPixels = 0;
  bool measureNow = true;
  int injectedFrame = -1;  // a frame drawn again after a resize takes its steps once
  for (int frame = 0; !window.closeRequested();) {
    if (window.waitWhileMinimised()) continue;
    const auto [firstStep, lastStep] = std::equal_range(script.begin(), script.end(), frame,
                                                        ByFrame());
    if (injectedFrame != frame) {
      for (auto step = firstStep; step != lastStep; ++step) {
        if (step->kind == ScriptStep::Kind::Key) window.injectKey(step->glfwKey);
        if (step->kind == ScriptStep::Kind::Drag) window.injectDrag(step->x, step->y);
        if (step->kind == ScriptStep::Kind::Wheel) window.injectWheel(step->x);
      }
      injectedFrame = frame;
    }
    const InputEvents input = window.poll();
    for (KeyAction key : input.keys) logLine(options.quiet, frame, applyKey(key, state));
    if (state.quit) window.requestClose();
    if (state.tolerancePixels != source.tolerance()) {
      source.setTolerance(state.tolerancePixels);
      measureNow = true;
    }
    if (!script.empty() && (input.dragX != 0 || input.dragY != 0 || input.wheel != 0)) {
      char moved[96];
      std::snprintf(moved, sizeof moved, "drag %g %g, wheel %g", input.dragX, input.dragY,
                    input.wheel);
      logLine(options.quiet, frame, moved);
    }
    orbit.drag(input.dragX, input.dragY, int(presenter.extent().width));
    orbit.zoom(input.wheel);
    const OrbitCamera view = scripted ? orbitPathFrame(orbit, frame, options.frames) : orbit;

    const VkExtent2D extent = presenter.extent();
    const Camera camera = view.camera(int(extent.width), int(extent.height));
    if (!state.frozen || !source.lastFrame()) source.tessellate(camera);
    const size_t triangles = source.lastFrame()->triangles;
    // The error check re-evaluates every triangle in double: about once a second, on the
    // scripted path's last frame (the screenshot's), and every frame of a script (its log).
    const bool lastFrame = scripted && frame == options.frames - 1;
    if (measureNow || lastFrame || !script.empty() || sinceError.elapsedSeconds() > 1.0) {
      errorPixels = source.measureError(camera).maxAffinePixels;
      sinceError.restart();
      measureNow = false;
    }

    const uint32_t meshCount = source.writeDrawVertices(state.colouring, meshVertices);
    const std::string status = statusLine(fps, triangles, errorPixels, state);
    const std::vector<DrawVertex> text = overlayTriangles(
        status + "\ndrag turn, wheel zoom, W wires, C colour, +/- tolerance, F freeze, Esc",
        extent.width >= 900 ? 2 : 1);
    if (overlayVertices.size() < text.size() * sizeof(DrawVertex))
      overlayVertices = vk::Buffer(context, 2 * text.size() * sizeof(DrawVertex),
                                   vk::BufferUse::Upload, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    overlayVertices.upload(text);
    const std::vector<DrawCall> calls = {
        {meshVertices.handle(), meshCount, meshPush(view, camera, state)},
        {overlayVertices.handle(), uint32_t(text.size()),
         overlayPush(int(extent.width), int(extent.height))}};
    bool wantPicture = lastFrame && !options.screenshot.empty();
    for (auto step = firstStep; step != lastStep; ++step)
      wantPicture = wantPicture || step->kind == ScriptStep::Kind::Screenshot;
    if (!presenter.present(calls, wantPicture ? &screenshot : nullptr))
      continue;  // the window changed size: the same frame again at the new size

    if (!script.empty()) logLine(options.quiet, frame, status);
    if (frame == options.dumpFrame && !options.dumpPath.empty())
      writeGlbFile(options.dumpPath, source.lastMesh());
    if (lastFrame && !options.screenshot.empty())
      writePngFile(options.screenshot, screenshot, int(extent.width), int(extent.height));
    for (auto step = firstStep; step != lastStep; ++step) {
      if (step->kind == ScriptStep::Kind::Screenshot)
        writePngFile(step->word, screenshot, int(extent.width), int(extent.height));
      if (step->kind == ScriptStep::Kind::Dump) writeGlbFile(step->word, source.lastMesh());
    }

    ++frame;
    ++framesSinceFps;
    if (sinceFps.elapsedSeconds() >= 0.5) {  // frames/s over the last half second
      fps = framesSinceFps / sinceFps.elapsedSeconds();
      framesSinceFps = 0;
      sinceFps.restart();
      fpsWindowDone = true;
    } else if (!fpsWindowDone) {  // the first half second: the mean so far
      fps = frame / std::max(sinceStart.elapsedSeconds(), 1e-9);
    }
    report.frames = frame;
    report.lastTriangles = triangles;
    report.lastErrorPixels = errorPixels;
    if (scripted ? frame == options.frames : frame == lastStepFrame + 1) break;
  }
  report.framesPerSecond = report.frames / std::max(sinceStart.elapsedSeconds(), 1e-9);
  report.validationMessages = context.validationMessageCount();
  return report;
}

}  // namespace tessera::viewer
