// Geom_BSplineSurface::D1 (OCCT 7.6) along an iso-line, with the span's work done once.
#include "cad/iso_line_d1.h"

#include <BSplCLib.hxx>
#include <Standard_Real.hxx>
#include <algorithm>
#include <cmath>

#include "cad/detail/bohm_steps.h"

namespace tessera {

IsoLineD1::IsoLineD1(const Geom_BSplineSurface& surface, bool alongU, double fixed)
    : surface_(surface),
      alongU_(alongU),
      fixed_(fixed),
      kept_(!surface.IsUPeriodic() && !surface.IsVPeriodic() &&
            std::max(surface.UDegree(), surface.VDegree()) <= kMaxKeptDegree) {
  if (!kept_) return;
  fixedIndex_ = alongU ? locate(surface.VDegree(), surface.VKnots(), surface.VMultiplicities(), fixed, nullptr)
                       : locate(surface.UDegree(), surface.UKnots(), surface.UMultiplicities(), fixed, nullptr);
  const bool uFirst = surface.UDegree() <= surface.VDegree();
  fixedFirst_ = uFirst != alongU;
  degree1_ = uFirst ? surface.UDegree() : surface.VDegree();
  degree2_ = uFirst ? surface.VDegree() : surface.UDegree();
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

void IsoLineD1::prepareSpan() {
  // BSplSLib::D1's arguments: flat knots without multiplicities, flat span indices.
  const int uIndex = alongU_ ? moving_.flatIndex : fixedIndex_;
  const int vIndex = alongU_ ? fixedIndex_ : moving_.flatIndex;
  const bool uFirst = fixedFirst_ != alongU_;
  const int uDegree = surface_.UDegree(), vDegree = surface_.VDegree();
  const TColStd_Array1OfReal& uKnots = surface_.UKnotSequence();
  const TColStd_Array1OfReal& vKnots = surface_.VKnotSequence();
  BSplCLib::BuildKnots(uDegree, uIndex, Standard_False, uKnots, BSplCLib::NoMults(), *(uFirst ? knots1_ : knots2_));
  BSplCLib::BuildKnots(vDegree, vIndex, Standard_False, vKnots, BSplCLib::NoMults(), *(uFirst ? knots2_ : knots1_));
  // The span's first pole (without multiplicities: the flat index less the degree and the
  // sequence's lower bound), and whether its weights differ by more than the first one's
  // Epsilon: else D1 evaluates it as polynomial, without the weights.
  const TColgp_Array2OfPnt& poles = surface_.Poles();
  const TColStd_Array2OfReal* weights = surface_.Weights();
  const int row0 = poles.LowerRow() + uIndex - (uKnots.Lower() + uDegree);
  const int column0 = poles.LowerCol() + vIndex - (vKnots.Lower() + vDegree);
  rational_ = false;
  if ((surface_.IsURational() || surface_.IsVRational()) && weights) {
    const double w = weights->Value(row0, column0), eps = Epsilon(w);
    for (int i = 0; i <= uDegree && !rational_; ++i)
      for (int j = 0; j <= vDegree && !rational_; ++j)
        rational_ = std::abs(weights->Value(row0 + i, column0 + j) - w) > eps;
  }
  dimension_ = rational_ ? 4 : 3;
  // PrepareEval's layout: degree1_ + 1 rows (the first direction) of degree2_ + 1 points.
  double* pole = prepared_;
  for (int a = 0; a <= degree1_; ++a)
    for (int b = 0; b <= degree2_; ++b) {
      const int row = row0 + (uFirst ? a : b), column = column0 + (uFirst ? b : a);
      const gp_Pnt& p = poles.Value(row, column);
      if (rational_) {
        const double w = weights->Value(row, column);
        pole[0] = p.X() * w, pole[1] = p.Y() * w, pole[2] = p.Z() * w, pole[3] = w;
      } else {
        pole[0] = p.X(), pole[1] = p.Y(), pole[2] = p.Z();
      }
      pole += dimension_;
    }
  // Bohm's first step (cad_detail::bohmDifferences) does not depend on the parameter: kept.
  // Fixed first: D1's first Bohm, along the first direction at `fixed`, gives the one row the
  // second reads (its value row, the same for any number of derivatives), then that row's
  // differences along the second; else the differences of the block along the first direction.
  const int row = dimension_ * (degree2_ + 1);
  if (fixedFirst_) {
    BSplCLib::Bohm(fixed_, degree1_, 0, *knots1_, row, *prepared_);
    cad_detail::bohmDifferences(degree2_, knots2_, dimension_, prepared_);
  } else {
    cad_detail::bohmDifferences(degree1_, knots1_, row, prepared_);
  }
  preparedIndex_ = moving_.flatIndex;
}

void IsoLineD1::d1(double x, gp_Pnt& p, gp_Vec& d) {
  if (!kept_) {
    gp_Vec du, dv;
    if (alongU_) surface_.D1(x, fixed_, p, du, dv); else surface_.D1(fixed_, x, p, du, dv);
    d = alongU_ ? du : dv;
    return;
  }
  if (!(x > moving_.lo && x < moving_.hi))
    moving_.flatIndex = alongU_ ? locate(surface_.UDegree(), surface_.UKnots(), surface_.UMultiplicities(), x, &moving_)
                                : locate(surface_.VDegree(), surface_.VKnots(), surface_.VMultiplicities(), x, &moving_);
  if (moving_.flatIndex != preparedIndex_) prepareSpan();
  const int dim = dimension_;
  const int row = dim * (degree2_ + 1);  // one row of the first direction
  double work[kMaxBlock];
  const double* value;       // homogeneous when rational: (w·x, w·y, w·z, w)
  const double* derivative;  // along the line, likewise
  if (fixedFirst_) {
    // The line runs along the second direction: D1's second Bohm on the kept row gives the
    // point and its derivative there; the first direction's derivative is not needed.
    std::copy(prepared_, prepared_ + row, work);
    cad_detail::bohmAt(x, degree2_, 1, knots2_, dim, work);
    value = work, derivative = work + dim;
  } else {
    // The line runs along the first direction: D1's first Bohm in full, then the second
    // direction's value at `fixed` of the value row (Bohm) and of the derivative row (Eval).
    std::copy(prepared_, prepared_ + row * (degree1_ + 1), work);
    cad_detail::bohmAt(x, degree1_, 1, knots1_, row, work);
    BSplCLib::Bohm(fixed_, degree2_, 0, *knots2_, dim, *work);  // value row 0 (N leaves it)
    BSplCLib::Eval(fixed_, degree2_, *knots2_, dim, *(work + row));
    value = work, derivative = work + row;
  }
  double ders[6];
  const double* result = value;
  if (rational_) {
    // BSplSLib::RationalDerivative's (0, 0) and first derivative along the line: the quotient
    // rule, 1/w as a product, the weight's derivative times the point subtracted first.
    const double inverse = 1.0e0 / value[3];
    for (int k = 0; k < 3; ++k) {
      ders[k] = value[k] * inverse;
      ders[3 + k] = (derivative[k] - derivative[3] * ders[k]) * inverse;
    }
    result = ders, derivative = ders + 3;
  }
  p.SetCoord(result[0], result[1], result[2]);
  d.SetCoord(derivative[0], derivative[1], derivative[2]);
}

}  // namespace tessera
