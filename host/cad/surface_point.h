// A face surface's points at scattered (u, v), for the loop points' 3D-gap check (wireLoop):
// Geom_Surface::Value, except on a non-periodic B-spline, whose Geom_BSplineSurface::D0 locates
// both knot spans and gathers the span's poles (times their weights) at every call; here the
// span is kept while (u, v) stays well inside it and its gathered poles with it, and each call
// makes the rest of D0's arithmetic (two BSplCLib::Eval on the same numbers, the division by the
// weight): the same bits (docs/cad.md, step 6). A loop's points walk along its edges, so
// consecutive points mostly share a span.
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <gp_Pnt.hxx>

namespace tessera {

class SurfacePoint {
 public:
  // `surface` must outlive this.
  explicit SurfacePoint(const Handle(Geom_Surface)& surface);
  // surface->Value(u, v), bit for bit.
  gp_Pnt value(double u, double v);

 private:
  static constexpr int kMaxKeptDegree = 7;  // above (never in the import), Value itself
  static constexpr int kMaxBlock = 4 * (kMaxKeptDegree + 1) * (kMaxKeptDegree + 1);

  struct Span {
    int flatIndex = -1;
    double lo = 1.0, hi = 0.0;  // a parameter in (lo, hi) takes flatIndex; empty at first
  };
  // BSplCLib::LocateParameter on the flat knots, as BSplSLib::D0 (called with index 0) locates.
  static void locate(int degree, const TColStd_Array1OfReal& flatKnots, double t, Span& span);
  // BSplSLib::D0's PrepareEval for the kept spans: knots, poles, whether locally rational.
  void prepareSpans();

  const Geom_Surface& surface_;
  const Geom_BSplineSurface* bspline_ = nullptr;  // null: surface_.Value
  Span u_, v_;
  int preparedU_ = -1, preparedV_ = -1;
  bool uFirst_ = true;  // D0 evaluates the lower degree's direction first (u on a tie)
  int degree1_ = 0, degree2_ = 0;
  bool rational_ = false;
  int dimension_ = 3;
  double knots1_[2 * kMaxKeptDegree] = {}, knots2_[2 * kMaxKeptDegree] = {};
  double poles_[kMaxBlock] = {};  // degree1_ + 1 rows of degree2_ + 1 points, as PrepareEval
};

}  // namespace tessera
