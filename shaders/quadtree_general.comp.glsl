#version 450
// quadtree.comp.glsl for general patches, any split rule (lib/quadtree_general_main.glsl).
#extension GL_GOOGLE_include_directive : require
#include "lib/quadtree_general_main.glsl"
