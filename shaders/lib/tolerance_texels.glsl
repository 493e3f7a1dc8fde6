// Rule T's bicubic shaders (lib/tolerance_bicubic_shader.glsl includes this for the three)
// read their inputs as uniform texel buffers, not storage buffers: lavapipe (Mesa 22.3) loads
// a storage buffer at a per-invocation index one lane at a time, with a bounds test per
// component (~70 instructions a lane for a vec4), which was about two thirds of these shaders'
// instructions; a texel fetch gathers the lanes' texels at once (host/vk/texel_view.h). Every
// view is RGBA32UI and floats pass as their bits (uintBitsToFloat: no conversion, so no device
// may flush a denormal on the way): the shaders see the bits a storage buffer gives them and
// the decisions stay the mirror's. (Writing the outputs by imageStore instead of as storage
// buffers saved nothing on lavapipe: its texel stores go lane by lane too.) Bindings 0-1: the
// patches' control points (16 texels a patch) and the nodes (2 texels each: rect; patch index,
// level, pads). Include after layout.h.
layout(binding = 0) uniform usamplerBuffer patchTexels;
layout(binding = 1) uniform usamplerBuffer nodeTexels;

vec4 fetchVec4(usamplerBuffer texels, uint texel) {
  return uintBitsToFloat(texelFetch(texels, int(texel)));
}

QuadNode fetchNode(uint index) {
  QuadNode node;
  node.rect = fetchVec4(nodeTexels, 2u * index);
  uvec4 words = texelFetch(nodeTexels, int(2u * index + 1u));
  node.patchIndex = words.x;
  node.level = words.y;
  node.pad0 = words.z;
  node.pad1 = words.w;
  return node;
}

BicubicPatch fetchPatch(uint patchIndex) {
  BicubicPatch bp;
  [[unroll]] for (uint k = 0u; k < 16u; ++k) bp.cp[k] = fetchVec4(patchTexels, 16u * patchIndex + k);
  return bp;
}
