#version 450
// Classifies one frontier level of the quad-tree of bicubic patches by any split rule
// (lib/quadtree_bicubic_main.glsl).
#extension GL_GOOGLE_include_directive : require
#include "lib/quadtree_bicubic_main.glsl"
