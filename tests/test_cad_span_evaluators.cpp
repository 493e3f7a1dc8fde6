// IsoLineD1 (host/cad/): OCCT's own evaluation with the knot span kept between calls must give
// OCCT's bits, at knots, between them, a hair off them and outside the domain; and Bohm's two
// steps (cad/detail/bohm_steps.h) BSplCLib::Bohm's; a plane's kept transform
// (cad/detail/plane_parameters.h) ElSLib::Parameters'.
#ifdef TESSERA_HAVE_CAD
#include <catch2/catch.hpp>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include <BSplCLib.hxx>
#include <ElSLib.hxx>
#include <gp_Ax3.hxx>
#include <random>

#include "cad/detail/bohm_steps.h"
#include "cad/detail/plane_parameters.h"
#include "cad/iso_line_d1.h"

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Parameters over [-0.2, 1.2] of a knot vector with knots at 0, 0.3, 0.5, 1: a walk up, one
// down (as a reversed edge reads its samples), the knots themselves and their neighbours.
std::vector<double> walk() {
  std::vector<double> ts;
  for (int k = 0; k <= 140; ++k) ts.push_back(-0.2 + 1.4 * k / 140.0);
  for (int k = 140; k >= 0; --k) ts.push_back(-0.2 + 1.4 * k / 140.0 + 1e-3);
  for (double knot : {0.0, 0.3, 0.5, 1.0})
    for (double t : {knot, std::nextafter(knot, -1.0), std::nextafter(knot, 2.0), knot - 1e-17, knot + 1e-16})
      ts.push_back(t);
  return ts;
}

// A B-spline surface of the given degrees over the knots above (u: 0, 0.3 double, 0.5, 1;
// v: 0, 0.4, 1). `weighting`: 0 polynomial, 1 rational everywhere, 2 rational with weights that
// are equal over some spans (D1 evaluates those as polynomial).
Handle(Geom_BSplineSurface) testSurface(int uDegree, int vDegree, int weighting) {
  TColStd_Array1OfReal uKnots(1, 4), vKnots(1, 3);
  TColStd_Array1OfInteger uMults(1, 4), vMults(1, 3);
  uKnots(1) = 0.0, uKnots(2) = 0.3, uKnots(3) = 0.5, uKnots(4) = 1.0;
  uMults(1) = uDegree + 1, uMults(2) = std::min(2, uDegree), uMults(3) = 1, uMults(4) = uDegree + 1;
  vKnots(1) = 0.0, vKnots(2) = 0.4, vKnots(3) = 1.0;
  vMults(1) = vDegree + 1, vMults(2) = 1, vMults(3) = vDegree + 1;
  const int nu = uMults(2) + uMults(3) + uDegree + 1, nv = 1 + vDegree + 1;
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int i = 1; i <= nu; ++i)
    for (int j = 1; j <= nv; ++j) {
      poles(i, j) = gp_Pnt(i + 0.1 * j * j, j - 0.2 * i, std::sin(i * j * 0.7));
      weights(i, j) = weighting == 2 && i <= uDegree + 1 ? 1.5 : 1.0 + 0.25 * ((i + j) % 3);
    }
  if (weighting == 0) return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, uDegree, vDegree);
  return new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, uDegree, vDegree);
}

}  // namespace

