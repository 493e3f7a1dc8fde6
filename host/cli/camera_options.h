// The camera of a pixel tolerance (`--tolerance 1px`): --view (eye, target, field of view) or
// --view-projection (a 4×4 clip-from-world matrix, Vulkan conventions), and --viewport.
#pragma once
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "division/view_dependent.h"

namespace tessera::cli {

struct CameraArgs {
  std::string view;            // "ex,ey,ez,tx,ty,tz[,fovDegrees]"
  std::string viewProjection;  // 16 numbers, column-major (glm's and GLSL's order)
  std::string viewport = "1920x1080";
  bool given() const { return !view.empty() || !viewProjection.empty(); }
};

void addCameraOptions(CLI::App* cmd, CameraArgs& args);

// The camera the options describe, or nothing when neither --view nor --view-projection is
// given. Throws CLI::ValidationError naming the option for malformed numbers, both options at
// once, an eye on its target, a field of view outside (0°, 179°) or a viewport outside
// 1..16384 pixels a side. --view looks from the eye at the target with +z up (+y when looking
// along z), near = 0.001 and far = 1000 times the eye–target distance.
std::optional<Camera> parseCamera(const CameraArgs& args);

}  // namespace tessera::cli
