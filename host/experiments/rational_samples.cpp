#include "experiments/rational_samples.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tessera {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec4 homogeneous(const glm::dvec3& p, double w) { return glm::dvec4(w * p, w); }
glm::dvec3 euclidean(const glm::dvec4& h) { return glm::dvec3(h) / h.w; }

// Quarter `k` of the unit circle: control points (2-D) and weights.
void quarterArc(int k, glm::dvec2 points[3], double weights[3]) {
  // Exact cosines of k·90° (std::cos(π/2) is 6e-17, not 0): neighbouring quarters must share
  // their end control points bit for bit, or meshing cannot see the shared edges.
  const double cosines[4] = {1.0, 0.0, -1.0, 0.0};
  const double c = cosines[k % 4], s = cosines[(k + 3) % 4];
  points[0] = {c, s};
  points[1] = {c - s, s + c};
  points[2] = {-s, c};
  weights[0] = weights[2] = 1.0;
  weights[1] = std::sqrt(0.5);
}

bool isCorner(const RationalBezierPatch& p, int index) {
  const int i = index / (p.degreeV + 1), j = index % (p.degreeV + 1);
  return (i == 0 || i == p.degreeU) && (j == 0 || j == p.degreeV);
}

// A direction in which every other control point lies ahead of control point `c` (or on the
// plane through it), or zero if the average of the unit directions towards them is not one.
glm::dvec3 viewDirectionFrom(const RationalBezierPatch& p, int c) {
  const glm::dvec3 xc = euclidean(p.cpw[c]);
  glm::dvec3 sum(0.0);
  for (size_t k = 0; k < p.cpw.size(); ++k)
    if (static_cast<int>(k) != c) sum += glm::normalize(euclidean(p.cpw[k]) - xc);
  const glm::dvec3 d = glm::normalize(sum);
  for (size_t k = 0; k < p.cpw.size(); ++k)
    if (static_cast<int>(k) != c && glm::dot(euclidean(p.cpw[k]) - xc, d) < -1e-12)
      return glm::dvec3(0.0);
  return d;
}

double netSize(const RationalBezierPatch& p) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec4& h : p.cpw) {
    lo = glm::min(lo, euclidean(h));
    hi = glm::max(hi, euclidean(h));
  }
  return glm::length(hi - lo);
}

struct ViewRequest {
  std::string surface;
  const RationalBezierPatch* patch;
  int controlPoint;
  glm::dvec3 direction;
};

