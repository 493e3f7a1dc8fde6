// B-spline → Bézier pieces (bspline_to_bezier.h): each piece, evaluated on its own by
// de Casteljau, reproduces the B-spline on its parameter interval.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "bspline/bspline.h"
#include "bspline/to_bezier.h"
#include "bspline/knots.h"
#include "bspline/oslo.h"

using namespace tessera;

namespace {

std::vector<glm::dvec3> randomPoints(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::vector<glm::dvec3> pts(count);
  for (auto& q : pts) q = glm::dvec3(coord(rng), coord(rng), coord(rng));
  return pts;
}

double maxAbs(const glm::dvec3& d) {
  return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
}

// A local de Casteljau, so these tests do not lean on the Bézier kernel being built beside
// this one (host/geometry/bezier.h).
glm::dvec3 deCasteljau(std::vector<glm::dvec3> b, double s) {
  for (size_t level = 1; level < b.size(); ++level) {
    for (size_t k = 0; k + level < b.size(); ++k) b[k] = (1.0 - s) * b[k] + s * b[k + 1];
  }
  return b.front();
}

glm::dvec3 deCasteljauPatch(const BezierPatch& patch, double s, double r) {
  std::vector<glm::dvec3> alongU;
  for (int i = 0; i <= patch.degreeU; ++i) {
    std::vector<glm::dvec3> row;
    for (int j = 0; j <= patch.degreeV; ++j) row.push_back(patch.at(i, j));
    alongU.push_back(deCasteljau(row, r));
  }
  return deCasteljau(alongU, s);
}

// Checks pieces tile the domain in order and each matches the curve on its interval.
void requireCurvePiecesMatch(const BSplineCurve& curve, size_t expectedPieces) {
  const std::vector<BezierCurvePiece> pieces = bezierPieces(curve);
  REQUIRE(pieces.size() == expectedPieces);
  const double lo = curve.knots[static_cast<size_t>(curve.degree)];
  const double hi = curve.knots[curve.cp.size()];
  REQUIRE(pieces.front().t0 == lo);
  REQUIRE(pieces.back().t1 == hi);
  for (size_t k = 0; k < pieces.size(); ++k) {
    const BezierCurvePiece& piece = pieces[k];
    REQUIRE(piece.curve.degree == curve.degree);
    REQUIRE(piece.curve.cp.size() == static_cast<size_t>(curve.degree + 1));
    REQUIRE(piece.t0 < piece.t1);
    if (k > 0) REQUIRE(piece.t0 == pieces[k - 1].t1);
    for (int i = 0; i <= 50; ++i) {
      const double s = i / 50.0;
      const double t = piece.t0 + s * (piece.t1 - piece.t0);
      INFO("piece " << k << ", t = " << t);
      // At the right end of a piece the B-spline reads the next span: compare the
      // left limit there, which is what the piece represents.
      const double tEval = (i == 50 && k + 1 < pieces.size()) ? std::nextafter(t, lo) : t;
      REQUIRE(maxAbs(deCasteljau(piece.curve.cp, s) - curvePoint(curve, tEval)) <= 1e-12);
    }
  }
}

}  // namespace

TEST_CASE("to Bezier: a single clamped span is already the Bezier curve", "[bspline_to_bezier]") {
  const BSplineCurve c{3, {0, 0, 0, 0, 1, 1, 1, 1}, {{1, 1, 0}, {2, 3, 0}, {5, 3, 0}, {4, 1, 0}}};
  const std::vector<BezierCurvePiece> pieces = bezierPieces(c);
  REQUIRE(pieces.size() == 1);
  REQUIRE(pieces[0].curve.cp == c.cp);
  REQUIRE(pieces[0].t0 == 0.0);
  REQUIRE(pieces[0].t1 == 1.0);
  // Taniguchi 2000's P(0.5) through the Bézier piece.
  REQUIRE(maxAbs(deCasteljau(pieces[0].curve.cp, 0.5) - glm::dvec3(3.25, 2.5, 0)) <= 1e-15);
}

