#version 450
// quadtree_general.comp.glsl for rule T alone, as quadtree_tolerance.comp.glsl is for bicubic
// patches: the proven bound without the corner frames and rules B-D's tests.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : enable  // DIVISION_KEEP_LOOP in the variants
#define CLASSIFY_TOLERANCE_ONLY
#include "lib/quadtree_general_main.glsl"
