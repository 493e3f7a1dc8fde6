// Geom_BSplineSurface::D1 along one iso-line, for the Newton solves of CadSurface::mapParameter.
// OCCT's D1 looks up both knot spans at every call (half its time in the solves); here the fixed
// parameter's span is found once and the moving one's kept while the parameter stays well inside
// it. The same BSplSLib::D1 call with the same indices as D1 makes: the same bits.
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
  struct Span {
    int flatIndex = 0;
    double lo = 1.0, hi = 0.0;  // x in (lo, hi) takes flatIndex without a lookup; empty at first
  };
  // BSplCLib::LocateParameter and FlatIndex as Geom_BSplineSurface::D1 calls them.
  static int locate(int degree, const TColStd_Array1OfReal& knots,
                    const TColStd_Array1OfInteger& mults, double t, Span* span);

  const Geom_BSplineSurface& surface_;
  const bool alongU_;
  const double fixed_;
  const bool periodic_;  // then surface.D1 itself (its periodic normalisation), no cache
  int fixedIndex_ = 0;
  Span moving_;
};

}  // namespace tessera
