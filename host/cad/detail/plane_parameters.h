// A plane's (u, v) of many points, as ElSLib::Parameters(plane, point, u, v) gives them, bit for
// bit: OCCT's PlaneParameters builds the plane's gp_Trsf (SetTransformation(position)) at every
// call and takes the transformed point's x and y; built once here and applied the same way.
// The import projects every sample of a plane's edges without a stored pcurve (to_trimmed.cpp):
// the transform was about half of that.
#pragma once
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Trsf.hxx>

namespace tessera::cad_detail {

class PlaneParameters {
 public:
  explicit PlaneParameters(const gp_Pln& plane) { toPlane_.SetTransformation(plane.Position()); }
  gp_Pnt2d operator()(const gp_Pnt& point) const {
    const gp_Pnt local = point.Transformed(toPlane_);
    return gp_Pnt2d(local.X(), local.Y());
  }

 private:
  gp_Trsf toPlane_;
};

}  // namespace tessera::cad_detail
