// BRepAdaptor_Curve::Value (OCCT 7.6) on a B-spline edge with a cache per knot span.
#include "cad/edge_points.h"

#include <BSplCLib.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <algorithm>

namespace tessera {

EdgePoints::EdgePoints(const BRepAdaptor_Curve& curve) : curve_(curve) {
  if (curve.GetType() != GeomAbs_BSplineCurve || !curve.Is3DCurve()) return;
  const GeomAdaptor_Curve& adaptor = curve.Curve();
  bspline_ = adaptor.BSpline();
  if (bspline_.IsNull()) return;
  first_ = adaptor.FirstParameter();
  last_ = adaptor.LastParameter();
  caches_.resize(size_t(bspline_->KnotSequence().Length()) + 1);
}

glm::dvec3 EdgePoints::at(double t) {
  // The range's ends: GeomAdaptor_Curve evaluates them locally (IsBoundary), not by the cache.
  if (bspline_.IsNull() || t == first_ || t == last_) {
    const gp_Pnt p = curve_.Value(t);
    return {p.X(), p.Y(), p.Z()};
  }
  // The adaptor's one cache: kept while its validity test takes t (a span is valid up to its
  // end as rounded, where a rebuild for t can pick the next span: which span evaluates t near
  // a knot depends on the calls before, so this keeps the adaptor's sequence of spans exactly),
  // else rebuilt for the span its BuildCache locates, here taken from the store.
  if (!current_ || !current_->IsCacheValid(t)) {
    const TColStd_Array1OfReal& knots = bspline_->KnotSequence();
    int index = 0;  // BSplCLib_CacheParams::LocateParameter's own call
    double located = t;
    BSplCLib::LocateParameter(bspline_->Degree(), knots, BSplCLib::NoMults(), located,
                              bspline_->IsPeriodic(), index, located);
    Handle(BSplCLib_Cache)& cache = caches_[size_t(index - knots.Lower())];
    if (cache.IsNull()) {
      cache = new BSplCLib_Cache(bspline_->Degree(), bspline_->IsPeriodic(), knots, bspline_->Poles(),
                                 bspline_->Weights());
      cache->BuildCache(t, knots, bspline_->Poles(), bspline_->Weights());
    }
    current_ = cache.get();
  }
  gp_Pnt p;
  current_->D0(t, p);
  p.Transform(curve_.Trsf());  // BRepAdaptor_Curve::Value's location
  return {p.X(), p.Y(), p.Z()};
}

}  // namespace tessera
