// Every buffer layout shared by the C++ host and the GLSL shaders (std430).
// Included by both: GLSL sees plain structs, C++ sees the same structs in tessera::gpu,
// and host/vk/layout_checks.cpp pins their sizes and offsets with static_asserts.
// Rule for std430 here: only vec4/uvec4 and 4-byte scalars, grouped in fours, so that the
// C++ and GLSL layouts cannot drift apart.
#ifndef TESSERA_SHADERS_LAYOUT_H
#define TESSERA_SHADERS_LAYOUT_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace tessera::gpu {
using uint = std::uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
#define TESSERA_CONST(type, name, value) constexpr type name = value
#else
#define TESSERA_CONST(type, name, value) const type name = value
#endif

// Workgroup size of every 1-D compute shader.
TESSERA_CONST(uint, kLocalSize, 64u);

// A bicubic Bézier patch: control point b_ij at cp[i*4 + j], i along u, j along v.
// xyz = position, w unused (1.0).
struct BicubicPatch {
  vec4 cp[16];
};

// One evaluation request: parameter (u, v) on patch `patchIndex`.
struct EvalQuery {
  uint patchIndex;
  float u;
  float v;
  uint pad;
};

// One evaluation result. w components: position.w = 1, du.w = dv.w = 0,
// normal.w = κ (max |principal curvature|, 0 at degenerate points).
struct EvalSample {
  vec4 position;
  vec4 du;
  vec4 dv;
  vec4 normalKappa;
};

// What a mesh keeps of an evaluation (eval_vertices.comp.glsl): EvalSample's position and
// unit normal, 32 bytes where EvalSample has 64. position.w = 1, normal.w = 0.
struct VertexSample {
  vec4 position;
  vec4 normal;
};

// eval_vertices.comp.glsl: one invocation per run of consecutive queries on one patch, at most
// kVertexRunLength long, so the patch's 16 control points are read once a run (lavapipe reads a
// storage buffer lane by lane: those reads were most of eval.comp's time). Run r is queries
// runStarts[r] .. runStarts[r + 1] − 1 (a uint buffer of runCount + 1 entries).
TESSERA_CONST(uint, kVertexRunLength, 8u);
struct VertexEvalPush {
  uint runCount;
  float degenerateEps;  // ε of docs/conventions.md (1e-5 in fp32)
  uint pad0;
  uint pad1;
};

// Push constants of eval.comp.glsl.
struct EvalPush {
  uint queryCount;
  float degenerateEps;  // ε of docs/conventions.md (1e-5 in fp32)
  uint pad0;
  uint pad1;
};


// ---- Adaptive quad-tree (shaders/quadtree.comp.glsl, host/quadtree/frontier.cpp) ----

// Split rules of the quad-tree paper. A (uniform grid) needs no shader.
TESSERA_CONST(uint, kSplitRuleMidpoint, 1u);    // (B) parameter midpoint
TESSERA_CONST(uint, kSplitRuleSampledMax, 2u);  // (C) largest κ among S×S samples
TESSERA_CONST(uint, kSplitRuleTrueMax, 3u);     // (D) κu = κv = 0 by Newton, plus the boundary
TESSERA_CONST(uint, kSplitRuleTolerance, 4u);   // (T) the node's proven deviation bound ≤ δ (issue 15)

