// The tessellation-shader peer's surface (shaders/tess_peer*.tese.glsl): the bicubic patch of the
// 16 input control points (b_ij = gl_in[i*4 + j], u along i) at (u, v), its position and the
// normal Pu × Pv (not normalised) for shading.
vec4 tessPeerBernstein(float t) {
  float s = 1.0 - t;
  return vec4(s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t);
}
vec4 tessPeerBernsteinDerivative(float t) {
  float s = 1.0 - t;
  return vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t);
}

void tessPeerSurface(float u, float v, out vec3 p, out vec3 normal) {
  vec4 bu = tessPeerBernstein(u), bv = tessPeerBernstein(v);
  vec4 du = tessPeerBernsteinDerivative(u), dv = tessPeerBernsteinDerivative(v);
  vec3 pu = vec3(0.0), pv = vec3(0.0);
  p = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    vec3 row = vec3(0.0), rowDv = vec3(0.0);
    for (int j = 0; j < 4; ++j) {
      vec3 b = gl_in[i * 4 + j].gl_Position.xyz;
      row += bv[j] * b;
      rowDv += dv[j] * b;
    }
    p += bu[i] * row;
    pu += du[i] * row;
    pv += bu[i] * rowDv;
  }
  normal = cross(pu, pv);
}
