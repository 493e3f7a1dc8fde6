// Adaptive quad-tree throughput: leaves per second for the scalar CPU (the fp32 mirror on one
// thread), the CPU on all cores, and Vulkan, on the same teapots, in one run; then where the
// Vulkan run's time goes, level by level.
// Usage: bench_quadtree [instancesB=1000] [instancesD=100] [threshold=0.05]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <thread>

#include "evaluator.h"
#include "io/bpt_reader.h"
#include "quadtree.h"
#include "vk/context.h"

using namespace tessera;

namespace {

// `count` copies of the teapot, each moved and bent by its own smooth deformation field, so
// no two are identical while coincident control points (collapsed edges, shared boundaries)
// stay coincident: independent jitter would turn the lid's collapsed edge into a crinkle that
// never tests flat.
std::vector<gpu::BicubicPatch> teapots(const std::vector<gpu::BicubicPatch>& teapot, int count) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> phase(0.0f, 6.2831853f);
  std::vector<gpu::BicubicPatch> out;
  out.reserve(teapot.size() * count);
  for (int c = 0; c < count; ++c) {
    gpu::vec4 offset(float(c % 40) * 8.0f, float(c / 40) * 8.0f, 0.0f, 0.0f);
    float a = phase(rng), b = phase(rng), d = phase(rng);
    for (gpu::BicubicPatch p : teapot) {
      for (auto& cp : p.cp) {
        gpu::vec4 bend(0.02f * std::sin(1.3f * cp.y + a), 0.02f * std::sin(1.1f * cp.z + b),
                       0.02f * std::sin(0.9f * cp.x + d), 0.0f);
        cp += offset + bend;
      }
      out.push_back(p);
    }
  }
  return out;
}

struct Run {
  QuadtreeResult result;
  double seconds;
};

Run timed(const std::vector<gpu::BicubicPatch>& patches, const QuadtreeOptions& o,
          NodeClassifier& c) {
  auto start = std::chrono::steady_clock::now();
  Run r{buildQuadtree(patches, o, c), 0};
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void benchRule(SplitRule rule, int instances, float threshold,
               const std::vector<gpu::BicubicPatch>& teapot, vk::Context& context) {
  auto patches = teapots(teapot, instances);
  QuadtreeOptions o;
  o.rule = rule;
  o.linearity = o.flatness = threshold;
  auto scalar = makeMirrorClassifier();
  auto parallel = makeParallelMirrorClassifier();
  auto vulkan = makeVulkanClassifier(context);
  // Warm up the Vulkan pipeline (lavapipe compiles it on first use) on one teapot.
  buildQuadtree(teapots(teapot, 1), o, *vulkan);

  Run s = timed(patches, o, *scalar);
  Run p = timed(patches, o, *parallel);
  Run v = timed(patches, o, *vulkan);
  if (s.result.leaves.size() != v.result.leaves.size() ||
      p.result.leaves.size() != v.result.leaves.size())
    std::printf("WARNING: leaf counts differ: scalar %zu, parallel %zu, vulkan %zu\n",
                s.result.leaves.size(), p.result.leaves.size(), v.result.leaves.size());
  double leaves = double(v.result.leaves.size());
  std::printf("\n## rule %c, linearity = flatness = %.2f, teapot x%d (%zu patches): %zu leaves, depth %u\n\n",
              splitRuleLetter(rule), threshold, instances, patches.size(),
              v.result.leaves.size(), v.result.depth);
  std::printf("| path | seconds | leaves/s | ratio to scalar CPU |\n|---|---|---|---|\n");
  std::printf("| scalar CPU (fp32 mirror, 1 thread) | %.3f | %.3g | 1.00 |\n", s.seconds,
              leaves / s.seconds);
  std::printf("| CPU, all %u cores | %.3f | %.3g | %.2f |\n", std::thread::hardware_concurrency(),
              p.seconds, leaves / p.seconds, s.seconds / p.seconds);
  std::printf("| Vulkan (%s) | %.3f | %.3g | %.2f |\n", context.info().name.c_str(), v.seconds,
              leaves / v.seconds, s.seconds / v.seconds);
  std::printf("\nVulkan run by level (classify = upload + dispatch + readback; GPU = timestamps; "
              "frontier = host work on leaves and children):\n\n");
  std::printf("| level | nodes | splits | leaves | classify ms | GPU ms | frontier ms |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const LevelStats& l : v.result.levels)
    std::printf("| %u | %zu | %zu | %zu | %.1f | %.1f | %.1f |\n", l.level, l.nodes, l.splits,
                l.leaves, l.classifyMs, l.gpuMs, l.frontierMs);
}

}  // namespace

int main(int argc, char** argv) {
  int instancesB = argc > 1 ? std::atoi(argv[1]) : 1000;
  int instancesD = argc > 2 ? std::atoi(argv[2]) : 100;
  float threshold = argc > 3 ? float(std::atof(argv[3])) : 0.05f;
  auto teapot = toGpuPatches(readBpt(TESSERA_BENCH_DATA "/teapot.bpt"));
  vk::ContextOptions options;
  vk::Context context(options);
  std::printf("bench_quadtree on %s (%s)\n", context.info().name.c_str(),
              context.info().driverInfo.c_str());
  benchRule(SplitRule::Midpoint, instancesB, threshold, teapot, context);
  benchRule(SplitRule::TrueMax, instancesD, threshold, teapot, context);
  return 0;
}
