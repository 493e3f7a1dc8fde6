// tessera::Tessellator (include/tessera/tessera.h): owns the backend (a Vulkan context or the
// CPU mirror) and turns the library's exceptions into the public ones.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "api/convert.h"
#include "api/public_errors.h"
#include "api/tessellator_access.h"
#include "common/thread_cap.h"
#include "division/count.h"
#include "eval/patch_set.h"
#include "geometry/rational.h"
#include "mesh/screen_tolerance.h"
#include "mesh/tessellate.h"
#include "quadtree/tolerance.h"
#include "trim/trim_classifier.h"
#include "vk/context.h"
#include "vk/errors.h"

namespace tessera {
namespace {

// Rule A with each patch's grid from Filip's bound at `tolerance` (host/division/count.h), the
// grids made watertight across patches by meshFromTree (as bench/bench_occt.cpp's countedGrids).
Tessellation countedGrids(const std::vector<BezierPatch>& patches, double tolerance,
                          int maxPerDirection, size_t maxNodes, Backend& backend,
                          double& largestBound) {
  for (size_t i = 0; i < patches.size(); ++i)
    validateTessellationPatch(patches[i], "patch " + std::to_string(i));
  // Counted and meshed in the local frame, as tessellate() works (model_frame.h).
  const ModelFrame frame = modelFrame(patches);
  std::vector<BezierPatch> local = toLocalFrame(patches, frame);
  DivisionOptions counting;
  counting.tolerance = tolerance / frame.scale;
  counting.maxPerDirection = maxPerDirection;
  QuadtreeOptions grid;
  grid.rule = SplitRule::UniformGrid;
  PatchSet set = toPatchSet(local);
  QuadtreeResult tree;
  size_t cells = 0;
  largestBound = 0;
  for (size_t p = 0; p < local.size(); ++p) {
    const Divisions d = patchDivisions(toRationalPatch(local[p]), counting);
    if (d.status == DivisionStatus::Unbounded)
      throw std::invalid_argument("patch " + std::to_string(p) +
                                  ": its weights vanish on the patch, so the surface runs off "
                                  "to infinity and no uniform grid is within any tolerance");
    if (d.status == DivisionStatus::Capped)
      throw LimitError("tolerance " + std::to_string(tolerance) + ": patch " + std::to_string(p) +
                       " needs more than maxPerDirection = " + std::to_string(maxPerDirection) +
                       " cells a side (" + std::to_string(d.realU) + " x " +
                       std::to_string(d.realV) + ")");
    // Filip's bound of the grid (docs/rational_division.md), local units → model units.
    const double nu = d.nu, nv = d.nv;
    largestBound = std::max(largestBound, frame.scale *
                                              (d.bounds.uu / (nu * nu) +
                                               2.0 * d.bounds.uv / (nu * nv) +
                                               d.bounds.vv / (nv * nv)) / 8.0);
    cells += size_t(d.nu) * size_t(d.nv);
    if (cells > maxNodes)
      throw LimitError("tolerance " + std::to_string(tolerance) + ": the grids reach " +
                       std::to_string(cells) + " cells by patch " + std::to_string(p) +
                       ", more than " + std::to_string(maxNodes));
    grid.gridU = d.nu;
    grid.gridV = d.nv;
    // One patch's tree at a time (each has its own grid), renumbered to its place.
    QuadtreeResult one = buildQuadtree(set.subset(p, p + 1), grid, *backend.classifier);
    for (QuadLeaf leaf : one.leaves) {
      leaf.patchIndex = uint32_t(p);
      tree.leaves.push_back(leaf);
    }
    tree.depth = std::max(tree.depth, one.depth);
  }
  return meshFromTree(std::move(local), std::move(set), std::move(tree), *backend.evaluator, frame);
}

using api::translatingErrors;

// What rule T's tree proves (Mesh::proof): its largest leaf bound in model units; a leaf
// fanned off its one diagonal holds only its any-triangle bound, so it proves nothing.
ToleranceProof treeProof(const Tessellation& t, double tolerance) {
  const double bound = largestLeafBound(t.tree);
  return {tolerance, bound, bound <= tolerance && t.stats.diagonalFans == 0};
}

// In pixels: over the leaves in view; culled leaves are unseen, eye-plane ones unproven.
ToleranceProof screenProof(const Tessellation& t, double pixels) {
  const ScreenLeafCounts counts = screenLeafCounts(t.tree);
  return {pixels, counts.largestBound,
          counts.largestBound <= pixels && counts.eyePlane == 0 && t.stats.diagonalFans == 0};
}

}  // namespace

struct Tessellator::Impl {
  TessellatorOptions options;
  std::unique_ptr<vk::Context> context;  // null on the CPU
  Backend backend;
  std::unique_ptr<TrimClassifier> trim;  // on Vulkan, made at the first CAD call