// Why a node ended (NodeDecision.cause).
TESSERA_CONST(uint, kCauseSplit, 0u);     // not a leaf: split at NodeDecision.split
TESSERA_CONST(uint, kCauseFlat, 1u);      // every linearity and flatness test passed
TESSERA_CONST(uint, kCauseMaxDepth, 2u);  // reached the maximum depth
// Smaller than the minimum parameter size, or (rules B-D) too thin for fp32 to hold children:
// narrower than kResolvedWidthUlps of its coordinates (lib/quadtree_classify.h).
TESSERA_CONST(uint, kCauseMinSize, 3u);
TESSERA_CONST(uint, kCauseUniform, 4u);   // a cell of rule (A)'s uniform grid
// Rule T's midpoint splits go only where the bound needs them: along u alone, along v alone,
// or both (kCauseSplit); its grid splits are kCauseSplitGrid.
TESSERA_CONST(uint, kCauseSplitU, 5u);    // not a leaf: two children, split at u = NodeDecision.split.x
TESSERA_CONST(uint, kCauseSplitV, 6u);    // not a leaf: two children, split at v = NodeDecision.split.y
TESSERA_CONST(uint, kCauseWithinTolerance, 7u);  // rule T: the proven bound is ≤ δ
// Rule T: not a leaf: NodeDecision.pad = k_u | k_v << 8 equal children per direction, the
// fewest whose estimated bound is within δ (lib/tolerance_bound.h; docs/quadtree.md).
TESSERA_CONST(uint, kCauseSplitGrid, 8u);
// The largest cap on rule T's equal children per direction (ClassifyPush.toleranceSplitCap).
TESSERA_CONST(uint, kToleranceSplitCapMax, 16u);
// Rule T in screen space (host/mesh/screen_tolerance.h; set on the host, never by a shader):
TESSERA_CONST(uint, kCauseCulled, 9u);    // the node's hull is outside one clip plane: unseen
TESSERA_CONST(uint, kCauseEyePlane, 10u);  // the near plane cuts the node at the eye-plane depth
// Trimmed faces (host/trim/trim_frontier.h; set on the host): the node lies outside its face's
// trim loops (kTrimOutside), so it ends here and the mesher drops it.
TESSERA_CONST(uint, kCauseTrimmedAway, 11u);
// Rule T on rational patches: the pieces per direction on which the `split` bounds take the
// weight ratios where a weight of the node's net vanishes (DivisionOptions::ratioPieces).
TESSERA_CONST(int, kToleranceRatioPieces, 4);
// Rule T's grid estimate counts this share of the spreads m of a polynomial node's second
// derivatives about their centres (lib/tolerance_bound.h, toleranceGridNumerator). The
// children's second derivatives lie within the parent's C ± m (scaled by 1/k²), but their own
// spreads about their own centres are smaller again, by about 1/k (m is the variation of S''
// across the node): counting all of m over-refined (tea set at δ = 0.01 and 0.001: 10,907 and
// 80,787 triangles with 1; 9,915 and 75,348 with ½; docs/quadtree.md). Only an estimate: every
// child is classified by its own bound. Terms without centres (rational nets, the trimmed
// mesher's revolution bound) count all of m: theirs is the whole bound, which shrinks by 1/k²
// at best (with ½ there, the grid splits were too few and the children split again: a sphere
// took 26% more triangles).
TESSERA_CONST(float, kToleranceSpreadShare, 0.5f);
// Rule T's leaf diagonals (NodeDecision.pad of a kCauseWithinTolerance leaf): the bound holds
// for any triangles in the leaf (kToleranceAnyDiagonal), or only for triangles whose edges all
// run along the diagonal (0,0)–(1,1) of the leaf (d_s·d_t ≥ 0: kToleranceMainDiagonal) or
// along (1,0)–(0,1) (d_s·d_t ≤ 0: kToleranceAntiDiagonal), which the triangulator then keeps
// to (docs/quadtree.md, "One diagonal").
TESSERA_CONST(uint, kToleranceAnyDiagonal, 0u);
TESSERA_CONST(uint, kToleranceMainDiagonal, 1u);
TESSERA_CONST(uint, kToleranceAntiDiagonal, 2u);

