// Geom_BSplineSurface::D1 (OCCT 7.6) without its two span lookups per call.
#include "cad/iso_line_d1.h"

#include <BSplCLib.hxx>
#include <BSplSLib.hxx>
#include <Standard_Real.hxx>
#include <cmath>

namespace tessera {

IsoLineD1::IsoLineD1(const Geom_BSplineSurface& surface, bool alongU, double fixed)
    : surface_(surface),
      alongU_(alongU),
      fixed_(fixed),
      periodic_(surface.IsUPeriodic() || surface.IsVPeriodic()) {
  if (periodic_) return;
  fixedIndex_ = alongU ? locate(surface.VDegree(), surface.VKnots(), surface.VMultiplicities(), fixed, nullptr)
                       : locate(surface.UDegree(), surface.UKnots(), surface.UMultiplicities(), fixed, nullptr);
}

int IsoLineD1::locate(int degree, const TColStd_Array1OfReal& knots,
                      const TColStd_Array1OfInteger& mults, double t, Span* span) {
  int index = 0;  // 0: looked up in full, as Geom_BSplineSurface::D1 starts
  double newT = t;
  BSplCLib::LocateParameter(degree, knots, &mults, t, Standard_False, index, newT);
  if (span && index < knots.Upper()) {
    // For x strictly inside (K(index), K(index+1) − margin) LocateParameter gives `index` again:
    // its search lands there (knots strictly increase) and x is farther from the next knot than
    // its Eps, Epsilon(min(|last knot|, |x|)) ≤ Epsilon(|last knot|).
    span->lo = knots(index);
    span->hi = knots(index + 1) - 2.0 * Epsilon(std::abs(knots(knots.Upper())));
  }
  return BSplCLib::FlatIndex(degree, index, mults, Standard_False);
}

void IsoLineD1::d1(double x, gp_Pnt& p, gp_Vec& d) {
  gp_Vec du, dv;
  if (periodic_) {
    if (alongU_) surface_.D1(x, fixed_, p, du, dv); else surface_.D1(fixed_, x, p, du, dv);
    d = alongU_ ? du : dv;
    return;
  }
  if (!(x > moving_.lo && x < moving_.hi))
    moving_.flatIndex = alongU_ ? locate(surface_.UDegree(), surface_.UKnots(), surface_.UMultiplicities(), x, &moving_)
                                : locate(surface_.VDegree(), surface_.VKnots(), surface_.VMultiplicities(), x, &moving_);
  const double u = alongU_ ? x : fixed_, v = alongU_ ? fixed_ : x;
  const int uIndex = alongU_ ? moving_.flatIndex : fixedIndex_;
  const int vIndex = alongU_ ? fixedIndex_ : moving_.flatIndex;
  // Geom_BSplineSurface::D1's own call: flat knots, no multiplicities, its rational flags.
  BSplSLib::D1(u, v, uIndex, vIndex, surface_.Poles(), surface_.Weights(), surface_.UKnotSequence(),
               surface_.VKnotSequence(), BSplCLib::NoMults(), BSplCLib::NoMults(), surface_.UDegree(),
               surface_.VDegree(), surface_.IsURational(), surface_.IsVRational(), Standard_False,
               Standard_False, p, du, dv);
  d = alongU_ ? du : dv;
}

}  // namespace tessera
