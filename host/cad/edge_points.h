// An edge's 3D points at scattered parameters, for its discretisation (edge_samples.cpp):
// BRepAdaptor_Curve::Value, except on a B-spline 3D curve, where the adaptor keeps one
// BSplCLib_Cache and rebuilds it whenever a parameter leaves its knot span: the bisection's
// checks jump between spans (a coarse segment's 15 samples can each fall in another span, and
// a child segment starts back at its parent's start), so most evaluations rebuilt it. Here each
// span's cache, built as the adaptor builds it, is kept for the edge, and the adaptor's choice
// of span is followed call by call (its validity test, then BuildCache's location of the
// span); the range's two ends take the adaptor's own path: the same bits (docs/cad.md, "Edges").
#pragma once
#include <BRepAdaptor_Curve.hxx>
#include <BSplCLib_Cache.hxx>
#include <Geom_BSplineCurve.hxx>
#include <glm/glm.hpp>
#include <vector>

namespace tessera {

class EdgePoints {
 public:
  // `curve` must outlive this.
  explicit EdgePoints(const BRepAdaptor_Curve& curve);
  // curve.Value(t), bit for bit.
  glm::dvec3 at(double t);

 private:
  const BRepAdaptor_Curve& curve_;
  Handle(Geom_BSplineCurve) bspline_;  // null: curve_.Value
  double first_ = 0.0, last_ = 0.0;    // the adaptor's range: its ends take its own path
  std::vector<Handle(BSplCLib_Cache)> caches_;  // by span: the flat knot index less the lowest
  BSplCLib_Cache* current_ = nullptr;           // the span the adaptor's one cache would hold
};

}  // namespace tessera
