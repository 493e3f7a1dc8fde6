// Rule T's bicubic shaders (quadtree_tolerance_nets.comp.glsl, quadtree_tolerance.comp.glsl)
// read their inputs as uniform texel buffers, not storage buffers: lavapipe (Mesa 22.3) loads
// a storage buffer at a per-invocation index one lane at a time, with a bounds test per
// component, which was about two thirds of these shaders' instructions; a texel fetch gathers
// the lanes' texels at once (host/vk/texel_view.h). The same bits either way, so the decisions
// stay the mirror's. Bindings 0-2: the patches' control points (RGBA32F, 16 a patch), and the
// nodes seen as RGBA32F (texel 2i: rect) and as RGBA32UI (texel 2i + 1: patch index, level).
// Include after layout.h.
layout(binding = 0) uniform samplerBuffer patchPoints;
layout(binding = 1) uniform samplerBuffer nodeRects;
layout(binding = 2) uniform usamplerBuffer nodeWords;

QuadNode fetchNode(uint index) {
  QuadNode node;
  node.rect = texelFetch(nodeRects, int(2u * index));
  uvec4 words = texelFetch(nodeWords, int(2u * index + 1u));
  node.patchIndex = words.x;
  node.level = words.y;
  node.pad0 = words.z;
  node.pad1 = words.w;
  return node;
}

BicubicPatch fetchPatch(uint patchIndex) {
  BicubicPatch bp;
  [[unroll]] for (int k = 0; k < 16; ++k) bp.cp[k] = texelFetch(patchPoints, int(16u * patchIndex) + k);
  return bp;
}
