#version 450
// quadtree_general.comp.glsl for rule B alone, as quadtree_midpoint.comp.glsl is for bicubic
// patches: the same text without rules C and D's searches.
#extension GL_GOOGLE_include_directive : require
#define CLASSIFY_MIDPOINT_ONLY
#include "lib/quadtree_general_main.glsl"
