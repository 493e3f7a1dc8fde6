// Geom_BSplineSurface::D0 (OCCT 7.6) with the span's preparation kept between calls.
#include "cad/surface_point.h"

#include <BSplCLib.hxx>
#include <Standard_Real.hxx>
#include <algorithm>
#include <cmath>

namespace tessera {

SurfacePoint::SurfacePoint(const Handle(Geom_Surface)& surface) : surface_(*surface) {
  const auto* bspline = dynamic_cast<const Geom_BSplineSurface*>(surface.get());
  if (!bspline || bspline->IsUPeriodic() || bspline->IsVPeriodic() ||
      std::max(bspline->UDegree(), bspline->VDegree()) > kMaxKeptDegree)
    return;
  bspline_ = bspline;
  uFirst_ = bspline->UDegree() <= bspline->VDegree();
  degree1_ = uFirst_ ? bspline->UDegree() : bspline->VDegree();
  degree2_ = uFirst_ ? bspline->VDegree() : bspline->UDegree();
}

void SurfacePoint::locate(int degree, const TColStd_Array1OfReal& flatKnots, double t, Span& span) {
  int index = 0;
  double newT = t;
  BSplCLib::LocateParameter(degree, flatKnots, BSplCLib::NoMults(), t, Standard_False, index, newT);
  span.flatIndex = index;
  // For t strictly inside (K(index), K(index+1) − margin) the search gives `index` again: it
  // lands in the one non-empty span holding t, farther from the next knot than its Eps,
  // Epsilon(min(|the domain's last knot|, |t|)) ≤ Epsilon(|last knot|) (IsoLineD1 likewise).
  if (index < flatKnots.Upper()) {
    span.lo = flatKnots(index);
    span.hi = flatKnots(index + 1) - 2.0 * Epsilon(std::abs(flatKnots(flatKnots.Upper())));
  } else {
    span.lo = 1.0, span.hi = 0.0;
  }
}

void SurfacePoint::prepareSpans() {
  const Geom_BSplineSurface& s = *bspline_;
  const int uDegree = s.UDegree(), vDegree = s.VDegree();
  const TColStd_Array1OfReal& uKnots = s.UKnotSequence();
  const TColStd_Array1OfReal& vKnots = s.VKnotSequence();
  BSplCLib::BuildKnots(uDegree, u_.flatIndex, Standard_False, uKnots, BSplCLib::NoMults(), *(uFirst_ ? knots1_ : knots2_));
  BSplCLib::BuildKnots(vDegree, v_.flatIndex, Standard_False, vKnots, BSplCLib::NoMults(), *(uFirst_ ? knots2_ : knots1_));
  // The span's first pole and PrepareEval's test: weights that differ by more than the first
  // one's Epsilon make the span rational, else it is evaluated as polynomial.
  const TColgp_Array2OfPnt& poles = s.Poles();
  const TColStd_Array2OfReal* weights = s.Weights();
  const int row0 = poles.LowerRow() + u_.flatIndex - (uKnots.Lower() + uDegree);
  const int column0 = poles.LowerCol() + v_.flatIndex - (vKnots.Lower() + vDegree);
  rational_ = false;
  if ((s.IsURational() || s.IsVRational()) && weights) {
    const double w = weights->Value(row0, column0), eps = Epsilon(w);
    for (int i = 0; i <= uDegree && !rational_; ++i)
      for (int j = 0; j <= vDegree && !rational_; ++j)
        rational_ = std::abs(weights->Value(row0 + i, column0 + j) - w) > eps;
  }
  dimension_ = rational_ ? 4 : 3;
  double* pole = poles_;
  for (int a = 0; a <= degree1_; ++a)
    for (int b = 0; b <= degree2_; ++b) {
      const int row = row0 + (uFirst_ ? a : b), column = column0 + (uFirst_ ? b : a);
      const gp_Pnt& p = poles.Value(row, column);
      if (rational_) {
        const double w = weights->Value(row, column);
        pole[0] = p.X() * w, pole[1] = p.Y() * w, pole[2] = p.Z() * w, pole[3] = w;
      } else {
        pole[0] = p.X(), pole[1] = p.Y(), pole[2] = p.Z();
      }
      pole += dimension_;
    }
  preparedU_ = u_.flatIndex, preparedV_ = v_.flatIndex;
}

gp_Pnt SurfacePoint::value(double u, double v) {
  if (!bspline_) return surface_.Value(u, v);
  if (!(u > u_.lo && u < u_.hi)) locate(bspline_->UDegree(), bspline_->UKnotSequence(), u, u_);
  if (!(v > v_.lo && v < v_.hi)) locate(bspline_->VDegree(), bspline_->VKnotSequence(), v, v_);
  if (u_.flatIndex != preparedU_ || v_.flatIndex != preparedV_) prepareSpans();
  // BSplSLib::HomogeneousD0's two evaluations, then D0's division by the weight.
  const int dim = dimension_;
  double work[kMaxBlock];
  std::copy(poles_, poles_ + dim * (degree1_ + 1) * (degree2_ + 1), work);
  BSplCLib::Eval(uFirst_ ? u : v, degree1_, *knots1_, dim * (degree2_ + 1), *work);
  BSplCLib::Eval(uFirst_ ? v : u, degree2_, *knots2_, dim, *work);
  const double w = rational_ ? work[3] : 1.0e0;
  return gp_Pnt(work[0] / w, work[1] / w, work[2] / w);
}

}  // namespace tessera