// C and D keep the split point at least this fraction of the node's width from its edges,
// so a child is at least a quarter of its parent in each direction. A small margin lets a κ
// maximum on a node's edge shave off slivers whose long side shrinks by only the margin per
// level: on the teapot at 0.1, a margin of 0.1 took C and D to the maximum depth (37k and
// 124k leaves against B's 4.7k); 0.25 ends every node by flatness (7.7k and 8.4k).
TESSERA_CONST(float, kSplitMargin, 0.25f);
// Rules B-D split a node only when its width on the model (the highest of the four triangles
// from its split point to consecutive corners) is at least this many fp32 units in the last
// place of its largest coordinate. A child is at least a quarter of its parent each way
// (kSplitMargin) and a leaf's fan triangles are at least a quarter of the leaf high, so a
// leaf's triangles stay about 64 / 16 = 4 ulps high: more than rounding each corner (half an
// ulp a coordinate) can flatten. Scale-free, unlike a parameter size. Narrower nodes come only
// where the surface itself is degenerate (the teaspoon's handle tip, P_u and P_v nearly
// parallel): its tests fail however deep the tree goes, and deeper leaves only give triangles
// of zero area in fp32 (docs/watertight.md). No teapot or teacup tree meets it (256 would
// stop rule C's sliver nodes on the teapot's spout at 0.02).
TESSERA_CONST(float, kResolvedWidthUlps, 64.0f);
// Newton iterations of rule D per seed (fixed count: GPU and mirror run the same steps).
TESSERA_CONST(int, kNewtonIterations, 8);

// One frontier node: the rectangle [u0,u1]×[v0,v1] of patch `patchIndex` at depth `level`.
struct QuadNode {
  vec4 rect;  // u0, v0, u1, v1
  uint patchIndex;
  uint level;
  uint pad0;
  uint pad1;
};

// What the classifier decided for one node.
struct NodeDecision {
  vec4 split;       // us, vs (patch parameters), κ there, 0
  uint cause;       // kCause*
  // Rules B-D: the tests' values. Rule T: linearity = A/(A + B), the u share of the bound
  // (A = M_ss + M_st, B = M_tt + M_st), and flatness = the node's proven deviation bound
  // with its fp32 guard (lib/tolerance_bound.h: for a leaf kept to one diagonal, that
  // diagonal's); split = the node's midpoint.
  float linearity;  // largest 1 − Ti·Tj over the 4 edges (0 where a tangent is missing)
  float flatness;   // largest 1 − Ni·Nj over the 8 normal pairs (0 where a normal is missing)
  uint pad;         // rule T, kCauseSplitGrid: the child counts k_u | k_v << 8; a
                    // kCauseWithinTolerance leaf: its diagonal (kTolerance*Diagonal); else 0
};

// Rule T on bicubic patches classifies a level in two dispatches whose pipelines the driver
// compiles side by side (quadtree_tolerance_nets.comp.glsl, then quadtree_tolerance.comp.glsl):
// the first writes, per node, two of the three restricted difference nets' terms
// (lib/tolerance_bound.h, bicubicNetBound), which the second reads: the largest norms and
// error terms, and for the centred form each net's bounding-box centre and spread about it.
struct ToleranceNetBounds {
  vec4 ssSt;      // (‖Δ²_s‖, its error term, ‖Δ_sΔ_t‖, its error term)
  vec4 ssCentre;  // Δ²_s's centre (xyz) and spread (w)
  vec4 stCentre;  // Δ_sΔ_t's centre (xyz) and spread (w)
};

// Push constants of quadtree.comp.glsl. The split rule and S are specialization constants.
struct ClassifyPush {
  float linearity;
  float flatness;
  float minSize;
  float degenerateEps;
  uint maxDepth;
  uint nodeCount;
  float tolerance;  // δ of rule T (model units); 0 for rules A-D
  uint toleranceSplitCap;  // rule T: most equal children per direction (1: midpoints only); 0 for A-D
};


// ---- Offscreen rendering (shaders/mesh.vert.glsl, mesh.frag.glsl, host/render/offscreen_vulkan.cpp) ----

// What colours a triangle (MeshDrawPush.colourMode).
TESSERA_CONST(uint, kColourShaded, 0u);  // one porcelain colour
TESSERA_CONST(uint, kColourDepth, 1u);   // sequential palette by quad-tree level, clamped
TESSERA_CONST(uint, kColourPatch, 2u);   // categorical palette by patch id, cycling
TESSERA_CONST(uint, kColourFlat, 3u);    // grey level = the value, unlit (the viewer's text)

