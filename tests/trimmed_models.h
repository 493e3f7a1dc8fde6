// Hand-built TrimmedModels for the trimmed mesher's tests (no Open CASCADE): planar and
// bicubic faces, loops sampled from uv curves with each point's shared id found by its 3D
// position (or its place on an integer lattice), so faces meeting along an edge share ids.
#pragma once
#include <cmath>
#include <functional>
#include <map>
#include <tuple>
#include <vector>

#include "geometry/bezier.h"
#include "trim/trimmed_face.h"

namespace tessera::test {

constexpr double kPi = 3.14159265358979323846;

// S(u, v) = origin + u·du + v·dv on [0,1]², degree 1 × 1.
inline BezierPatch planarPatch(glm::dvec3 origin, glm::dvec3 du, glm::dvec3 dv) {
  BezierPatch p;
  p.degreeU = p.degreeV = 1;
  p.cp = {origin, origin + dv, origin + du, origin + du + dv};
  return p;
}

// A bicubic over [0,1]² with z = `height`·(bump) at the inner control points and z = 0 on
// the boundary rows, x = i/3·size, y = j/3·size: a pillow side.
inline BezierPatch bumpPatch(double size, double height, double tilt = 0) {
  BezierPatch p;
  p.cp.resize(16);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const bool inner = i > 0 && i < 3 && j > 0 && j < 3;
      p.at(i, j) = {size * i / 3.0, size * j / 3.0, inner ? height * (1 + tilt * (i - j)) : 0.0};
    }
  return p;
}

// Shared points looked up by a key: faces that reach the same key share the id.
class SharedPoints {
 public:
  explicit SharedPoints(TrimmedModel& model) : model_(model) {}
  uint32_t id(const std::tuple<long, long, long>& key, const glm::dvec3& position) {
    auto [it, fresh] = ids_.emplace(key, uint32_t(model_.sharedPoints.size()));
    if (fresh) model_.sharedPoints.push_back(position);
    return it->second;
  }
  // Keyed by the position rounded to 1e-9 (test geometry is exact to far better).
  uint32_t at(const glm::dvec3& p) {
    return id({std::lround(p.x * 1e9), std::lround(p.y * 1e9), std::lround(p.z * 1e9)}, p);
  }

 private:
  TrimmedModel& model_;
  std::map<std::tuple<long, long, long>, uint32_t> ids_;
};

// A loop through curve(t), t = k/n, k = 0..n−1, positions by `position`, ids by 3D place.
inline TrimLoop sampledLoop(const std::function<glm::dvec2(double)>& curve, int n,
                            const std::function<glm::dvec3(glm::dvec2)>& position,
                            SharedPoints& shared) {
  TrimLoop loop;
  for (int k = 0; k < n; ++k) {
    const glm::dvec2 uv = curve(double(k) / n);
    loop.uv.push_back(uv);
    loop.pointIds.push_back(shared.at(position(uv)));
  }
  return loop;
}

// The boundary of [0,1]² counter-clockwise, `perSide` segments a side.
inline std::function<glm::dvec2(double)> squareBoundary() {
  return [](double t) {
    const double s = 4 * t;
    const int side = std::min(int(s), 3);
    const double f = s - side;
    switch (side) {
      case 0: return glm::dvec2(f, 0);
      case 1: return glm::dvec2(1, f);
      case 2: return glm::dvec2(1 - f, 1);
      default: return glm::dvec2(0, 1 - f);
    }
  };
}

// A circle, clockwise (a hole) unless counterClockwise.
inline std::function<glm::dvec2(double)> circle(glm::dvec2 centre, double radius,
                                               bool counterClockwise = false) {
  return [=](double t) {
    const double a = 2 * kPi * (counterClockwise ? t : -t);
    return centre + radius * glm::dvec2(std::cos(a), std::sin(a));
  };
}

inline TrimmedFace faceOf(const BezierPatch& patch, std::vector<TrimLoop> loops, bool reversed,
                          uint32_t index) {
  TrimmedFace face;
  face.pieces.push_back({patch, 0, 1, 0, 1});
  face.loops = std::move(loops);
  face.reversed = reversed;
  face.faceIndex = index;
  face.label = "face " + std::to_string(index);
  return face;
}

// A quarter of a torus (tube radius 1 round a circle of radius 2) over [0,1]², one rational
// 2 × 2 piece: its parametrisation slides along the surface (not by angle), so gap triangles
// measure more parametrically than geometrically.
inline TrimmedFace quarterTorusFace() {
  const double w = std::sqrt(0.5);
  const glm::dvec2 around[3] = {{1, 0}, {1, 1}, {0, 1}};    // the big circle's quarter
  const glm::dvec2 profile[3] = {{3, 0}, {3, 1}, {2, 1}};  // (distance from the axis, height)
  const double weight[3] = {1, w, 1};
  BezierPatch patch;
  patch.degreeU = 2, patch.degreeV = 2;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      patch.cp.push_back({profile[j].x * around[i].x, profile[j].x * around[i].y, profile[j].y});
      patch.weights.push_back(weight[i] * weight[j]);
    }
  return faceOf(patch, {}, false, 0);
}

// A cylinder's side (radius 1, height 1) over u ∈ [0, 2π], v ∈ [0, 1] in four quarter-circle
// pieces (degree 2 × 1, weights 1, √2/2, 1), no loops.
inline TrimmedFace fourPieceCylinderSide() {
  TrimmedFace side;
  for (int q = 0; q < 4; ++q) {
    const double a = q * kPi / 2, w = std::sqrt(0.5);
    const glm::dvec3 p0(std::cos(a), std::sin(a), 0), p2(-std::sin(a), std::cos(a), 0);
    BezierPatch piece;
    piece.degreeU = 2;
    piece.degreeV = 1;
    for (glm::dvec3 p : {p0, p0 + p2, p2})
      for (double z : {0.0, 1.0}) piece.cp.push_back(p + glm::dvec3(0, 0, z));
    piece.weights = {1, 1, w, w, 1, 1};
    side.pieces.push_back({piece, a, a + kPi / 2, 0, 1});
  }
  return side;
}

}  // namespace tessera::test