  // On an engine's device (tessera/vulkan.h): no device of its own, no CPU start.
  Impl(const TessellatorOptions& o, const vk::ExternalDevice& device) : options(o) {
    if (options.device == Device::Cpu || !options.deviceName.empty())
      throw std::invalid_argument(
          "tessellatorOnDevice: the device is the one lent; TessellatorOptions::device must be "
          "Auto or Vulkan and deviceName empty");
    const ScopedThreadCap cap(options.threads);
    context = std::make_unique<vk::Context>(device);
    backend = makeVulkanBackend(*context);
  }

  explicit Impl(const TessellatorOptions& o) : options(o) {
    const ScopedThreadCap cap(options.threads);  // the device's setup too
    if (options.device == Device::Cpu) {
      backend = makeMirrorBackend();
      return;
    }
    try {
      vk::ContextOptions contextOptions;
      contextOptions.device = options.deviceName;
      context = std::make_unique<vk::Context>(contextOptions);
      backend = makeVulkanBackend(*context);
    } catch (const vk::VulkanUnavailable&) {
      if (options.device == Device::Vulkan) throw;
      useCpu();
    } catch (const vk::VulkanError&) {  // the device failed while being set up
      if (options.device == Device::Vulkan) throw;
      useCpu();
    }
  }

  void useCpu() {
    backend = makeMirrorBackend();  // drops the Vulkan classifier and evaluator first
    trim.reset();
    context.reset();
  }