// The palettes in sRGB, as lists that both languages expand into an array
// (GLSL: vec3[](LIST), C++: {LIST}), so that the CLI's legend shows the shader's colours.
// Depth: ColorBrewer "Spectral" (11 classes) from blue (shallow) to red (deep), one class per
// quad-tree level; deeper levels share the last. Patch: Tableau 10. Shaded: porcelain.
#define TESSERA_PORCELAIN vec3(0.910, 0.886, 0.839)
TESSERA_CONST(int, kDepthPaletteSize, 11);
#define TESSERA_DEPTH_PALETTE                                                               \
  vec3(0.369, 0.310, 0.635), vec3(0.196, 0.533, 0.741), vec3(0.400, 0.761, 0.647),          \
      vec3(0.671, 0.867, 0.643), vec3(0.902, 0.961, 0.596), vec3(1.000, 1.000, 0.749),      \
      vec3(0.996, 0.878, 0.545), vec3(0.992, 0.682, 0.380), vec3(0.957, 0.427, 0.263),      \
      vec3(0.835, 0.243, 0.310), vec3(0.620, 0.004, 0.259)
TESSERA_CONST(int, kPatchPaletteSize, 10);
#define TESSERA_PATCH_PALETTE                                                               \
  vec3(0.306, 0.475, 0.655), vec3(0.949, 0.557, 0.169), vec3(0.882, 0.341, 0.349),          \
      vec3(0.463, 0.718, 0.698), vec3(0.349, 0.631, 0.310), vec3(0.929, 0.788, 0.282),      \
      vec3(0.690, 0.478, 0.631), vec3(1.000, 0.616, 0.655), vec3(0.612, 0.459, 0.373),      \
      vec3(0.729, 0.690, 0.675)

// Push constants of mesh.vert.glsl and mesh.frag.glsl (one range for both stages; 112 of the
// 128 bytes every device offers). The matrix is four vec4 columns rather than a mat4 to keep
// to this header's vec4-and-scalars rule; the columns are glm's (column-major) order.
struct MeshDrawPush {
  vec4 viewProjection[4];  // clip from world, Vulkan clip space (y down, z in [0, 1])
  vec4 eye;                // xyz camera position: two-sided shading turns normals towards it
  vec4 light;              // xyz unit direction towards the light, w = ambient fraction
  uint colourMode;         // kColour*
  uint wireframe;          // 1: darken triangle edges (barycentric distance), 0: none
  float wireWidth;         // edge line width in pixels
  uint pad0;
};


// ---- Loop subdivision stencils (shaders/loop_stencil.comp.glsl, host/loop/evaluator_vulkan.cpp) ----

// Push constants of loop_stencil.comp.glsl. One dispatch applies stencils firstStencil ..
// firstStencil + stencilCount − 1 of a table (host/loop/stencils.h); stencil s writes row
// sourceRows + s of the values buffer, a row being `width` floats (any per-vertex data).
struct LoopStencilPush {
  uint firstStencil;
  uint stencilCount;
  uint sourceRows;
  uint width;
};


// ---- General Bézier patches: degree 1..7 each way, polynomial or rational ----
// (shaders/lib/general_eval.h, eval_general.comp.glsl, quadtree_general.comp.glsl,
// host/geometry/general_patch.h). Bicubic polynomial patches keep BicubicPatch and its shaders.

// Orders (degree + 1) are at most this: every loop over a patch's control points has this
// fixed bound, so shader and mirror run the same loops for every degree.
TESSERA_CONST(int, kGeneralMaxOrder, 8);

// A tensor-product patch whose control points live in a separate buffer of homogeneous points
// vec4(w·x, w·y, w·z, w): b_ij at firstPoint + i*(degreeV+1) + j, i along u (conventions.md).
struct GeneralPatch {
  uint degreeU;     // 1..7
  uint degreeV;     // 1..7
  uint rational;    // 0: polynomial, every w is 1 and the quotient rule is skipped
  uint firstPoint;  // index of b_00 in the control-point buffer
};


// ---- Uniform-grid evaluation (shaders/grid_eval.comp.glsl, shaders/lib/grid_eval.h,
// host/realtime/grid_evaluator_vulkan.cpp) ----

