// Tessera's public API: free-form surfaces in, triangle meshes out, as plain arrays.
//
//   #include <tessera/tessera.h>
//   tessera::Tessellator tessellator;                        // Vulkan if usable, else the CPU
//   tessera::Mesh mesh = tessellator.tessellate(tessera::loadPatches("teapot.bpt"));
//   // mesh.positions: x y z per vertex, mesh.indices: three per triangle
//
// Everything here is plain C++17 and the standard library: no Vulkan, glm or internal types.
// Errors are exceptions derived from tessera::Error (tessera/errors.h). docs/api.md.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/errors.h"

namespace tessera {

// The library's version, "major.minor.patch".
const char* version();

// One tensor-product Bézier patch of degree 1..7 each way, polynomial or rational.
struct Patch {
  int degreeU = 3;
  int degreeV = 3;
  // (degreeU+1)·(degreeV+1) control points as x y z triples, b_ij at 3·(i·(degreeV+1) + j),
  // i along u (the order of .bpt files; docs/conventions.md).
  std::vector<double> points;
  // Empty: polynomial. Else one weight per control point, same order (weights ≥ 0, corner
  // weights > 0): the patch is Σ B w b / Σ B w.
  std::vector<double> weights;
};

// Reads a surface file by extension: .bpt (Bézier patches), .grid (points, interpolated by
// bicubic patches), .json (a scene of Bézier, rational and B-spline surfaces, B-splines split
// into their Bézier pieces; docs/scene_format.md). Throws InputError naming file and line.
std::vector<Patch> loadPatches(const std::string& path);

// `patchCount` patches of one degree from flat arrays: `xyz` holds
// patchCount·(degreeU+1)·(degreeV+1)·3 coordinates, patch after patch, each in Patch::points
// order; `weights` (may be null: polynomial) one per control point. Throws ArgumentError for a
// degree outside 1..7.
std::vector<Patch> patchesFromArrays(int degreeU, int degreeV, size_t patchCount, const double* xyz,
                                     const double* weights = nullptr);

// How the adaptive quad-tree splits (docs/quadtree.md): A a uniform gridU×gridV grid per
// patch, B at the midpoint, C at the sampled curvature maximum, D at the true one (the paper's
// four); T to a tolerance: a node is a leaf once its proven deviation bound is within
// RuleOptions::tolerance, else it is split into up to 4 × 4 equal parts where that reaches
// the tolerance, or in u, v or both at its midpoint (tessellateToTolerance's default).
enum class Rule { A, B, C, D, T };

struct RuleOptions {
  Rule rule = Rule::B;
  float linearity = 0.1f;             // a node is a leaf when every 1 − Ti·Tj < linearity ...
  float flatness = 0.1f;              // ... and every 1 − Ni·Nj < flatness (rules B–D)
  double tolerance = 0;               // rule T: δ in model units (> 0); relativeTolerance helps
  int gridU = 8, gridV = 8;           // rule A's grid
  int samples = 5;                    // rules C and D: samples per direction
  uint32_t maxDepth = 0;              // nodes at this depth are leaves; 0: the rule's default
                                      // (12; rule T 30, as its one-way splits are levels)
  size_t maxNodes = size_t(1) << 24;  // more nodes in a tree: LimitError
};

// The diagonal of the axis-aligned bounding box of all control points (for rational patches
// those of weight > 0): the model's size. Throws ArgumentError when it is 0 (no patches, or
// every point the same).
double boundingBoxDiagonal(const std::vector<Patch>& patches);
// A tolerance relative to the model's size, in model units: fraction × boundingBoxDiagonal.
// relativeTolerance(patches, 0.001) is the CLI's default δ ("0.1%", about what Open CASCADE's
// importers use). Throws ArgumentError unless 0 < fraction ≤ 1.
double relativeTolerance(const std::vector<Patch>& patches, double fraction);

// How tessellateToTolerance meets the tolerance. Adaptive: the quad-tree of rule T, which
// stops each node on a proven bound of the distance between its triangles and the surface and
// splits anisotropically (fewest triangles). UniformGrids: one uniform grid per patch (rule A)
// sized by Filip's bound of the second derivatives (rational too, zero weights included;
// docs/rational_division.md): simple and predictable, more triangles.
enum class ToleranceMethod { Adaptive, UniformGrids };

struct ToleranceOptions {
  ToleranceMethod method = ToleranceMethod::Adaptive;
  int maxPerDirection = 1024;         // UniformGrids: most cells per direction of one patch
  uint32_t maxDepth = 30;             // Adaptive: nodes at this depth are leaves (a one-way
                                      // split is a level, so rule T needs about twice B's 12)
  size_t maxNodes = size_t(1) << 24;  // more nodes (or grid cells): LimitError
};

// A camera, for a tolerance in pixels: the clip-from-world matrix, 16 numbers column-major
// (glm's and GLSL's order; Vulkan clip space: visible where −w ≤ x, y ≤ w and 0 ≤ z ≤ w, y
// down), and the viewport in pixels. lookAtView makes a perspective one.
struct View {
  std::array<double, 16> viewProjection = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  int width = 1920, height = 1080;
};

// A perspective View from `eye` towards `target`, `up` up in the picture, `fovYDegrees` the
// vertical field of view, near and far distances > 0. Throws ArgumentError for a viewport
// < 1 px, fovYDegrees outside (0, 179), near ≤ 0, far ≤ near, or an eye on the target.
View lookAtView(const std::array<double, 3>& eye, const std::array<double, 3>& target,
                const std::array<double, 3>& up, double fovYDegrees, int width, int height,
                double nearDistance, double farDistance);

// What a tolerance call proved of its mesh: tessellateToTolerance, tessellateToPixelTolerance
// and tessellate with Rule::T fill Mesh::proof; rules A–D prove no distance and leave it empty.
struct ToleranceProof {
  double tolerance = 0;     // the tolerance asked: model units, or pixels for a pixel tolerance
  double largestBound = 0;  // the largest proven distance bound over the mesh's triangles, in
                            // the same units (pixels: over the triangles in view)
  bool proven = false;      // every triangle proven within the tolerance. False where the depth
                            // limit (maxDepth) stopped a leaf above it, where the triangulator
                            // had to fan a leaf proven for one diagonal only (docs/quadtree.md,
                            // "One diagonal"), or, in pixels, where the near plane cuts the
                            // surface through the eye
};

// An indexed triangle mesh in fp32. Per vertex: positions and normals (3 floats each), uvs
// (2 floats: the vertex's (u, v) on its patch), patchIds (the index of its patch in the input).
// indices: 3 per triangle, counter-clockwise seen from the side the normals point to.
// Vertices on a seam between patches are shared (welded), so the mesh is watertight.
struct Mesh {
  std::vector<float> positions;
  std::vector<float> normals;
  std::vector<float> uvs;
  std::vector<uint32_t> patchIds;
  std::vector<uint32_t> indices;
  std::optional<ToleranceProof> proof;  // tolerance calls only (above)