void addViews(std::vector<SampleView>& out, const ViewRequest& request,
              const std::vector<double>& lateralFractions, int width, int height, double fovY) {
  const RationalBezierPatch& patch = *request.patch;
  const glm::dvec3 d = request.direction;
  if (glm::length(d) == 0.0) return;
  const glm::dvec3 xc = euclidean(patch.cpw[request.controlPoint]);
  const glm::dvec3 e1 =
      glm::normalize(glm::cross(d, std::abs(d.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
  const glm::dvec3 e2 = glm::cross(d, e1);
  const double size = netSize(patch);
  int variant = 0;
  for (double fraction : lateralFractions) {
    const double angle = 2.0 * kPi * variant++ / 3.0;
    const glm::dvec3 eye = xc + fraction * size * (std::cos(angle) * e1 + std::sin(angle) * e2);
    SampleView view;
    view.patch = patch;
    view.camera = lookAtCamera(eye, eye + d, e2, fovY, width, height, 1e-3 * size, 100.0 * size);
    const RationalBezierPatch screen = screenSpacePatch(patch, view.camera);
    bool valid = screen.cpw[request.controlPoint].w == 0.0;
    for (size_t k = 0; k < screen.cpw.size(); ++k) {
      const double w = screen.cpw[k].w;
      valid = valid && w >= 0.0 && (!isCorner(patch, static_cast<int>(k)) || w > view.camera.nearW);
      view.vanishedWeights += w == 0.0;
    }
    if (!valid) continue;
    const int n = patch.degreeV + 1;
    char where[96];
    std::snprintf(where, sizeof where, ", cp (%d,%d), eye %s", request.controlPoint / n,
                  request.controlPoint % n,
                  fraction == 0.0 ? "at the control point" : "moved sideways in its plane");
    view.name = request.surface + where;
    out.push_back(view);
  }
}

}  // namespace

RationalBezierPatch quarterCylinder(double radius, double height, double angle) {
  if (!(radius > 0.0 && height > 0.0 && angle > 0.0 && angle < kPi))
    throw std::invalid_argument("quarterCylinder: need radius, height > 0 and 0 < angle < π");
  const double half = 0.5 * angle;
  const glm::dvec2 arc[3] = {{radius, 0.0},
                             {radius, radius * std::tan(half)},
                             {radius * std::cos(angle), radius * std::sin(angle)}};
  const double weights[3] = {1.0, std::cos(half), 1.0};
  RationalBezierPatch p;
  p.degreeU = 2;
  p.degreeV = 1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j)
      p.cpw.push_back(homogeneous({arc[i].x, arc[i].y, j * height}, weights[i]));
  return p;
}

std::vector<RationalBezierPatch> rationalTorus(double majorRadius, double minorRadius) {
  if (!(majorRadius > minorRadius && minorRadius > 0.0))
    throw std::invalid_argument("rationalTorus: need major radius > minor radius > 0");
  std::vector<RationalBezierPatch> patches;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      glm::dvec2 tube[3], ring[3];
      double wt[3], wr[3];
      quarterArc(a, tube, wt);
      quarterArc(b, ring, wr);
      RationalBezierPatch p;
      p.degreeU = p.degreeV = 2;
      // A surface of revolution: profile (ρ, z) = (R + r·x, r·y) times the ring's (cos, sin).
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double rho = majorRadius + minorRadius * tube[i].x;
          p.cpw.push_back(homogeneous({rho * ring[j].x, rho * ring[j].y, minorRadius * tube[i].y},
                                      wt[i] * wr[j]));
        }
      patches.push_back(p);
    }
  return patches;
}

std::vector<SampleView> zeroWeightViews(bool full, int width, int height, double fovY) {
  std::vector<std::pair<std::string, RationalBezierPatch>> surfaces = {
      {"quarter cylinder R1 H1", quarterCylinder(1.0, 1.0)},
      {"quarter cylinder R1 H2", quarterCylinder(1.0, 2.0)},
  };
  const std::vector<RationalBezierPatch> torus = rationalTorus(2.0, 0.75);
  surfaces.push_back({"torus 2/0.75 outer", torus[0]});
  surfaces.push_back({"torus 2/0.75 inner", torus[4 * 2 + 1]});
  if (full) {
    surfaces.push_back({"cylinder arc 120° R1 H1.5", quarterCylinder(1.0, 1.5, 2.0 * kPi / 3.0)});
    surfaces.push_back({"torus 2/0.75 top", torus[4 * 1 + 2]});
    surfaces.push_back({"torus 2/0.75 bottom", torus[4 * 3 + 3]});
  }
  const std::vector<double> lateral =
      full ? std::vector<double>{0.0, 0.15, 0.3} : std::vector<double>{0.0, 0.2};
  std::vector<SampleView> views;
  for (const auto& [name, patch] : surfaces) {
    for (int c = 0; c < static_cast<int>(patch.cpw.size()); ++c) {
      if (isCorner(patch, c)) continue;
      addViews(views, {name, &patch, c, viewDirectionFrom(patch, c)}, lateral, width, height,
               fovY);
    }
    if (patch.degreeV == 1) {
      // Both arc corners of a cylinder on the eye plane: look back at the axis.
      const glm::dvec3 mid = euclidean(patch.cpw[2]);
      const glm::dvec3 d = -glm::normalize(glm::dvec3(mid.x, mid.y, 0.0));
      addViews(views, {name + " (both middle points)", &patch, 2, d}, lateral, width, height,
               fovY);
    }
  }
  return views;
}

}  // namespace tessera
