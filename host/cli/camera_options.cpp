#include "cli/camera_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace tessera::cli {
namespace {

// Comma-separated finite numbers; throws naming `option` for anything else.
std::vector<double> numberList(const std::string& text, const std::string& option) {
  std::vector<double> numbers;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(value))
      throw CLI::ValidationError(option, "'" + item + "' in '" + text + "' is not a finite number");
    numbers.push_back(value);
    start = comma + 1;
  }
  return numbers;
}

}  // namespace

void addCameraOptions(CLI::App* cmd, CameraArgs& args) {
  cmd->add_option("--view", args.view,
                  "camera of a pixel tolerance: EX,EY,EZ,TX,TY,TZ[,FOV] looks from the eye at "
                  "the target, +z up, FOV vertical degrees (default 45)");
  cmd->add_option("--view-projection", args.viewProjection,
                  "camera of a pixel tolerance as 16 numbers, the clip-from-world matrix "
                  "column-major (Vulkan clip space: -w <= x, y <= w, 0 <= z <= w)");
  cmd->add_option("--viewport", args.viewport, "viewport of the camera in pixels, WxH")
      ->capture_default_str();
}

std::optional<Camera> parseCamera(const CameraArgs& args) {
  if (!args.given()) return std::nullopt;
  if (!args.view.empty() && !args.viewProjection.empty())
    throw CLI::ValidationError("--view", "give --view or --view-projection, not both");
  int width = 0, height = 0;
  char extra = 0;
  if (std::sscanf(args.viewport.c_str(), "%dx%d%c", &width, &height, &extra) != 2 || width < 1 ||
      height < 1 || width > 16384 || height > 16384)
    throw CLI::ValidationError("--viewport",
                               "expected WxH with each in 1..16384, got '" + args.viewport + "'");
  if (!args.viewProjection.empty()) {
    const std::vector<double> m = numberList(args.viewProjection, "--view-projection");
    if (m.size() != 16)
      throw CLI::ValidationError("--view-projection",
                                 "expected 16 numbers, got " + std::to_string(m.size()));
    Camera camera;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) camera.viewProjection[c][r] = m[size_t(4 * c + r)];
    camera.width = width;
    camera.height = height;
    return camera;
  }
  const std::vector<double> v = numberList(args.view, "--view");
  if (v.size() != 6 && v.size() != 7)
    throw CLI::ValidationError(
        "--view", "expected EX,EY,EZ,TX,TY,TZ[,FOV], got " + std::to_string(v.size()) + " numbers");
  const glm::dvec3 eye(v[0], v[1], v[2]), target(v[3], v[4], v[5]);
  const double fov = v.size() == 7 ? v[6] : 45.0;
  const double distance = glm::length(target - eye);
  if (!(distance > 0.0)) throw CLI::ValidationError("--view", "the eye is on the target");
  if (!(fov > 0.0 && fov < 179.0))
    throw CLI::ValidationError("--view", "the field of view must be in (0, 179) degrees");
  const glm::dvec3 look = (target - eye) / distance;
  const glm::dvec3 up = std::abs(look.z) > 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  return lookAtCamera(eye, target, up, glm::radians(fov), width, height, 1e-3 * distance,
                      1e3 * distance);
}

}  // namespace tessera::cli
