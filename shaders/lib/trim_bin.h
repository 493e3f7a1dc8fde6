// A face's v bin of a value, for the trim classification's segment bins (TrimFace::binCount):
// floor((v − v0)·scale) clamped to [0, count − 1]. Non-decreasing in v (a subtraction and a
// product by a positive scale, each correctly rounded, then floor), so a segment placed in the
// bins of its two ends' v (packTrimSet, on the host) is in every bin between, and a node's v
// range [lo, hi] meets it only in bins trimBin(lo) .. trimBin(hi). One text for the host's
// binning, the fp32 mirror and the shader. Include shared_glsl_cpp.h first.
#ifndef TESSERA_TRIM_BIN_H
#define TESSERA_TRIM_BIN_H

SHARED_FN uint trimBin(float v, float v0, float scale, uint count) {
  PRECISE float offset = v - v0;
  PRECISE float t = offset * scale;
  if (!(t > 0.0f)) return 0u;
  if (t >= float(count - 1u)) return count - 1u;
  return uint(t);
}

#endif
