#include "experiments/synthetic_surfaces.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "bspline/knots.h"

namespace tessera {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLength = 260.0;

struct Bump {
  glm::dvec3 centre;
  double sigma, height;
};

// The shape without features: position and outward cross-section direction.
struct BasePoint {
  glm::dvec3 position, outward;
};

BasePoint basePoint(double u, double v) {
  const double theta = 2.0 * kPi * u;
  const double s = 0.015 + 0.97 * v;  // heel → toe, ends kept open
  const double envelope = std::pow(std::sin(kPi * s), 0.6);
  const auto bell = [](double t, double centre, double width) {
    const double d = (t - centre) / width;
    return std::exp(-d * d);
  };
  // Wider at the ball, narrower at the waist; taller at the heel, lower at the toe.
  const double halfWidth = 42.0 * envelope * (1.0 + 0.18 * bell(s, 0.68, 0.12) - 0.12 * bell(s, 0.42, 0.1));
  const double halfHeight = 38.0 * envelope * (1.15 - 0.55 * s);
  const double c = std::cos(theta), sn = std::sin(theta);
  // A polynomial in sin θ that flattens the bottom (sin θ = −1) and leaves the top round.
  const double flatten = 0.2 * 0.5 * (1.0 - sn) * (4.0 * sn * sn * sn - 3.0 * sn);
  const double x = kLength * (s - 0.5);
  const double y = halfWidth * c + 8.0 * (s - 0.5) * (s - 0.5) * kLength / 100.0;
  const double z = halfHeight * (sn + flatten) + 14.0 * std::pow(s, 4.0) + 6.0 * std::pow(1.0 - s, 6.0);
  return {{x, y, z}, glm::normalize(glm::dvec3(0.0, c, sn))};
}

// Uniform in [0, 1) from the top 53 bits: the same numbers with every standard library.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

const std::vector<Bump>& bumps() {
  static const std::vector<Bump> list = [] {
    std::vector<Bump> out;
    std::mt19937_64 rng(20240611);
    const struct {
      int count;
      double sigma, height;
    } sizes[] = {{2, 20.0, 2.5}, {4, 7.0, 1.0}, {8, 2.5, 0.3}, {12, 0.9, 0.06}};
    for (const auto& size : sizes) {
      for (int k = 0; k < size.count; ++k) {
        const double u = unit(rng), v = 0.12 + 0.76 * unit(rng);
        out.push_back({basePoint(u, v).position, size.sigma, size.height});
      }
    }
    return out;
  }();
  return list;
}

double greville(const std::vector<double>& knots, int degree, int i) {
  double sum = 0.0;
  for (int k = 1; k <= degree; ++k) sum += knots[static_cast<size_t>(i + k)];
  return sum / degree;
}

}  // namespace

glm::dvec3 syntheticLastPoint(double u, double v) {
  const BasePoint base = basePoint(u, v);
  double displacement = 0.0;
  for (const Bump& b : bumps()) {
    const glm::dvec3 d = base.position - b.centre;
    const double r2 = glm::dot(d, d) / (b.sigma * b.sigma);
    if (r2 < 60.0) displacement += b.height * std::exp(-0.5 * r2);
  }
  // The instep ridge: across the top at 55 % of the length.
  const double s = 0.015 + 0.97 * v;
  const double across = (s - 0.55) * kLength / 1.5;
  const double top = std::max(0.0, std::sin(2.0 * kPi * u));
  displacement += 0.8 * std::exp(-0.5 * across * across) * top * top;
  return base.position + displacement * base.outward;
}

BSplineSurface syntheticLast(int countU, int countV) {
  if (countU < 4 || countV < 4) {
    throw std::invalid_argument("syntheticLast: needs at least 4 x 4 control points, got " +
                                std::to_string(countU) + " x " + std::to_string(countV));
  }
  BSplineSurface s;
  s.degreeU = s.degreeV = 3;
  s.countU = countU;
  s.countV = countV;
  s.knotsU = openUniformKnots(3, countU);
  s.knotsV = openUniformKnots(3, countV);
  s.cp.resize(static_cast<size_t>(countU) * static_cast<size_t>(countV));
  std::vector<double> gv(static_cast<size_t>(countV));
  for (int j = 0; j < countV; ++j) gv[static_cast<size_t>(j)] = greville(s.knotsV, 3, j);
  for (int i = 0; i < countU; ++i) {
    const double u = greville(s.knotsU, 3, i);
    for (int j = 0; j < countV; ++j) s.at(i, j) = syntheticLastPoint(u, gv[static_cast<size_t>(j)]);
  }
  return s;
}

BSplineSurface syntheticLastSmall() { return syntheticLast(40, 56); }

}  // namespace tessera
