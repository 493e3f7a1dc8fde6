#version 450
// quadtree.comp.glsl for rule B alone: the same text without rules C and D's searches
// (CLASSIFY_MIDPOINT_ONLY), which are most of the shader. The driver compiles the pipeline at
// every run (lavapipe keeps no pipeline cache), and this variant costs it a fraction of the time:
// bench/bench_startup.cpp. Rule B's arithmetic is the very same, so the trees are bit-identical.
#extension GL_GOOGLE_include_directive : require
#define CLASSIFY_MIDPOINT_ONLY
#include "lib/quadtree_bicubic_main.glsl"
