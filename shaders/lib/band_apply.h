// One output point of the control-point reduction's row product (host/reduction/curve_product.h): row i
// of a band matrix (A⁺ of banded_oslo.h) applied to one curve, in fp32. Compiled twice from
// this one text: as GLSL in shaders/reduction_apply.comp.glsl, where firsts, offsets, weights,
// points and results are storage buffers, and as C++ inside the struct of
// host/reduction/band_mirror.cpp, where they are members of the same names. The sum runs over
// the row's entries in order from 0 with no fused multiply-add (PRECISE), so lavapipe and the
// mirror round identically. Points are relative to their curve's first point (the host
// subtracts it in double and adds it back), so the rounding scales with the curve's extent,
// not with its distance from the origin.
// Include shared_glsl_cpp.h first.
#ifndef TESSERA_BAND_APPLY_H
#define TESSERA_BAND_APPLY_H

// results[curve·rows + i] = Σ_t weights[offsets[i] + t] · points[curve·cols + firsts[i] + t].
void applyBandRow(uint curve, uint i, uint rows, uint cols) {
  uint begin = offsets[i];
  uint end = offsets[i + 1u];
  uint source = curve * cols + firsts[i];
  PRECISE vec3 sum = vec3(0.0f);
  for (uint k = begin; k < end; ++k) {
    PRECISE vec3 term = weights[k] * vec3(points[source + (k - begin)]);
    sum = sum + term;
  }
  results[curve * rows + i] = vec4(sum, 0.0f);
}

#endif