TEST_CASE("cad: the iso-line evaluator with a kept span gives Geom_BSplineSurface::D1's bits", "[cad]") {
  // Both orders of D1's two steps (the lower degree first: the fixed or the moving direction),
  // a tie, polynomial, rational and locally polynomial spans.
  size_t compared = 0, differing = 0;
  for (const auto& [uDegree, vDegree] : {std::pair{2, 3}, {3, 2}, {2, 2}, {2, 1}, {1, 2}, {3, 3}})
    for (const int weighting : {0, 1, 2}) {
      const Handle(Geom_BSplineSurface) surface = testSurface(uDegree, vDegree, weighting);
      for (const bool alongU : {true, false})
        for (const double fixed : {0.0, 0.3, 0.4, 0.77, 1.0}) {
          tessera::IsoLineD1 line(*surface, alongU, fixed);
          for (const double x : walk()) {
            gp_Pnt p, q;
            gp_Vec d, du, dv;
            line.d1(x, p, d);
            if (alongU) surface->D1(x, fixed, q, du, dv); else surface->D1(fixed, x, q, du, dv);
            const gp_Vec e = alongU ? du : dv;
            ++compared;
            if (!sameBits(p.X(), q.X()) || !sameBits(p.Y(), q.Y()) || !sameBits(p.Z(), q.Z()) ||
                !sameBits(d.X(), e.X()) || !sameBits(d.Y(), e.Y()) || !sameBits(d.Z(), e.Z()))
              ++differing;
          }
        }
    }
  CHECK(compared > 50000);
  CHECK(differing == 0);
}

TEST_CASE("cad: Bohm's two steps give BSplCLib::Bohm's bits", "[cad]") {
  // Degrees 1-7, dimensions 2-12 (one point, a homogeneous point, rows of them), every number of
  // derivatives, parameters inside, at and outside the span, knots with repeats.
  size_t compared = 0, differing = 0;
  for (int degree = 1; degree <= 7; ++degree)
    for (int dimension = 2; dimension <= 12; ++dimension)
      for (int derivatives = 0; derivatives <= degree + 1; ++derivatives)
        for (const double u : {0.37, 0.5, 0.0, 1.0, -0.3, 1.9}) {
          double knots[14];
          for (int k = 0; k < 2 * degree; ++k) knots[k] = (k - degree + 1) * 0.5 + (k % 3 == 0 ? 0.0 : 0.1 * k);
          if (degree > 2) knots[1] = knots[0];  // a double knot, as at a multiplicity
          double poles[8 * 12], reference[8 * 12];
          for (int k = 0; k < (degree + 1) * dimension; ++k)
            poles[k] = reference[k] = std::sin(1.3 * k + degree) * (1.0 + dimension);
          BSplCLib::Bohm(u, degree, derivatives, *knots, dimension, *reference);
          tessera::cad_detail::bohmDifferences(degree, knots, dimension, poles);
          tessera::cad_detail::bohmAt(u, degree, derivatives, knots, dimension, poles);
          for (int k = 0; k < (degree + 1) * dimension; ++k) {
            ++compared;
            if (!sameBits(poles[k], reference[k])) ++differing;
          }
        }
  CHECK(compared > 20000);
  CHECK(differing == 0);
}

TEST_CASE("cad: a plane's kept transform gives ElSLib::Parameters' bits", "[cad]") {
  std::mt19937 random(41);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0), unit(-1.0, 1.0);
  size_t compared = 0;
  for (int planeIndex = 0; planeIndex < 40; ++planeIndex) {
    // Axis-aligned planes (most of a file's), then tilted ones, each with its own origin.
    const gp_Pnt origin(coordinate(random), coordinate(random), coordinate(random));
    gp_Dir normal(0, 0, 1), xDirection(1, 0, 0);
    if (planeIndex % 4 == 1) normal = gp_Dir(0, -1, 0), xDirection = gp_Dir(0, 0, 1);
    if (planeIndex >= 8) {
      normal = gp_Dir(unit(random), unit(random), 1.0 + unit(random));
      xDirection = gp_Dir(gp_Vec(normal) ^ gp_Vec(unit(random), 1.0, unit(random)));
    }
    const gp_Pln plane(gp_Ax3(origin, normal, xDirection));
    const tessera::cad_detail::PlaneParameters kept(plane);
    for (int k = 0; k < 50; ++k) {
      const gp_Pnt point(coordinate(random), coordinate(random), coordinate(random));
      double u = 0, v = 0;
      ElSLib::Parameters(plane, point, u, v);
      const gp_Pnt2d uv = kept(point);
      REQUIRE(sameBits(uv.X(), u));
      REQUIRE(sameBits(uv.Y(), v));
      ++compared;
    }
  }
  CHECK(compared == 2000);
}

#endif  // TESSERA_HAVE_CAD
