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

constexpr double kMinTolerance = 0.125, kMaxTolerance = 64.0;

struct ViewState {
  bool wireframe = false;
  bool frozen = false;
  Colouring colouring = Colouring::Shaded;
};

const char* colouringName(Colouring c) {
  return c == Colouring::Patch ? "patch" : c == Colouring::Depth ? "level" : "shaded";
}

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

std::string statusLine(double fps, size_t triangles, double errorPixels, double tolerance,
                       const ViewState& s) {
  char line[256];
  std::snprintf(line, sizeof line,
                "%.1f frames/s  %zu triangles  error %.2f px (tolerance %.3g px)  %s%s%s\n"
                "drag turn, wheel zoom, W wires, C colour, +/- tolerance, F freeze, Esc",
                fps, triangles, errorPixels, tolerance, colouringName(s.colouring),
                s.wireframe ? " wire" : "", s.frozen ? "  FROZEN" : "");
  return line;
}

}  // namespace

ViewerReport runViewer(const ViewerOptions& options) {
  const bool scripted = options.frames > 0;
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
  Presenter presenter(context, window, surface.surface, !options.screenshot.empty());
  const VkExtent2D first = presenter.extent();
  const OrbitCamera start =
      OrbitCamera::framing(options.patches, double(first.width) / double(first.height));
  OrbitCamera orbit = start;
  ViewState state;
  state.wireframe = options.wireframe;
  state.colouring = Colouring(options.colouring);

  vk::Buffer meshVertices, overlayVertices;
  std::vector<uint8_t> screenshot;
  ViewerReport report;
  Stopwatch sinceStart, sinceFps, sinceError;
  int framesSinceFps = 0;
  bool fpsWindowDone = false;
  double fps = 0, errorPixels = 0;
  bool measureNow = true;
  for (int frame = 0; !window.closeRequested();) {
    if (window.waitWhileMinimised()) continue;
    const InputEvents input = window.poll();
    for (KeyAction key : input.keys) {
      switch (key) {
        case KeyAction::Wireframe: state.wireframe = !state.wireframe; break;
        case KeyAction::Colour:
          state.colouring = state.colouring == Colouring::Shaded  ? Colouring::Patch
                            : state.colouring == Colouring::Patch ? Colouring::Depth
                                                                  : Colouring::Shaded;
          break;
        case KeyAction::Finer:
        case KeyAction::Coarser: {
          const double factor = key == KeyAction::Finer ? 0.5 : 2.0;
          const double next = source.tolerance() * factor;
          if (next >= kMinTolerance && next <= kMaxTolerance) {
            source.setTolerance(next);
            state.frozen = false;  // the frozen frame belonged to the old tessellator
            measureNow = true;
          }
          break;
        }
        case KeyAction::Freeze: state.frozen = !state.frozen; break;
        case KeyAction::Quit: window.requestClose(); break;
      }
    }
    orbit.drag(input.dragX, input.dragY, int(presenter.extent().width));
    orbit.zoom(input.wheel);
    if (scripted) orbit = orbitPathFrame(start, frame, options.frames);

    const VkExtent2D extent = presenter.extent();
    const Camera camera = orbit.camera(int(extent.width), int(extent.height));
    if (!state.frozen || !source.lastFrame()) source.tessellate(camera);
    const size_t triangles = source.lastFrame()->triangles;
    if (frame == options.dumpFrame && !options.dumpPath.empty())
      writeGlbFile(options.dumpPath, source.lastMesh());
    // The error check re-evaluates every triangle in double: about once a second, and on the
    // scripted path's last frame (the screenshot's).
    const bool lastFrame = scripted && frame == options.frames - 1;
    if (measureNow || lastFrame || sinceError.elapsedSeconds() > 1.0) {
      errorPixels = source.measureError(camera).maxAffinePixels;
      sinceError.restart();
      measureNow = false;
    }

    const uint32_t meshCount = source.writeDrawVertices(state.colouring, meshVertices);
    const std::vector<DrawVertex> text = overlayTriangles(
        statusLine(fps, triangles, errorPixels, source.tolerance(), state),
        extent.width >= 900 ? 2 : 1);
    if (overlayVertices.size() < text.size() * sizeof(DrawVertex))
      overlayVertices = vk::Buffer(context, 2 * text.size() * sizeof(DrawVertex),
                                   vk::BufferUse::Upload, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    overlayVertices.upload(text);
    const std::vector<DrawCall> calls = {
        {meshVertices.handle(), meshCount, meshPush(orbit, camera, state)},
        {overlayVertices.handle(), uint32_t(text.size()),
         overlayPush(int(extent.width), int(extent.height))}};
    const bool wantPicture = lastFrame && !options.screenshot.empty();
    if (!presenter.present(calls, wantPicture ? &screenshot : nullptr))
      continue;  // the window changed size: the same frame again at the new size

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
    if (wantPicture) writePngFile(options.screenshot, screenshot, int(extent.width),
                                  int(extent.height));
    if (scripted && frame == options.frames) break;
  }
  report.framesPerSecond = report.frames / std::max(sinceStart.elapsedSeconds(), 1e-9);
  report.validationMessages = context.validationMessageCount();
  return report;
}

}  // namespace tessera::viewer
