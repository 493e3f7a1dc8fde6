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
#else
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define PRECISE precise
#endif
#endif
