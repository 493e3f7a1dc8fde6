// Case 6, the fixed-function peer: the scene of case 5 (100 perturbed teapots) drawn through
// Vulkan tessellation shaders (host/realtime/tess_shader_peer.h: per-edge factors from the screen-space
// chord rule, tolerance 1 px, factor ≤ 64) at 1920×1080, along a camera path circling the
// scene; every frame tessellates from scratch. Frames per second and triangles per second.
// Usage: bench_tess_shader [frames=300] [teapots=100] [tolerancePx=1] [--json file]
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "bench_args.h"
#include "bench_report.h"
#include "bench_scenes.h"
#include "common/stopwatch.h"
#include "eval/evaluator.h"
#include "io/bpt_reader.h"
#include "realtime/tess_shader_peer.h"
#include "vk/context.h"

using namespace tessera;

int main(int argc, char** argv) {
  bench::Report report("bench_tess_shader",
                       "[frames=300] [teapots=100] [tolerancePx=1] [--json file]", argc, argv);
  bench::atMostArguments(report, argc, argv, 3);
  int frames = argc > 1 ? int(bench::integerArg(report, argv[1], "frames", 1, 1000000)) : 300;
  int teapots = argc > 2 ? int(bench::integerArg(report, argv[2], "teapots", 1, 100000)) : 100;
  float tolerance = argc > 3 ? float(bench::numberArg(report, argv[3], "tolerancePx", 1e-3)) : 1.0f;
  // 100 teapots as a 10 × 10 block.
  int perRow = std::max(1, int(std::lround(std::sqrt(double(teapots)))));
  auto patches = bench::perturbedCopies(readBpt(TESSERA_BENCH_DATA "/teapot.bpt"), teapots, perRow);
  glm::dvec3 lo(1e30), hi(-1e30);
  for (auto& p : patches)
    for (auto& c : p.cp) {
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
    }
  vk::ContextOptions options;
  vk::Context context(options);
  report.setDevice(context);
  TessPeerOptions o{1920, 1080, tolerance, 64.0f};
  TessShaderPeer peer(context, toGpuPatches(patches), o);

  glm::vec3 centre = glm::vec3(0.5 * (lo + hi));
  float radius = 0.5f * float(glm::length(hi - lo));
  auto camera = [&](int frame) {  // circles the scene, dipping closer and further
    float t = 6.2831853f * float(frame) / float(frames);
    float distance = radius * (1.3f + 0.5f * std::sin(2.0f * t));
    glm::vec3 eye = centre + glm::vec3(distance * std::cos(t), distance * std::sin(t), 0.5f * radius);
    return glm::perspectiveRH_ZO(glm::radians(45.0f), 1920.0f / 1080.0f, 0.05f, 10.0f * radius) *
           glm::lookAtRH(eye, centre, glm::vec3(0, 0, 1));
  };
  peer.drawFrame(camera(0));  // warm-up: pipeline compile, first touch of the targets
  std::vector<double> seconds;
  double triangles = 0;
  const Stopwatch stopwatch;
  for (int f = 0; f < frames; ++f) {
    const Stopwatch frameStopwatch;
    triangles += double(peer.drawFrame(camera(f)));
    seconds.push_back(frameStopwatch.elapsedSeconds());
  }
  double total = stopwatch.elapsedSeconds();
  std::sort(seconds.begin(), seconds.end());
  bench::Timing perFrame{seconds.front(), seconds[seconds.size() / 2], frames};

  char title[200];
  std::snprintf(title, sizeof title,
                "tessellation shaders, %d teapots (%zu patches), %d-frame camera path at 1920x1080, "
                "tolerance %.2g px, max factor 64 (times per frame)",
                teapots, patches.size(), frames, tolerance);
  bench::Table& table = report.table("tessellation shaders", "frames", title);
  table.rateUnit = "frames/s";
  bench::Case c{"Vulkan tessellation shaders (" + context.info().name + ")", double(frames),
                perFrame};
  c.throughput = frames / total;
  c.extra = {{"teapots", teapots},
             {"patches", patches.size()},
             {"trianglesPerFrame", peer.countsTriangles() ? triangles / frames : -1.0},
             {"trianglesPerSecond", peer.countsTriangles() ? triangles / total : -1.0},
             {"tolerancePixels", tolerance}};
  table.cases.push_back(c);
  report.print(table);
  if (peer.countsTriangles())
    std::printf("\n%.0f triangles per frame on average, %.3g triangles/s\n", triangles / frames,
                triangles / total);
  report.finish();
  return 0;
}
