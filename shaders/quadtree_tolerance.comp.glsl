#version 450
// quadtree.comp.glsl for rule T alone (CLASSIFY_TOLERANCE_ONLY): the proven bound against δ
// without the corner frames and rules B-D's tests. The driver compiles the pipeline at every run
// (lavapipe keeps no pipeline cache), and the default job of `tessera tessellate` runs rule T:
// this variant costs the driver a fraction of the whole shader (bench/bench_startup.cpp). Rule
// T's arithmetic is the very same text, so the trees are bit-identical.
#extension GL_GOOGLE_include_directive : require
#define CLASSIFY_TOLERANCE_ONLY
#include "lib/quadtree_bicubic_main.glsl"