TEST_CASE("to Bezier: curves are reproduced exactly on every interval", "[bspline_to_bezier]") {
  SECTION("clamped cubic, simple and double interior knots") {
    requireCurvePiecesMatch({3, {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1}, randomPoints(8, 5)},
                            4);
  }
  SECTION("unclamped uniform quadratic: the domain ends are raised too") {
    requireCurvePiecesMatch({2, uniformKnots(2, 6), randomPoints(6, 6)}, 4);
  }
  SECTION("unclamped quartic with a double knot") {
    requireCurvePiecesMatch(
        {4, {-1, -0.5, 0, 0.1, 0.4, 0.4, 0.9, 1.3, 1.4, 2, 2.2, 3}, randomPoints(7, 7)}, 2);
  }
  SECTION("a C^-1 break (multiplicity p + 1) stays two pieces") {
    requireCurvePiecesMatch({2, {0, 0, 0, 0.3, 0.3, 0.3, 0.45, 1, 1, 1}, randomPoints(7, 8)}, 3);
  }
  SECTION("degree 1 and degree 7") {
    requireCurvePiecesMatch({1, openUniformKnots(1, 5), randomPoints(5, 9)}, 4);
    requireCurvePiecesMatch({7, openUniformKnots(7, 11), randomPoints(11, 10)}, 4);
  }
}

TEST_CASE("to Bezier: adjacent pieces join with the spline's continuity", "[bspline_to_bezier]") {
  // Simple knots of a cubic: C², so end points and end tangents coincide across joints.
  const BSplineCurve c{3, openUniformKnots(3, 7), randomPoints(7, 12)};
  const std::vector<BezierCurvePiece> pieces = bezierPieces(c);
  REQUIRE(pieces.size() == 4);
  for (size_t k = 1; k < pieces.size(); ++k) {
    const auto& a = pieces[k - 1].curve.cp;
    const auto& b = pieces[k].curve.cp;
    REQUIRE(maxAbs(a[3] - b[0]) <= 1e-15);
    // Equal spans: equal Bézier legs across the joint.
    REQUIRE(maxAbs((a[3] - a[2]) - (b[1] - b[0])) <= 1e-14);
  }
}

TEST_CASE("to Bezier: surfaces are reproduced exactly on every patch", "[bspline_to_bezier]") {
  BSplineSurface s;
  s.degreeU = 3;
  s.degreeV = 2;
  s.knotsU = {0, 0, 0, 0, 0.3, 0.3, 0.6, 1, 1, 1, 1};  // 3 spans
  s.knotsV = uniformKnots(2, 5, -1.0, 0.5);            // unclamped, 3 spans on [0, 1.5]
  s.countU = 7;
  s.countV = 5;
  s.cp = randomPoints(35, 13);

  const std::vector<BezierPatchPiece> patches = bezierPatches(s);
  REQUIRE(patches.size() == 9);
  const double uBreaks[] = {0, 0.3, 0.6, 1};
  const double vBreaks[] = {0, 0.5, 1, 1.5};
  for (size_t k = 0; k < patches.size(); ++k) {
    const BezierPatchPiece& piece = patches[k];
    // u-major order: patch (a, b) at a·3 + b.
    REQUIRE(piece.u0 == uBreaks[k / 3]);
    REQUIRE(piece.u1 == uBreaks[k / 3 + 1]);
    REQUIRE(piece.v0 == vBreaks[k % 3]);
    REQUIRE(piece.v1 == vBreaks[k % 3 + 1]);
    REQUIRE(piece.patch.degreeU == 3);
    REQUIRE(piece.patch.degreeV == 2);
    REQUIRE(piece.patch.cp.size() == 12);
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; j <= 8; ++j) {
        // Interior of the patch and its lower edges, where the B-spline's half-open spans
        // read this same polynomial piece.
        const double sU = i / 9.0, sV = j / 9.0;
        const double u = piece.u0 + sU * (piece.u1 - piece.u0);
        const double v = piece.v0 + sV * (piece.v1 - piece.v0);
        INFO("patch " << k << ", u = " << u << ", v = " << v);
        REQUIRE(maxAbs(deCasteljauPatch(piece.patch, sU, sV) - surfacePoint(s, u, v)) <= 1e-12);
      }
    }
  }
  // The surface's corners are the outer patches' corner control points (u clamped; v is
  // unclamped, so compare points rather than control points there).
  REQUIRE(maxAbs(patches.back().patch.at(3, 2) - surfacePoint(s, 1.0, 1.5)) <= 1e-14);
  REQUIRE(maxAbs(patches.front().patch.at(0, 0) - surfacePoint(s, 0.0, 0.0)) <= 1e-14);
}

