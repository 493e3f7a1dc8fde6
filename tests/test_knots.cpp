// Knot vector construction, validation messages and the span-search conventions (knots.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "bspline/knots.h"

using Catch::Matchers::Contains;
using tessera::findSpan;
using tessera::knotMultiplicity;
using tessera::openUniformKnots;
using tessera::uniformKnots;
using tessera::validateKnots;

TEST_CASE("uniformKnots are evenly spaced and n + p + 1 long", "[knots]") {
  const std::vector<double> x = uniformKnots(3, 5, -1.0, 0.5);
  REQUIRE(x == std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0});
  REQUIRE_NOTHROW(validateKnots(3, 5, x));
  REQUIRE(uniformKnots(2, 3) == std::vector<double>{0, 1, 2, 3, 4, 5});
}

TEST_CASE("openUniformKnots clamp both ends with multiplicity p + 1", "[knots]") {
  // n = p + 1 gives the Bézier knot vector of Taniguchi 2000, §2.2.2.
  REQUIRE(openUniformKnots(3, 4) == std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1});
  REQUIRE(openUniformKnots(3, 7) == std::vector<double>{0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1});
  const std::vector<double> x = openUniformKnots(2, 6, 2.0, 5.0);
  REQUIRE(x.size() == 9);
  REQUIRE(knotMultiplicity(x, 2.0) == 3);
  REQUIRE(knotMultiplicity(x, 5.0) == 3);
  REQUIRE(x[3] == Approx(2.75));
  REQUIRE(x[5] == Approx(4.25));
  REQUIRE_NOTHROW(validateKnots(2, 6, x));
}

TEST_CASE("constructors reject impossible requests", "[knots]") {
  REQUIRE_THROWS_AS(uniformKnots(0, 4), std::invalid_argument);
  REQUIRE_THROWS_AS(uniformKnots(8, 10), std::invalid_argument);
  REQUIRE_THROWS_WITH(openUniformKnots(3, 3), Contains("at least 4 control points"));
  REQUIRE_THROWS_AS(openUniformKnots(3, 5, 1.0, 1.0), std::invalid_argument);
  REQUIRE_THROWS_AS(uniformKnots(3, 5, 0.0, -1.0), std::invalid_argument);
}

TEST_CASE("validateKnots names the reason a knot vector is bad", "[knots]") {
  SECTION("decreasing") {
    REQUIRE_THROWS_AS(validateKnots(3, 4, {0, 0, 0, 0, 1, 0.5, 1, 1}), std::invalid_argument);
    REQUIRE_THROWS_WITH(validateKnots(3, 4, {0, 0, 0, 0, 1, 0.5, 1, 1}),
                        Contains("non-decreasing") && Contains("x_4 = 1 > x_5 = 0.5"));
  }
  SECTION("wrong length") {
    REQUIRE_THROWS_WITH(
        validateKnots(3, 4, {0, 0, 0, 1, 1, 1, 1}),
        Contains("wrong length") && Contains("expected 8 knots") && Contains("got 7"));
    REQUIRE_THROWS_WITH(validateKnots(2, 4, {0, 0, 0, 0.5, 1, 1, 1, 1}, "knotsV"),
                        Contains("knotsV") && Contains("wrong length"));
  }
  SECTION("multiplicity above degree + 1") {
    REQUIRE_THROWS_WITH(validateKnots(2, 5, {0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1}),
                        Contains("multiplicity of knot 0.5 exceeds degree + 1 = 3"));
    REQUIRE_THROWS_WITH(validateKnots(1, 3, {0, 0, 0, 1, 1}), Contains("multiplicity"));
  }
  SECTION("empty domain") {
    // x_p = x_n: every knot in the middle coincides, no parameter interval is left.
    REQUIRE_THROWS_WITH(validateKnots(1, 2, {0, 1, 1, 2}), Contains("empty parameter domain"));
  }
  SECTION("not finite") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    REQUIRE_THROWS_WITH(validateKnots(1, 2, {0, 0, nan, 1}), Contains("not finite"));
  }
  SECTION("degree and count") {
    REQUIRE_THROWS_WITH(validateKnots(0, 2, {0, 1, 2}), Contains("degree 0 is outside"));
    REQUIRE_THROWS_WITH(validateKnots(3, 2, {0, 0, 0, 1, 1, 1}),
                        Contains("needs at least 4 control points"));
  }
  SECTION("good vectors pass") {
    REQUIRE_NOTHROW(validateKnots(3, 4, {0, 0, 0, 0, 1, 1, 1, 1}));
    // A full-multiplicity interior knot (a C^-1 break) is allowed.
    REQUIRE_NOTHROW(validateKnots(2, 6, {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}));
  }
}

TEST_CASE("findSpan returns the non-empty span holding t", "[knots]") {
  const std::vector<double> x{0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1};  // p = 3, n = 8
  const int p = 3;
  for (int mu = p; mu < 8; ++mu) {
    if (x[mu] == x[mu + 1]) continue;
    for (double s : {0.0, 0.3, 0.999}) {
      const double t = x[mu] + s * (x[mu + 1] - x[mu]);
      INFO("t = " << t);
      const int span = findSpan(p, x, t);
      REQUIRE(span == mu);
      REQUIRE(x[span] <= t);
      REQUIRE(t < x[span + 1]);
    }
  }
  SECTION("a repeated knot belongs to the span on its right") {
    REQUIRE(findSpan(p, x, 0.5) == 6);
    REQUIRE(findSpan(p, x, 0.0) == 3);
  }
  SECTION("right end: t = x_n falls in the last non-empty span") {
    REQUIRE(findSpan(p, x, 1.0) == 7);
    // p = 2, n = 4, x_3 = x_4 = 1: the span ending at x_n is [x_2, x_3), not the empty one.
    REQUIRE(findSpan(2, {0, 0, 0, 1, 1, 2, 3}, 1.0) == 2);
  }
  SECTION("unclamped: the domain is [x_p, x_n]") {
    const std::vector<double> u = uniformKnots(2, 5);  // 0..7, domain [2, 5]
    REQUIRE(findSpan(2, u, 2.0) == 2);
    REQUIRE(findSpan(2, u, 4.5) == 4);
    REQUIRE(findSpan(2, u, 5.0) == 4);
  }
  SECTION("outside the domain: the nearest end span") {
    REQUIRE(findSpan(p, x, -0.1) == 3);
    REQUIRE(findSpan(p, x, 1.5) == 7);
    REQUIRE(findSpan(2, uniformKnots(2, 5), 0.5) == 2);
  }
  SECTION("non-finite t throws") {
    REQUIRE_THROWS_AS(findSpan(p, x, std::nan("")), std::invalid_argument);
  }
}

TEST_CASE("knotMultiplicity counts equal knots", "[knots]") {
  const std::vector<double> x{0, 0, 0, 0.5, 0.5, 1, 1, 1};
  REQUIRE(knotMultiplicity(x, 0.0) == 3);
  REQUIRE(knotMultiplicity(x, 0.5) == 2);
  REQUIRE(knotMultiplicity(x, 0.25) == 0);
}