  // `run(backend)`; under Device::Auto a Vulkan failure moves to the CPU and runs it again.
  template <class Run>
  decltype(auto) withFallback(Run&& run) {
    try {
      return run(backend);
    } catch (const vk::VulkanError&) {
      if (options.device != Device::Auto || !context) throw;
      useCpu();
      return run(backend);
    }
  }
};

Tessellator::Tessellator(const TessellatorOptions& options)
    : impl_(translatingErrors([&] { return std::make_unique<Impl>(options); })) {}
Tessellator::Tessellator(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Tessellator::~Tessellator() = default;
Tessellator::Tessellator(Tessellator&&) noexcept = default;
Tessellator& Tessellator::operator=(Tessellator&&) noexcept = default;

bool Tessellator::usesVulkan() const { return impl_->context != nullptr; }

std::string Tessellator::deviceName() const {
  return impl_->context ? impl_->context->info().name : "cpu";
}

Tessellator TessellatorAccess::onDevice(const vk::ExternalDevice& device,
                                        const TessellatorOptions& options) {
  return Tessellator(
      translatingErrors([&] { return std::make_unique<Tessellator::Impl>(options, device); }));
}

void TessellatorAccess::run(Tessellator& tessellator,
                            const std::function<void(Backend&, vk::Context*)>& work) {
  Tessellator::Impl& impl = *tessellator.impl_;
  const ScopedThreadCap cap(impl.options.threads);
  // The context is read at each try: after a fallback it is null (the CPU).
  translatingErrors([&] {
    impl.withFallback([&](Backend& backend) { work(backend, impl.context.get()); });
  });
}

TrimClassifier* TessellatorAccess::trimClassifier(Tessellator& tessellator) {
  Tessellator::Impl& impl = *tessellator.impl_;
  if (!impl.context) return nullptr;
  if (!impl.trim) impl.trim = makeVulkanTrimClassifier(*impl.context);
  return impl.trim.get();
}

Mesh Tessellator::tessellate(const std::vector<Patch>& patches, const RuleOptions& options) {
  const ScopedThreadCap cap(impl_->options.threads);
  const std::vector<BezierPatch> internal = api::toBezierPatches(patches);
  const QuadtreeOptions quadtree = api::toQuadtreeOptions(options);
  return translatingErrors([&] {
    Tessellation t = impl_->withFallback(
        [&](Backend& backend) { return tessera::tessellate(internal, quadtree, backend); });
    Mesh mesh = api::toMesh(std::move(t.mesh));
    if (quadtree.rule == SplitRule::Tolerance) mesh.proof = treeProof(t, quadtree.tolerance);
    return mesh;
  });
}

Mesh Tessellator::tessellateToTolerance(const std::vector<Patch>& patches, double tolerance,
                                        const ToleranceOptions& options) {
  const ScopedThreadCap cap(impl_->options.threads);
  if (!std::isfinite(tolerance) || !(tolerance > 0))
    throw ArgumentError("the tolerance must be finite and > 0, got " + std::to_string(tolerance));
  static_assert(ToleranceOptions{}.maxDepth == kToleranceMaxDepth,
                "the public default depth of rule T is the library's");
  if (options.method == ToleranceMethod::Adaptive) {
    RuleOptions adaptive;
    adaptive.rule = Rule::T;
    adaptive.tolerance = tolerance;
    adaptive.maxDepth = options.maxDepth;
    adaptive.maxNodes = options.maxNodes;
    return tessellate(patches, adaptive);
  }
  if (options.method != ToleranceMethod::UniformGrids)
    throw ArgumentError("unknown tolerance method " + std::to_string(int(options.method)));
  // Rule A's grids take at most 4096 cells per side (quadtree.h).
  const int maxPerDirection = options.maxPerDirection;
  if (maxPerDirection < 1 || maxPerDirection > 4096)
    throw ArgumentError("maxPerDirection must be 1..4096, got " + std::to_string(maxPerDirection));
  const std::vector<BezierPatch> internal = api::toBezierPatches(patches);
  return translatingErrors([&] {
    double largestBound = 0;
    Mesh mesh = api::toMesh(impl_
                                ->withFallback([&](Backend& backend) {
                                  return countedGrids(internal, tolerance, maxPerDirection,
                                                      options.maxNodes, backend, largestBound);
                                })
                                .mesh);
    // Each grid's counts solve its bound = tolerance and are rounded up (a capped or unbounded
    // grid threw above), so the grids are proven by construction; the bound is as computed.
    mesh.proof = ToleranceProof{tolerance, largestBound, true};
    return mesh;
  });
}

View lookAtView(const std::array<double, 3>& eye, const std::array<double, 3>& target,
                const std::array<double, 3>& up, double fovYDegrees, int width, int height,
                double nearDistance, double farDistance) {
  const glm::dvec3 from(eye[0], eye[1], eye[2]), to(target[0], target[1], target[2]);
  if (!(glm::length(to - from) > 0.0)) throw ArgumentError("lookAtView: the eye is on the target");
  if (!(fovYDegrees > 0.0 && fovYDegrees < 179.0))
    throw ArgumentError("lookAtView: the field of view must be in (0, 179) degrees");
  const Camera camera = translatingErrors([&] {
    return lookAtCamera(from, to, glm::dvec3(up[0], up[1], up[2]), glm::radians(fovYDegrees), width,
                        height, nearDistance, farDistance);
  });
  View view;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      view.viewProjection[size_t(4 * c + r)] = camera.viewProjection[c][r];
  view.width = width;
  view.height = height;
  return view;
}

Mesh Tessellator::tessellateToPixelTolerance(const std::vector<Patch>& patches, double pixels,
                                             const View& view, const ToleranceOptions& options) {
  const ScopedThreadCap cap(impl_->options.threads);
  if (!std::isfinite(pixels) || !(pixels > 0))
    throw ArgumentError("the pixel tolerance must be finite and > 0, got " +
                        std::to_string(pixels));
  if (options.method != ToleranceMethod::Adaptive)
    throw ArgumentError("a pixel tolerance takes ToleranceMethod::Adaptive only");
  ScreenView screen;
  screen.camera = api::toCamera(view);
  QuadtreeOptions quadtree = toleranceOptions(pixels);
  quadtree.maxDepth = options.maxDepth;
  quadtree.nodeBudget = options.maxNodes;
  const std::vector<BezierPatch> internal = api::toBezierPatches(patches);
  return translatingErrors([&] {
    Tessellation t = impl_->withFallback([&](Backend& backend) {
      return tessellateScreenTolerance(internal, quadtree, screen, backend);
    });
    Mesh mesh = api::toMesh(std::move(t.mesh));
    mesh.proof = screenProof(t, pixels);
    return mesh;
  });
}

Mesh tessellateFile(const std::string& path, const RuleOptions& options,
                    const TessellatorOptions& device) {
  std::vector<Patch> patches = loadPatches(path);
  return Tessellator(device).tessellate(patches, options);
}

}  // namespace tessera