TEST_CASE("to Bezier: a second net through the same insertion is what a second call gives, bit for bit",
          "[bspline_to_bezier]") {
  BSplineSurface s;
  s.degreeU = 3;
  s.degreeV = 2;
  s.knotsU = {0, 0, 0, 0, 0.3, 0.3, 0.6, 1, 1, 1, 1};
  s.knotsV = uniformKnots(2, 5, -1.0, 0.5);
  s.countU = 7;
  s.countV = 5;
  s.cp = randomPoints(35, 13);
  BSplineSurface companion = s;
  companion.cp = randomPoints(35, 14);
  companion.cp[3] = glm::dvec3(-0.0, 0.0, -0.0);  // signed zeros keep whatever the sums make

  // The reference: refineSurface along u, then along v (oslo.h), each non-empty span pair's
  // control points read off the refined net.
  const auto reference = [](const BSplineSurface& surface) {
    const BSplineSurface refined = refineSurface(
        refineSurface(surface, ParamDirection::U, bezierKnots(3, surface.knotsU)),
        ParamDirection::V, bezierKnots(2, surface.knotsV));
    std::vector<std::vector<glm::dvec3>> nets;
    for (int mu = 3; mu + 1 < int(refined.knotsU.size()) - 3; ++mu)
      for (int nu = 2; nu + 1 < int(refined.knotsV.size()) - 2; ++nu) {
        if (!(refined.knotsU[size_t(mu)] < refined.knotsU[size_t(mu + 1)]) ||
            !(refined.knotsV[size_t(nu)] < refined.knotsV[size_t(nu + 1)]))
          continue;
        std::vector<glm::dvec3> net;
        for (int i = 0; i <= 3; ++i)
          for (int j = 0; j <= 2; ++j) net.push_back(refined.at(mu - 3 + i, nu - 2 + j));
        nets.push_back(net);
      }
    return nets;
  };
  const auto sameBits = [](const std::vector<BezierPatchPiece>& pieces,
                           const std::vector<std::vector<glm::dvec3>>& expected) {
    REQUIRE(pieces.size() == expected.size());
    for (size_t k = 0; k < pieces.size(); ++k) {
      REQUIRE(pieces[k].patch.cp.size() == expected[k].size());
      for (size_t c = 0; c < expected[k].size(); ++c)
        for (int a = 0; a < 3; ++a) {
          INFO("piece " << k << ", point " << c << ", coordinate " << a);
          REQUIRE(std::signbit(pieces[k].patch.cp[c][a]) == std::signbit(expected[k][c][a]));
          REQUIRE(pieces[k].patch.cp[c][a] == expected[k][c][a]);
        }
    }
  };
  const std::vector<BezierPatchPiece> single = bezierPatches(s);
  sameBits(single, reference(s));
  const auto [first, second] = bezierPatchPair(s, companion.cp);
  sameBits(first, reference(s));
  sameBits(second, reference(companion));
  for (size_t k = 0; k < single.size(); ++k) {
    REQUIRE(second[k].u0 == single[k].u0);
    REQUIRE(second[k].v1 == single[k].v1);
  }
  REQUIRE_THROWS_AS(bezierPatchPair(s, randomPoints(34, 1)), std::invalid_argument);
}

TEST_CASE("to Bezier: invalid input is refused", "[bspline_to_bezier]") {
  const BSplineCurve bad{3, {0, 0, 0, 0, 1, 0.5, 1, 1}, randomPoints(4, 1)};
  REQUIRE_THROWS_WITH(bezierPieces(bad), Catch::Matchers::Contains("non-decreasing"));
  BSplineSurface s;
  s.degreeU = s.degreeV = 1;
  s.knotsU = s.knotsV = openUniformKnots(1, 2);
  s.countU = s.countV = 2;
  s.cp = randomPoints(3, 1);
  REQUIRE_THROWS_AS(bezierPatches(s), std::invalid_argument);
}
