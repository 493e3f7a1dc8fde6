// Lets one source text compile as GLSL and as C++ (the fp32 mirrors in host/mirror/).
// Write shared code with: float literals with an f suffix, IN(T)/OUT(T)/INOUT(T) for
// parameters, PRECISE on every local that carries arithmetic, vec3(x) to drop .w.
// PRECISE (GLSL `precise`) forbids the shader compiler from reassociating or fusing, so the
// GPU runs exactly the operations written here, in this order — which the mirror also runs.
#ifndef TESSERA_SHARED_GLSL_CPP_H
#define TESSERA_SHARED_GLSL_CPP_H
#ifdef __cplusplus
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
#define PRECISE
#define SHARED_FN inline
// A function whose callers pass constants that should unroll its loops (the C++ mirror's
// fixed-degree variants): inlined whatever the compiler's size estimate says.
#define SHARED_FORCE_INLINE __attribute__((always_inline)) inline
#else
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define PRECISE precise
#define SHARED_FN
#define SHARED_FORCE_INLINE
#endif

// i / n for the lines of a grid, with both ends exact on every driver: 0 / n = 0 and n / n = 1.
// Vulkan allows a division 2.5 ulp of error, and NVIDIA's driver multiplies by a reciprocal, so
// there n / n need not be 1: on an H100 a stitched patch's corner, evaluated at "1" from two
// sides, came out as two points and opened cracks. Lavapipe and C++ divide correctly rounded,
// where this is the plain quotient bit for bit.
SHARED_FN float exactRatio(uint i, uint n) {
  if (i == n) return 1.0f;
  PRECISE float t = float(i) / float(n);
  return t;
}
#endif