// One vertex of a patch's P×P grid: 32 bytes, the unit the bandwidth cap of bench/ counts.
struct GridVertex {
  vec4 position;  // w = 1
  vec4 normal;    // unit normal (conventions.md, degenerate points included), w = 0
};

// Push constants of grid_eval.comp.glsl: one invocation per (patch, row); vertex (i, j) of
// patch p at index (p·P + i)·P + j, u = i/(P−1), v = j/(P−1).
struct GridEvalPush {
  uint patchCount;
  uint pointsPerSide;   // P ≥ 2
  float degenerateEps;  // ε of docs/conventions.md
  uint pad0;
};


// ---- Stitched real-time patterns (shaders/stitch_pattern.comp.glsl, shaders/lib/stitch_pattern.h,
// host/realtime/frame_vulkan.cpp; the pattern is drawn in docs/realtime.md) ----

// Flags of one patch side.
TESSERA_CONST(uint, kStitchReversed, 1u);   // the side's t runs opposite to its edge's canonical t
TESSERA_CONST(uint, kStitchCollapsed, 2u);  // the side is one point (a pole): no outer triangles

// One visible patch of a frame: an inner grid from the patch's counts (nu, nv) and a
// transition strip on each side (order V0, U1, V1, U0 of host/mesh/shared_edges.h) to that
// side's edge count. Vertices start at firstVertex, triangle indices at firstIndex.
struct StitchPatch {
  uvec4 sideSegments;  // edge counts of the four sides (>= 1)
  uvec4 sideEdge;      // each side's edge: its canonical control points at edgePoints[4·edge]
  uvec4 sideFlags;     // kStitch* per side
  uint patchIndex;     // into the scene's BicubicPatch buffer
  uint nu;             // the patch's division counts (>= 1)
  uint nv;
  uint firstVertex;
  uint firstIndex;
  uint pad0;
  uint pad1;
  uint pad2;
};

// Push constants of stitch_pattern.comp.glsl: one invocation per work item, an item being
// (record << kStitchSlotBits) | band: band b draws the inner rows b·kStitchBandRows .. (b + 1)·
// kStitchBandRows − 1 of the record's patch (those below cu), the last band the four sides too.
// Most patches are one band. The host orders the items so that neighbouring lanes get equal grids.
TESSERA_CONST(uint, kStitchSlotBits, 9u);
TESSERA_CONST(uint, kStitchBandRows, 8u);
struct StitchPush {
  uint itemCount;
  float degenerateEps;  // ε of docs/conventions.md
  uint pad0;
  uint pad1;
};


// ---- The fixed-function peer: Vulkan tessellation shaders (shaders/tess_peer.*.glsl,
// host/realtime/tess_shader_peer_vulkan.cpp) ----

// Push constants of tess_peer.tesc/tese.glsl (96 of the guaranteed 128 bytes).
struct TessPeerPush {
  vec4 viewProjection[4];  // clip from world, glm column order, Vulkan clip space
  vec4 params;             // viewport width, height (pixels), tolerance (pixels), max factor
  vec4 rules;  // factor scale (multiplies each factor before rounding up; 1 = the chord rule),
               // a collapsed side's factor as a multiple of the inner one along it (0: its own,
               // 1), 0, 0
};

// One triangle of the peer as its capture pipeline records it (tess_peer_capture.geom.glsl):
// the corners' world positions (w unused), their (u, v) on patch `patchIndex`. 80 bytes.
struct TessPeerTriangle {
  vec4 corners[3];
  vec4 uv01;  // (u0, v0, u1, v1)
  vec2 uv2;
  uint patchIndex;
  uint pad;
};


// ---- Nodes against trim loops (shaders/trim_classify.comp.glsl, shaders/lib/trim_classify.h,
// host/trim/trim_classifier.h; docs/trimmed_faces.md, "Classifying nodes against trim loops") ----

