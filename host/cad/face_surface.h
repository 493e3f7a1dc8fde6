// A B-rep face's surface as Tessera's rational Bézier pieces (docs/cad.md, "Surfaces").
// The face's surface is converted to a non-periodic NURBS over the face's uv bounds
// (GeomConvert: exact rational forms for planes, cylinders, cones, spheres, tori, surfaces of
// revolution and extrusion), then cut into rational Bézier pieces by Tessera's knot insertion
// (bspline/to_bezier.h) applied to the weighted points (w·x, w·y, w·z) and the weights.
//
// Exact rational forms of circles are not parametrised by angle, so for a converted analytic
// surface the NURBS parameter (u', v') differs from the face's (u, v) inside each span. OCCT
// converts these surfaces as tensor products, so the change is separable: u' = f(u),
// v' = g(v), with f and g fixing the knots. mapUv finds f and g by Newton's method on one
// iso-line per direction and the conversion checks the result at interior points (not where
// the NURBS is a tensor product of exact curve conversions, separable by construction).
// Planes, cylinders, cones and non-periodic B-splines skip GeomConvert itself for what it would
// give them, bit for bit (docs/cad.md, "Surfaces").
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt2d.hxx>
#include <stdexcept>
#include <string>
#include <vector>

#include "bspline/to_bezier.h"
#include "trim/trimmed_face.h"

namespace tessera {

// Why a face could not be converted; toTrimmedModel adds the file and the face.
class CadFaceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A face whose loops span no width in u or in v: a sliver whose wires run back and forth along
// one curve. It has no area, so its mesh is empty: toTrimmedModel lists it in
// CadImport::emptyFaces, not in failures, and its edges stay with the faces beside it.
class CadZeroAreaFace : public CadFaceError {
 public:
  using CadFaceError::CadFaceError;
};

// Not trim/face_surface.h's FaceSurface (the mesher's evaluator of a TrimmedFace): one name for
// two classes in one namespace broke the one-definition rule (ASan saw one's destructor run on
// the other).
class IsoLineD1;

struct CadSurface {
  Handle(Geom_Surface) original;      // the face's surface, located (BRep_Tool::Surface)
  Handle(Geom_BSplineSurface) nurbs;  // non-periodic, over the face's uv bounds; null for a plane
  bool reparametrised = false;        // true when (u', v') ≠ (u, v) (a converted analytic surface)
  double uRef = 0.0, vRef = 0.0;      // the iso-lines f and g are solved on (see mapUv)
  std::vector<BezierPatchPiece> pieces;

  // The face's (u, v) (its pcurves' parameters) → the pieces' (u', v').
  glm::dvec2 mapUv(const gp_Pnt2d& uv) const;
  // One coordinate of mapUv: u' = f(u) (alongU) or v' = g(v); the change is separable.
  double mapParameter(double t, bool alongU) const;
  // mapUv of every point, each distinct coordinate solved once (a circle's points share their v
  // on a cylinder, a line's their u): the same doubles as mapUv point by point.
  std::vector<glm::dvec2> mapUvs(const std::vector<gp_Pnt2d>& uvs) const;

 private:
  // mapParameter's solve on `line` (the iso-line through vRef, alongU, or uRef).
  double solveParameter(double t, bool alongU, IsoLineD1& line) const;
};

// The face's surface (located, BRep_Tool::Surface) without its Geom_RectangularTrimmedSurface
// wrappers. Throws CadFaceError for a face without one.
Handle(Geom_Surface) faceBasisSurface(const TopoDS_Face& face);

// `basis` (faceBasisSurface) over the face's uv bounds [u0, u1] × [v0, v1]: the extent of its
// loops (clamped to a non-periodic surface's own bounds, at most one period in a periodic
// direction). Throws CadZeroAreaFace (a zero-area face), CadFaceError (a degree above 7, a
// surface GeomConvert cannot convert exactly, a reparametrisation that does not check out) or
// lets Standard_Failure through.
// `route`: Direct builds planes, cylinders and cones without GeomConvert and cuts a NURBS whose
// knots need no insertion into its blocks; GeomConvert takes GeomConvert and the knot insertion
// for every surface, the reference the tests compare Direct with (the same bits).
enum class ConversionRoute { Direct, GeomConvert };
CadSurface convertFaceSurface(const Handle(Geom_Surface)& basis, double u0, double u1, double v0,
                              double v1, ConversionRoute route = ConversionRoute::Direct);
// The same over BRepTools::UVBounds (the pcurves' boxes; the import takes its loop points'
// extent instead, to_trimmed.cpp).
CadSurface convertFaceSurface(const TopoDS_Face& face);

// The face's surface as a surface of revolution with a straight or circular profile, as the
// trimmed mesher's geometric bound takes it (trim/trimmed_face.h): cylinders, cones, spheres
// and ring tori (Open CASCADE's u turns about the axis, v runs along the profile); Profile::None
// for every other surface.
RevolutionForm revolutionFormOf(const Handle(Geom_Surface)& surface);

// The point of the pieces at (u', v'): the piece whose rectangle holds it (the nearest at the
// edges of the domain).
glm::dvec3 piecesPoint(const std::vector<BezierPatchPiece>& pieces, glm::dvec2 uv);

}  // namespace tessera
