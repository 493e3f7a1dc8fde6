// Geom_BSplineSurface::D1 along one iso-line, for the Newton solves of CadSurface::mapParameter.
// OCCT's D1 looks up both knot spans at every call, gathers the span's poles (times their
// weights) and evaluates both directions and every first derivative. Here the spans are found
// once (the fixed one per line, the moving one while the parameter stays well inside it), and
// what does not depend on the moving parameter is done once per span: the gathered poles,
// Bohm's first step (cad_detail::bohmDifferences), and, where the fixed direction is the one
// D1 evaluates first (the lower degree), that whole first evaluation. Each call then does the
// rest of D1's arithmetic for the point and the derivative along the line only, the same
// operations on the same numbers (BSplCLib::Bohm's second step, BSplCLib::Eval,
// BSplSLib::RationalDerivative's quotient): the same bits (docs/cad.md, step 5).
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace tessera {

class IsoLineD1 {
 public:
  // The iso-line v = fixed (alongU) or u = fixed of `surface`, which must outlive this.
  IsoLineD1(const Geom_BSplineSurface& surface, bool alongU, double fixed);
  // The point at parameter x along the line and the derivative along it: what
  // surface.D1(x, fixed) (alongU) or surface.D1(fixed, x) gives, P and D1U (or D1V).
  void d1(double x, gp_Pnt& p, gp_Vec& d);

 private:
  // Degrees up to this take the kept span (the import refuses higher ones); above, D1 itself.
  static constexpr int kMaxKeptDegree = 7;
  static constexpr int kMaxBlock = 4 * (kMaxKeptDegree + 1) * (kMaxKeptDegree + 1);

  struct Span {
    int flatIndex = 0;
    double lo = 1.0, hi = 0.0;  // x in (lo, hi) takes flatIndex without a lookup; empty at first
  };
  // BSplCLib::LocateParameter and FlatIndex as Geom_BSplineSurface::D1 calls them.
  static int locate(int degree, const TColStd_Array1OfReal& knots,
                    const TColStd_Array1OfInteger& mults, double t, Span* span);
  // What BSplSLib::D1's PrepareEval makes of the span (its knots, its poles, whether it is
  // locally rational), and what of D1's evaluation does not depend on the moving parameter.
  void prepareSpan();

  const Geom_BSplineSurface& surface_;
  const bool alongU_;
  const double fixed_;
  const bool kept_;  // else surface.D1 itself (a periodic surface's normalisation, a high degree)
  int fixedIndex_ = 0;
  Span moving_;
  int preparedIndex_ = -1;  // the moving span's flat index that the fields below are for

  // D1 evaluates the lower degree's direction first (u on a tie): `fixedFirst_` when that is
  // the fixed direction.
  bool fixedFirst_ = false;
  int degree1_ = 0, degree2_ = 0;  // first and second direction's degrees
  bool rational_ = false;          // the span's weights differ (PrepareEval's test)
  int dimension_ = 3;              // 4 when rational: (w·x, w·y, w·z, w)
  double knots1_[2 * kMaxKeptDegree] = {}, knots2_[2 * kMaxKeptDegree] = {};
  // fixedFirst_: the first direction's values at `fixed` (one row of degree2_ + 1 points), its
  // differences along the second direction taken; otherwise the span's poles, degree1_ + 1 rows
  // of degree2_ + 1 as PrepareEval lays them, their differences along the first direction taken.
  double prepared_[kMaxBlock] = {};
};

}  // namespace tessera