// What a node rectangle is to its face's trim loops (one uint per TrimQuery).
TESSERA_CONST(uint, kTrimOutside, 0u);   // no segment within the margin, even crossing parity: no material
TESSERA_CONST(uint, kTrimInside, 1u);    // no segment within the margin, odd parity (or no loops): all material
TESSERA_CONST(uint, kTrimCrossing, 2u);  // a segment meets the rectangle grown by the margin
// 4u (u = 2⁻²⁴): the rounding bound factor of an fp32 orientation test, above Shewchuk's
// (3 + 16u)·u for inputs that are fp32 values (lib/trim_classify.h).
TESSERA_CONST(float, kTrimOrientErrorFactor, 2.384185791015625e-7f);

// One trimmed face: its loops' segments are segments[firstSegment .. firstSegment + segmentCount),
// each a vec4 (a.u, a.v, b.u, b.v) in the face's (u, v) domain, fp32.
struct TrimFace {
  vec4 box;            // the segments' bounding box (u0, v0, u1, v1), from the fp32 segments
  uint firstSegment;
  uint segmentCount;   // 0: the face has no loops, every node is inside
  float margin;        // m: rectangles grow by m before the segment test (rounded up to fp32)
  uint pad;
  // The face's v bins (lib/trim_classify.h, trimBin; packTrimSet builds them once per set):
  // binWords[firstBin + b] .. binWords[firstBin + b + 1] are bin b's entries, each two words
  // (the segment's index in segments, the first bin it lies in). 0 bins: every node reads
  // every segment.
  uint firstBin;
  uint binCount;
  float binScale;      // bins per unit of v: bin(v) = floor((v − box.y)·binScale), clamped
  uint pad1;
};

// One Bézier piece of a face (= one patch of the quad-tree): its [0,1]² maps onto `rect`.
struct TrimPiece {
  vec4 rect;  // the piece's rectangle u0, v0, u1, v1 in its face's (u, v) domain, fp32
  uint face;
  uint pad0;
  uint pad1;
  uint pad2;
};

// One node to classify: `rect` (u0, v0, u1, v1) in piece `piece`'s [0,1]² (a QuadNode's rect).
struct TrimQuery {
  vec4 rect;
  uint piece;
  uint pad0;
  uint pad1;
  uint pad2;
};

// Push constants of trim_classify.comp.glsl.
struct TrimPush {
  uint queryCount;
  uint pad0;
  uint pad1;
  uint pad2;
};


// ---- Rational division counts (shaders/division_count.comp.glsl,
// shaders/lib/division_count.h, host/division/counter_vulkan.cpp; docs/rational_division.md) ----

// One rational Bézier patch of bidegree (degreeU, degreeV) ≤ (7, 7): its homogeneous control
// points (w·x, w·y, w·z, w), c[i*(degreeV+1) + j], start at points[firstPoint].
struct DivisionPatch {
  uint firstPoint;
  uint degreeU;
  uint degreeV;
  uint pad;
};

TESSERA_CONST(uint, kDivisionOk, 0u);
TESSERA_CONST(uint, kDivisionCapped, 1u);     // a count exceeded maxPerDirection, clamped
TESSERA_CONST(uint, kDivisionUnbounded, 2u);  // w may vanish on the patch: both counts capped

// Counts N_u, N_v, the real counts before rounding up, and the bounds of ‖S_uu‖, ‖S_uv‖, ‖S_vv‖.
struct DivisionResult {
  uint nu;
  uint nv;
  uint status;  // kDivision*
  float realU;
  float realV;
  float uu;
  float uv;
  float vv;
};

// Push constants of division_count.comp.glsl.
struct DivisionPush {
  float tolerance;       // TOL, in the units of the control points
  uint maxPerDirection;  // counts are clamped to this
  uint ratioPieces;      // q of the ρ/σ bounds (q×q pieces)
  uint patchCount;
};


// ---- Control-point reduction row product (shaders/reduction_apply.comp.glsl) ----

// Push constants of reduction_apply.comp.glsl: a rows × cols band matrix applied to `curves`
// curves of cols points each (vec4 per point, xyz used), giving curves × rows points.
struct BandApplyPush {
  uint rows;
  uint cols;
  uint curves;
  uint pad0;
};

#ifdef __cplusplus
}  // namespace tessera::gpu
#endif
#endif
