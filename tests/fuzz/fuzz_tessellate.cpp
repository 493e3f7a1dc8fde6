// libFuzzer target: tessellate() on the CPU backend with one or two small bicubic patches and
// fuzzed options. Coordinates come either from small integers (many repeated points:
// collapsed edges, cusps, folds, flat and degenerate nets), which must tessellate into a
// finite mesh whose every leaf records its cause, or from raw doubles (NaN, 1e300, ...),
// which tessellate() may refuse with std::invalid_argument as documented. The node budget is
// small so runaway refinement shows up as TessellationLimitError, never as a slow input.
#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz_checks.h"
#include "mesh/tessellate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace tessera;
  static Backend cpu = makeMirrorBackend();
  FuzzedDataProvider input(data, size);
  QuadtreeOptions options;
  const SplitRule rules[] = {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax};
  options.rule = rules[input.ConsumeIntegralInRange(0, 2)];
  options.maxDepth = input.ConsumeIntegralInRange(0u, 6u);
  options.linearity = input.ConsumeFloatingPointInRange(0.001f, 1.0f);
  options.flatness = input.ConsumeFloatingPointInRange(0.001f, 1.0f);
  options.samples = input.ConsumeIntegralInRange(1, 6);
  options.nodeBudget = 20000;
  const bool rawDoubles = input.ConsumeBool();
  std::vector<BezierPatch> patches(input.ConsumeIntegralInRange(1, 2));
  for (BezierPatch& p : patches) {
    p.cp.resize(16);
    for (glm::dvec3& c : p.cp)
      for (int k = 0; k < 3; ++k)
        c[k] = rawDoubles ? input.ConsumeFloatingPoint<double>()
                          : input.ConsumeIntegralInRange(-8, 8) / 4.0;
  }
  Tessellation t;
  try {
    t = tessellate(patches, options, cpu);
  } catch (const TessellationLimitError&) {
    return 0;
  } catch (const std::invalid_argument&) {
    if (rawDoubles) return 0;
    throw;  // small integer coordinates are always valid input
  }
  t.mesh.validate();  // throws (a crash here) on NaN or out-of-range indices
  for (const QuadLeaf& leaf : t.tree.leaves) {
    fuzz::expect(leaf.cause != gpu::kCauseSplit);
    fuzz::expect(leaf.level <= options.maxDepth);
  }
  return 0;
}
