// What rule T's three bicubic shaders share (quadtree_tolerance_nets.comp.glsl,
// quadtree_tolerance.comp.glsl and quadtree_tolerance_fused.comp.glsl, which does the two's
// work in one dispatch): the bound's bicubic configuration, which must be the same in all three
// for the two-dispatch and fused decisions to stay bit-identical, their inputs (bindings 0-1)
// and push constants. Each shader declares its outputs from binding 2 on. Include right after
// the #version and #extension lines (GL_GOOGLE_include_directive, GL_EXT_control_flow_attributes).
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#define TOLERANCE_ROW_ORDER 4  // bicubic rows: lib/tolerance_bound.h
#define TOLERANCE_UNROLL [[unroll]]  // constant trip counts: lib/tolerance_bound.h
#include "lib/tolerance_bound.h"
#include "lib/dispatch.glsl"

#include "lib/tolerance_texels.glsl"  // bindings 0-1: patches and nodes

layout(push_constant) uniform Push { ClassifyPush pc; };