  size_t vertexCount() const { return positions.size() / 3; }
  size_t triangleCount() const { return indices.size() / 3; }
};

// Where the work runs. Auto: Vulkan when a usable device exists, else the CPU; a device that
// fails during a call (lost, out of memory) is dropped and the call runs again on the CPU.
// Cpu: the fp32 mirror of the shaders on all cores (the same bits as the GPU on lavapipe).
enum class Device { Auto, Vulkan, Cpu };

struct TessellatorOptions {
  Device device = Device::Auto;
  // Vulkan only: "" picks the best device (discrete > integrated > CPU; the environment
  // variable TESSERA_DEVICE overrides), else an index from `tessera devices` or part of a name.
  std::string deviceName;
  // The most CPU threads each parallel step of a call uses, the calling thread included (the
  // Tessellator's calls and tessellateCadFile's, which takes the smaller non-zero of this and
  // CadOptions::threads); 0: all cores. 1 runs everything on the calling thread and starts no
  // thread, for a program that schedules its own. The mesh is the same, bit for bit, whatever
  // the count. A Vulkan driver's own threads are the driver's (lavapipe: LP_NUM_THREADS).
  unsigned threads = 0;
};

// Owns the device (the Vulkan instance, queues, pipelines), so repeated calls are cheap: make
// one and keep it. Not for use by two threads at once; separate Tessellators are independent.
class Tessellator {
 public:
  // Throws DeviceError when Device::Vulkan was asked for and no usable device exists.
  explicit Tessellator(const TessellatorOptions& options = {});
  ~Tessellator();
  Tessellator(Tessellator&&) noexcept;
  Tessellator& operator=(Tessellator&&) noexcept;
  Tessellator(const Tessellator&) = delete;
  Tessellator& operator=(const Tessellator&) = delete;

  // True while the work runs on Vulkan; deviceName() is then the GPU's name, else "cpu".
  bool usesVulkan() const;
  std::string deviceName() const;

  // Adaptive tessellation by a split rule. Throws ArgumentError for a patch or option it
  // cannot take (naming which), LimitError past maxNodes, DeviceError on Device::Vulkan when
  // the device fails.
  Mesh tessellate(const std::vector<Patch>& patches, const RuleOptions& options = {});

  // Tessellation to a tolerance in model units (relativeTolerance for one relative to the
  // model's size): every triangle stays within `tolerance` of the surface at the same (u, v),
  // by options.method (ToleranceMethod above); Mesh::proof says what was proven (Adaptive
  // stops at maxDepth, so check proof->proven). Throws ArgumentError for a tolerance that is
  // not finite and > 0, a bad option, or (UniformGrids) a patch whose weights vanish on it (the
  // surface runs off to infinity: no grid is within any tolerance); LimitError past maxNodes or
  // (UniformGrids) where a grid would need more than maxPerDirection cells a side; DeviceError
  // as tessellate.
  Mesh tessellateToTolerance(const std::vector<Patch>& patches, double tolerance,
                             const ToleranceOptions& options = {});

  // Tessellation to a tolerance in pixels as `view` sees the patches: rule T's tree on their
  // screen-space image, so each triangle's projection stays within `pixels` of the projected
  // surface; nearer parts get more triangles. Positions are in model space and the mesh is
  // watertight. Parts outside the view get coarse (off-screen) triangles; where the near plane
  // cuts the surface through the eye, triangles are not proven (docs/quadtree.md, "Rule T in
  // screen space"). Adaptive only (options.method UniformGrids: ArgumentError); other errors
  // as tessellateToTolerance, and ArgumentError for a bad view.
  Mesh tessellateToPixelTolerance(const std::vector<Patch>& patches, double pixels,
                                  const View& view, const ToleranceOptions& options = {});

 private:
  friend struct TessellatorAccess;  // the library's own entry points (tessera/cad.h, vulkan.h)
  struct Impl;
  explicit Tessellator(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// One call: loadPatches(path), tessellated by `options` on a Tessellator made for the call.
Mesh tessellateFile(const std::string& path, const RuleOptions& options = {},
                    const TessellatorOptions& device = {});

}  // namespace tessera
