// `tessera view`: a window showing the real-time tessellation of a scene (host/realtime/),
// re-made every frame for the orbit camera. Interactive, or scripted for tests and pictures:
// a fixed number of frames along the orbit path, a screenshot of the last, a frame's mesh to
// a .glb. docs/cli.md describes the keys and options.
#pragma once
#include <string>
#include <vector>

#include "geometry/patch.h"
#include "viewer/input_script.h"

namespace tessera::viewer {

struct ViewerOptions {
  std::vector<BezierPatch> patches;
  std::string title = "tessera view";
  int width = 960, height = 540;
  double tolerancePixels = 1.0;
  std::string device;       // as --device elsewhere
  bool validation = false;  // Khronos validation required; every message is counted
  // Scripted: `frames` > 0 frames along the orbit path (turning the camera the mouse has
  // set), then exit (the keys still work).
  int frames = 0;
  // Input and pictures at given frames (viewer/input_script.h), steps below `frames` when it
  // is set; without `frames` the run ends after the last step's frame. Each key's effect,
  // each scripted drag and wheel step, and every frame's status line are printed.
  std::vector<ScriptStep> script;
  std::string screenshot;  // the last frame as PNG ("" = none); needs frames > 0
  int dumpFrame = -1;      // this frame's mesh (0-based) ...
  std::string dumpPath;    // ... as .glb
  bool wireframe = false;
  int colouring = 0;  // Colouring (viewer/frame_source.h) to start with: 0 shaded, 1 patch, 2 level
  bool quiet = false;  // nothing printed, not even the keys' effects
};

struct ViewerReport {
  int frames = 0;
  size_t lastTriangles = 0;
  double framesPerSecond = 0;
  double lastErrorPixels = 0;   // the last measured error (affine, the counts' guarantee)
  size_t validationMessages = 0;
};

// Runs until Esc, the window is closed, or the scripted frames are done. Throws
// WindowSystemUnavailable (viewer/window.h) without a window system, VulkanUnavailable
// without a device that draws, VulkanError when the device fails, InputError when a file
// cannot be written, std::invalid_argument for patches the real-time path does not take.
ViewerReport runViewer(const ViewerOptions& options);

}  // namespace tessera::viewer
