// Face surface → non-periodic NURBS → rational Bézier pieces, and the (u, v) → (u', v') map.
#include "cad/face_surface.h"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Convert_ConeToBSplineSurface.hxx>
#include <Convert_CylinderToBSplineSurface.hxx>
#include <ElCLib.hxx>
#include <GeomConvert.hxx>
#include <Precision.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_Plane.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Conic.hxx>
#include <Geom_Line.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <type_traits>

#include "bspline/bspline.h"
#include "cad/detail/kind_of.h"
#include "cad/detail/number_text.h"
#include "cad/iso_line_d1.h"
#include "common/hash_map.h"
#include "geometry/bezier.h"

namespace tessera {
namespace {

glm::dvec3 toGlm(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The flat knot vector (each knot repeated by its multiplicity).
std::vector<double> flatKnots(const Handle(Geom_BSplineSurface)& s, bool alongU) {
  const int count = alongU ? s->NbUPoles() + s->UDegree() + 1 : s->NbVPoles() + s->VDegree() + 1;
  TColStd_Array1OfReal seq(1, count);
  if (alongU) s->UKnotSequence(seq); else s->VKnotSequence(seq);
  return std::vector<double>(seq.begin(), seq.end());
}

// True when every knot of the direction already has its Bézier multiplicity: the degree p
// inside, p + 1 at the ends (GeomConvert's circles and lines, a plane's or cone's bilinear
// net): no knot to insert.
bool bezierMultiplicities(const Handle(Geom_BSplineSurface)& s, bool alongU) {
  const int degree = alongU ? s->UDegree() : s->VDegree();
  const int knots = alongU ? s->NbUKnots() : s->NbVKnots();
  for (int k = 1; k <= knots; ++k) {
    const int m = alongU ? s->UMultiplicity(k) : s->VMultiplicity(k);
    if (m != (k == 1 || k == knots ? degree + 1 : degree)) return false;
  }
  return true;
}

// The pieces of a surface whose knots need no insertion (bezierMultiplicities both ways): the
// insertion's matrices are then identities (osloMatrix of a knot vector on itself gives exact
// 1s and 0s), which pass each weighted point and weight on as 0 + 1·(0 + 1·x), so each piece
// is the block of the net its span owns, taken with that arithmetic (−0 comes out +0) and
// divided as rationalPieces divides: the same bits without the matrices and the nets' copies.
std::vector<BezierPatchPiece> blockPieces(const Handle(Geom_BSplineSurface)& s) {
  const int p = s->UDegree(), q = s->VDegree();
  const int spansU = s->NbUKnots() - 1, spansV = s->NbVKnots() - 1;
  const bool rational = s->IsURational() || s->IsVRational();
  const TColgp_Array2OfPnt& poles = s->Poles();
  const TColStd_Array2OfReal* weights = rational ? s->Weights() : nullptr;
  std::vector<BezierPatchPiece> pieces(size_t(spansU) * size_t(spansV));
  for (int a = 0; a < spansU; ++a)
    for (int b = 0; b < spansV; ++b) {
      BezierPatchPiece& piece = pieces[size_t(a) * size_t(spansV) + size_t(b)];
      piece.u0 = s->UKnot(a + 1), piece.u1 = s->UKnot(a + 2);
      piece.v0 = s->VKnot(b + 1), piece.v1 = s->VKnot(b + 2);
      BezierPatch& patch = piece.patch;
      patch.degreeU = p, patch.degreeV = q;
      patch.cp.resize(size_t(p + 1) * size_t(q + 1));
      if (rational) patch.weights.resize(patch.cp.size());
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
          const int row = a * p + i + 1, column = b * q + j + 1;
          const size_t c = size_t(i) * size_t(q + 1) + size_t(j);
          if (!rational) {
            patch.cp[c] = 0.0 + (0.0 + toGlm(poles(row, column)) * 1.0);
            continue;
          }
          const double w = (*weights)(row, column);
          const double passed = 0.0 + (0.0 + w);
          if (!(passed > 0.0)) throw CadFaceError("a NURBS weight is not positive after knot insertion");
          patch.cp[c] = (0.0 + (0.0 + toGlm(poles(row, column)) * w)) / passed;
          patch.weights[c] = passed;
        }
    }
  return pieces;
}

// Knot insertion is linear in the control points, so the Bézier pieces of the homogeneous
// surface (w·P, w) are those of (w·P) and of (w) taken apart; dividing gives the rational pieces.
std::vector<BezierPatchPiece> rationalPieces(const Handle(Geom_BSplineSurface)& s,
                                             ConversionRoute route) {
  if (route == ConversionRoute::Direct && bezierMultiplicities(s, true) &&
      bezierMultiplicities(s, false))
    return blockPieces(s);
  BSplineSurface weighted;
  weighted.degreeU = s->UDegree();
  weighted.degreeV = s->VDegree();
  weighted.knotsU = flatKnots(s, true);
  weighted.knotsV = flatKnots(s, false);
  weighted.countU = s->NbUPoles();
  weighted.countV = s->NbVPoles();
  const bool rational = s->IsURational() || s->IsVRational();
  std::vector<glm::dvec3> weights;  // w in x, a net on the same knots
  weighted.cp.reserve(size_t(weighted.countU) * size_t(weighted.countV));
  weights.reserve(weighted.cp.capacity());
  for (int i = 1; i <= s->NbUPoles(); ++i)
    for (int j = 1; j <= s->NbVPoles(); ++j) {
      const double w = rational ? s->Weight(i, j) : 1.0;
      weighted.cp.push_back(toGlm(s->Pole(i, j)) * w);
      weights.push_back({w, 0.0, 0.0});
    }
  if (!rational) return bezierPatches(weighted);  // weights 1 stay 1: no division
  // Both nets through one set of insertion matrices (bezierPatchPair).
  std::pair<std::vector<BezierPatchPiece>, std::vector<BezierPatchPiece>> both =
      bezierPatchPair(weighted, weights);
  std::vector<BezierPatchPiece>& pieces = both.first;
  for (size_t k = 0; k < pieces.size(); ++k) {
    BezierPatch& patch = pieces[k].patch;
    patch.weights.resize(patch.cp.size());
    for (size_t c = 0; c < patch.cp.size(); ++c) {
      const double w = both.second[k].patch.cp[c].x;
      if (!(w > 0.0)) throw CadFaceError("a NURBS weight is not positive after knot insertion");
      patch.cp[c] /= w;
      patch.weights[c] = w;
    }
  }
  return std::move(pieces);
}

double poleDiagonal(const Handle(Geom_BSplineSurface)& s) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int i = 1; i <= s->NbUPoles(); ++i)
    for (int j = 1; j <= s->NbVPoles(); ++j) {
      lo = glm::min(lo, toGlm(s->Pole(i, j)));
      hi = glm::max(hi, toGlm(s->Pole(i, j)));
    }
  return glm::length(hi - lo);
}

// The distinct knot whose iso-line is longest: f (or g) is solved on it, away from poles.
double longestIsoKnot(const CadSurface& f, bool knotAlongU) {
  const Handle(Geom_BSplineSurface)& s = f.nurbs;
  double u0, u1, v0, v1;
  s->Bounds(u0, u1, v0, v1);
  // The domain's knots only: a surface made non-periodic keeps knots outside its bounds.
  const int first = knotAlongU ? s->FirstUKnotIndex() : s->FirstVKnotIndex();
  const int last = knotAlongU ? s->LastUKnotIndex() : s->LastVKnotIndex();
  double best = -1.0, bestKnot = knotAlongU ? u0 : v0;
  for (int k = first; k <= last; ++k) {
    const double knot = knotAlongU ? s->UKnot(k) : s->VKnot(k);
    double length = 0.0;
    gp_Pnt previous;
    for (int i = 0; i <= 8; ++i) {
      const double t = knotAlongU ? v0 + (v1 - v0) * i / 8.0 : u0 + (u1 - u0) * i / 8.0;
      gp_Pnt p = knotAlongU ? f.original->Value(knot, t) : f.original->Value(t, knot);
      if (i > 0) length += p.Distance(previous);
      previous = p;
    }
    if (length > best) best = length, bestKnot = knot;
  }
  return bestKnot;
}

void shiftKnots(const Handle(Geom_BSplineSurface)& s, bool alongU, double shift) {
  double n0, n1, m0, m1;
  s->Bounds(n0, n1, m0, m1);
  if (std::abs(shift) <= 1e-9 * std::max({1.0, std::abs(n0), std::abs(n1), std::abs(m0), std::abs(m1)}))
    return;
  TColStd_Array1OfReal knots(1, alongU ? s->NbUKnots() : s->NbVKnots());
  if (alongU) s->UKnots(knots); else s->VKnots(knots);
  for (double& k : knots) k += shift;
  if (alongU) s->SetUKnots(knots); else s->SetVKnots(knots);
}

// `shift` rounded to a whole number of periods.
double wholePeriods(double shift, double period) { return period * std::round(shift / period); }

// The periodic NURBS of a face that wraps a whole period (in u, v or both), cut into one period
// that starts where the face does: at the NURBS parameter of the face's u0 (v0), found by mapUv's
// solver on the periodic NURBS; that start is in general not a knot, since a circle's rational
// parameter is its angle only at the knots.
void wholePeriodCut(CadSurface& f, bool alongU, bool alongV, double u0, double v0) {
  double n0, n1, m0, m1;
  f.nurbs->Bounds(n0, n1, m0, m1);
  if ((alongU && !f.nurbs->IsUPeriodic()) || (alongV && !f.nurbs->IsVPeriodic()))
    throw CadFaceError("the NURBS form of a face that wraps a whole period is not periodic");
  f.reparametrised = true;
  f.uRef = longestIsoKnot(f, true);
  f.vRef = longestIsoKnot(f, false);
  // The face's start moved into the NURBS's period (it starts where OCCT's surface does).
  const auto intoPeriod = [](double x, double lo, double hi) {
    return lo + (x - lo) - (hi - lo) * std::floor((x - lo) / (hi - lo));
  };
  const glm::dvec2 start = f.mapUv(gp_Pnt2d(alongU ? intoPeriod(u0, n0, n1) : u0,
                                            alongV ? intoPeriod(v0, m0, m1) : v0));
  f.nurbs->Segment(alongU ? start.x : n0, alongU ? start.x + (n1 - n0) : n1,
                   alongV ? start.y : m0, alongV ? start.y + (m1 - m0) : m1);
  f.reparametrised = false;
}

// A plane over [u0, u1] × [v0, v1] without GeomConvert and the knot insertion, which take most
// of a planar face's conversion (a trimmed copy of the plane, arrays, insertion matrices) to
// give what this gives: GeomConvert's NURBS is bilinear through the plane's points at the
// corners, knots at the bounds, and its one Bézier piece is that net, which the insertion's
// identity matrices pass on as 0 + 1·x (so −0 comes out +0: the same bits as that path). No
// NURBS is kept: a plane's (u, v) need no map, and its piece is its net.
CadSurface planeSurface(CadSurface& result, double u0, double u1, double v0, double v1) {
  const Handle(Geom_Surface)& plane = result.original;
  BezierPatchPiece piece;
  piece.u0 = u0, piece.u1 = u1, piece.v0 = v0, piece.v1 = v1;
  piece.patch.degreeU = piece.patch.degreeV = 1;
  piece.patch.cp.reserve(4);
  for (const double u : {u0, u1})
    for (const double v : {v0, v1}) piece.patch.cp.push_back(0.0 + (0.0 + toGlm(plane->Value(u, v))));
  result.pieces.push_back(std::move(piece));
  return std::move(result);
}

// What GeomConvert's BSplineSurfaceBuilder makes of a Convert_ class's result: its poles,
// weights, knots and multiplicities copied into a Geom_BSplineSurface.
Handle(Geom_BSplineSurface) builtFrom(const Convert_ElementarySurfaceToBSplineSurface& c) {
  TColgp_Array2OfPnt poles(1, c.NbUPoles(), 1, c.NbVPoles());
  TColStd_Array2OfReal weights(1, c.NbUPoles(), 1, c.NbVPoles());
  TColStd_Array1OfReal knotsU(1, c.NbUKnots()), knotsV(1, c.NbVKnots());
  TColStd_Array1OfInteger multsU(1, c.NbUKnots()), multsV(1, c.NbVKnots());
  for (int j = 1; j <= c.NbVPoles(); ++j)
    for (int i = 1; i <= c.NbUPoles(); ++i) {
      poles(i, j) = c.Pole(i, j);
      weights(i, j) = c.Weight(i, j);
    }
  for (int i = 1; i <= c.NbUKnots(); ++i) knotsU(i) = c.UKnot(i), multsU(i) = c.UMultiplicity(i);
  for (int i = 1; i <= c.NbVKnots(); ++i) knotsV(i) = c.VKnot(i), multsV(i) = c.VMultiplicity(i);
  return new Geom_BSplineSurface(poles, weights, knotsU, knotsV, multsU, multsV, c.UDegree(),
                                 c.VDegree(), c.IsUPeriodic(), c.IsVPeriodic());
}

// GeomConvert's NURBS of a cylinder or cone without the trimmed copy of the surface it is
// handed (which copies the surface) and its dispatch: the Convert_ class it calls, with the
// bounds Geom_RectangularTrimmedSurface gives it (u moved into the first period as its SetTrim
// moves it, v as is), built as its BSplineSurfaceBuilder builds. `wholeU`: untrimmed in u, the
// periodic form. Null for any other surface, or where GeomConvert would segment the periodic
// form (its knots off [0, 2π]), which the caller leaves to GeomConvert. The test compares this
// with GeomConvert on every cylinder and cone of the IDF library, bit for bit.
Handle(Geom_BSplineSurface) revolvedLineNurbs(const Handle(Geom_Surface)& basis, bool wholeU,
                                              double u0, double u1, double v0, double v1) {
  const auto convert = [&](const auto& surface) -> Handle(Geom_BSplineSurface) {
    using Converter = std::conditional_t<std::is_same_v<std::decay_t<decltype(surface)>, gp_Cylinder>,
                                         Convert_CylinderToBSplineSurface, Convert_ConeToBSplineSurface>;
    if (!wholeU) {
      ElCLib::AdjustPeriodic(0.0, 2.0 * M_PI, std::min(std::abs(u1 - u0) / 2, Precision::PConfusion()),
                             u0, u1);
      return builtFrom(Converter(surface, std::min(u0, u1), std::max(u0, u1), v0, v1));
    }
    Handle(Geom_BSplineSurface) periodic = builtFrom(Converter(surface, v0, v1));
    const double eps = 100. * Epsilon(2. * M_PI);
    if (std::abs(periodic->UKnot(1)) > eps ||
        std::abs(periodic->UKnot(periodic->NbUKnots()) - 2. * M_PI) > eps)
      return Handle(Geom_BSplineSurface)();
    return periodic;
  };
  if (const auto* cylinder = cad_detail::kindOf<Geom_CylindricalSurface>(basis.get()))
    return convert(cylinder->Cylinder());
  if (const auto* cone = cad_detail::kindOf<Geom_ConicalSurface>(basis.get()))
    return convert(cone->Cone());
  return Handle(Geom_BSplineSurface)();
}

// True when GeomConvert converts the curve exactly (a line, a conic, a B-spline or Bézier
// curve, trimmed or not), not by approximation (an offset curve, say).
bool exactlyConvertedCurve(Handle(Geom_Curve) curve) {
  while (const auto* trimmed = dynamic_cast<const Geom_TrimmedCurve*>(curve.get()))
    curve = trimmed->BasisCurve();
  return curve->IsKind(STANDARD_TYPE(Geom_Line)) || curve->IsKind(STANDARD_TYPE(Geom_Conic)) ||
         curve->IsKind(STANDARD_TYPE(Geom_BSplineCurve)) ||
         curve->IsKind(STANDARD_TYPE(Geom_BezierCurve));
}

// True when GeomConvert's NURBS of the surface is a tensor product of exact curve conversions,
// so the change of parameters is separable by construction: a cylinder, cone, sphere or torus
// (the Convert_ classes: a circle times a line or a circle), a surface of revolution whose
// meridian converts exactly (GeomConvert rotates the meridian's poles: a circle times it).
bool separableByConstruction(const Handle(Geom_Surface)& basis) {
  if (basis->IsKind(STANDARD_TYPE(Geom_CylindricalSurface)) ||
      basis->IsKind(STANDARD_TYPE(Geom_ConicalSurface)) ||
      basis->IsKind(STANDARD_TYPE(Geom_SphericalSurface)) ||
      basis->IsKind(STANDARD_TYPE(Geom_ToroidalSurface)))
    return true;
  if (const auto* revolution = dynamic_cast<const Geom_SurfaceOfRevolution*>(basis.get()))
    return exactlyConvertedCurve(revolution->BasisCurve());
  return false;
}

}  // namespace

double CadSurface::mapParameter(double t, bool alongU) const {
  if (!reparametrised) return t;
  IsoLineD1 line(*nurbs, alongU, alongU ? vRef : uRef);
  return solveParameter(t, alongU, line);
}

double CadSurface::solveParameter(double t, bool alongU, IsoLineD1& line) const {
  // Gauss–Newton on |N(u', vRef) − S(u, vRef)|² (and likewise for v): vRef is a knot, which
  // both parametrisations share, so the iso-lines are the same curve.
  const gp_Pnt target = alongU ? original->Value(t, vRef) : original->Value(uRef, t);
  double lo, hi, c0, c1;
  if (alongU) nurbs->Bounds(lo, hi, c0, c1); else nurbs->Bounds(c0, c1, lo, hi);
  const double width = hi - lo;
  // Each iterate is a function of the one before (line.d1 and the step are), so once one repeats
  // an earlier one bit for bit, the iteration cycles without meeting its stop and the last
  // iterate is known without the evaluations left: rounding makes a tenth of the solves cycle
  // (a period of 2 or 3 a few ulps wide), and they were half of all the solves' evaluations.
  constexpr int kIterations = 40;
  double iterates[kIterations];
  double x = t;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    iterates[iteration] = x;
    for (int earlier = 0; earlier < iteration; ++earlier)
      if (sameBits(iterates[earlier], x))
        return iterates[earlier + (kIterations - earlier) % (iteration - earlier)];
    gp_Pnt p;
    gp_Vec d;
    line.d1(x, p, d);
    const double dd = d.SquareMagnitude();
    if (dd == 0.0) break;
    // A step never leaves the domain by more than its width (the map fixes the ends).
    const double step = gp_Vec(p, target).Dot(d) / dd;
    x = std::clamp(x + step, lo - width, hi + width);
    if (std::abs(step) <= 1e-15 * std::max(1.0, std::abs(x))) break;
  }
  return x;
}

glm::dvec2 CadSurface::mapUv(const gp_Pnt2d& uv) const {
  return {mapParameter(uv.X(), true), mapParameter(uv.Y(), false)};
}

std::vector<glm::dvec2> CadSurface::mapUvs(const std::vector<gp_Pnt2d>& uvs) const {
  std::vector<glm::dvec2> mapped;
  mapped.reserve(uvs.size());
  if (!reparametrised) {
    for (const gp_Pnt2d& uv : uvs) mapped.push_back({uv.X(), uv.Y()});
    return mapped;
  }
  // Keyed by the bits, so −0 and +0 (equal as doubles) keep their own solves; flat maps, no
  // node allocated per coordinate.
  HashMap<uint64_t, double> solved[2];
  // One evaluator per direction: the fixed knot's span found once, the moving one's kept.
  IsoLineD1 lines[2] = {IsoLineD1(*nurbs, true, vRef), IsoLineD1(*nurbs, false, uRef)};
  const auto solve = [&](double t, bool alongU) {
    uint64_t bits;
    std::memcpy(&bits, &t, sizeof bits);
    const auto [it, fresh] = solved[alongU ? 0 : 1].try_emplace(bits, 0.0);
    if (fresh) it.value() = solveParameter(t, alongU, lines[alongU ? 0 : 1]);
    return it->second;
  };
  for (const gp_Pnt2d& uv : uvs) mapped.push_back({solve(uv.X(), true), solve(uv.Y(), false)});
  return mapped;
}

Handle(Geom_Surface) faceBasisSurface(const TopoDS_Face& face) {
  Handle(Geom_Surface) basis = BRep_Tool::Surface(face);
  if (basis.IsNull()) throw CadFaceError("the face has no surface");
  while (const auto* trimmed = cad_detail::kindOf<Geom_RectangularTrimmedSurface>(basis.get())) {
    const Handle(Geom_Surface) inner = trimmed->BasisSurface();  // held while `basis` lets go
    basis = inner;
  }
  return basis;
}

CadSurface convertFaceSurface(const TopoDS_Face& face) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  return convertFaceSurface(faceBasisSurface(face), u0, u1, v0, v1);
}

CadSurface convertFaceSurface(const Handle(Geom_Surface)& basis, double u0, double u1, double v0,
                              double v1, ConversionRoute route) {
  CadSurface result;
  result.original = basis;
  double a, b, c, d;
  basis->Bounds(a, b, c, d);
  if (!basis->IsUPeriodic()) u0 = std::max(u0, a), u1 = std::min(u1, b);
  if (!basis->IsVPeriodic()) v0 = std::max(v0, c), v1 = std::min(v1, d);
  // A face that wraps a whole period can come out a hair wider than it (pcurve tolerance);
  // Geom_RectangularTrimmedSurface would then take the excess modulo the period and keep a
  // sliver. One period exactly; the hair lies outside the pieces' domain.
  if (basis->IsUPeriodic()) u1 = std::min(u1, u0 + basis->UPeriod());
  if (basis->IsVPeriodic()) v1 = std::min(v1, v0 + basis->VPeriod());
  // A sliver whose wires run back and forth along one curve has no area to mesh.
  if (!(u1 - u0 > 1e-12 * std::max(1.0, std::abs(u0))) || !(v1 - v0 > 1e-12 * std::max(1.0, std::abs(v0))))
    throw CadZeroAreaFace("zero-area face: its uv bounds are [" + cad_detail::numberText(u0) +
                          ", " + cad_detail::numberText(u1) + "] × [" + cad_detail::numberText(v0) +
                          ", " + cad_detail::numberText(v1) + "]");

  const bool direct = route == ConversionRoute::Direct;
  if (direct && basis->IsKind(STANDARD_TYPE(Geom_Plane))) return planeSurface(result, u0, u1, v0, v1);

  // A face that wraps a whole period is converted untrimmed in that direction, where the NURBS
  // stays periodic with its knots at the surface's own parameters (0, 2π/3, 4π/3 for a circle),
  // and then cut at the face's u0 (wholePeriodCut). Trimmed to the whole period instead,
  // GeomConvert converts the full circle and cuts it at u0 in the circle's rational parameter,
  // which is not the angle u0: the pieces then missed a sliver of the face at one end and
  // covered one of the next turn at the other (0.031 rad on RLF_7030's face 0).
  const double tiny = 1e-9;
  const bool wholeU = basis->IsUPeriodic() && u1 - u0 >= basis->UPeriod() * (1 - tiny);
  const bool wholeV = basis->IsVPeriodic() && v1 - v0 >= basis->VPeriod() * (1 - tiny);
  if (direct && !wholeV) result.nurbs = revolvedLineNurbs(basis, wholeU, u0, u1, v0, v1);
  // A non-periodic B-spline: GeomConvert copies it and segments the copy to the bounds, which
  // are the face's (clamped above, as Geom_RectangularTrimmedSurface and GeomConvert clamp
  // them); the trimmed surface it is handed first copies the B-spline once more.
  if (direct && !basis->IsUPeriodic() && !basis->IsVPeriodic())
    if (const auto* bspline = cad_detail::kindOf<Geom_BSplineSurface>(basis.get())) {
      result.nurbs = Handle(Geom_BSplineSurface)::DownCast(bspline->Copy());
      result.nurbs->Segment(u0, u1, v0, v1);
    }
  if (result.nurbs.IsNull()) {
    Handle(Geom_Surface) bounded;
    if (wholeU && wholeV)
      bounded = basis;
    else if (wholeU)
      bounded = new Geom_RectangularTrimmedSurface(basis, v0, v1, Standard_False);
    else if (wholeV)
      bounded = new Geom_RectangularTrimmedSurface(basis, u0, u1, Standard_True);
    else
      bounded = new Geom_RectangularTrimmedSurface(basis, u0, u1, v0, v1);
    result.nurbs = GeomConvert::SurfaceToBSplineSurface(bounded);
  }
  if (result.nurbs.IsNull()) throw CadFaceError("GeomConvert gave no NURBS form");
  if (wholeU || wholeV) wholePeriodCut(result, wholeU, wholeV, u0, v0);
  if (result.nurbs->IsUPeriodic()) result.nurbs->SetUNotPeriodic();
  if (result.nurbs->IsVPeriodic()) result.nurbs->SetVNotPeriodic();
  // Geom_RectangularTrimmedSurface moves a periodic range into the surface's first period;
  // the pcurves stay where they were, so move the knots back by that whole number of periods.
  double n0, n1, m0, m1;
  result.nurbs->Bounds(n0, n1, m0, m1);
  if (basis->IsUPeriodic()) shiftKnots(result.nurbs, true, wholePeriods(u0 - n0, basis->UPeriod()));
  if (basis->IsVPeriodic()) shiftKnots(result.nurbs, false, wholePeriods(v0 - m0, basis->VPeriod()));
  if (result.nurbs->UDegree() > kMaxDegree || result.nurbs->VDegree() > kMaxDegree)
    throw CadFaceError("surface degree " + std::to_string(result.nurbs->UDegree()) + "×" +
                       std::to_string(result.nurbs->VDegree()) + " is above 7");

  // Same parametrisation? A B-spline's NURBS is a segment of it (knots shifted by whole periods
  // above), as a plane's is bilinear between its corners at its own (u, v) (planeSurface): the
  // same, so no check (it evaluated both surfaces at 36 points and found a gap of rounding).
  // Otherwise compare at a grid of interior points; if not the same, solve f and g and check
  // that they reproduce the surface (separability, see the header).
  if (basis->IsKind(STANDARD_TYPE(Geom_BSplineSurface))) {
    result.pieces = rationalPieces(result.nurbs, route);
    return result;
  }
  const double scale = std::max(1e-300, poleDiagonal(result.nurbs));
  result.nurbs->Bounds(n0, n1, m0, m1);
  // Fractions that are neither knots nor span middles of an even split, where the angle and
  // the rational parameter agree.
  const double fractions[] = {0.0613, 0.2371, 0.4159, 0.5873, 0.7741, 0.9387};
  // Only whether some point of the grid is off by more than 1e-10 of the size matters: the
  // first such point settles it. The diagonal first (every u and every v among its six).
  const double identityTolerance = 1e-10 * scale;
  bool sameParameters = true;
  for (size_t shift = 0; shift < std::size(fractions) && sameParameters; ++shift)
    for (size_t i = 0; i < std::size(fractions); ++i) {
      const double u = n0 + (n1 - n0) * fractions[i];
      const double v = m0 + (m1 - m0) * fractions[(i + shift) % std::size(fractions)];
      if (result.nurbs->Value(u, v).Distance(basis->Value(u, v)) > identityTolerance) {
        sameParameters = false;
        break;
      }
    }
  if (!sameParameters) {
    result.reparametrised = true;
    result.uRef = longestIsoKnot(result, true);
    result.vRef = longestIsoKnot(result, false);
    // A NURBS that is a tensor product of exact curve conversions (separableByConstruction)
    // passes the check below (12 solves, 72 evaluations, most of such a face's conversion)
    // by construction; the GeomConvert route, which the tests compare with this one, still
    // makes it.
    if (direct && separableByConstruction(basis)) {
      result.pieces = rationalPieces(result.nurbs, route);
      return result;
    }
    // The grid has 6 distinct u and 6 distinct v: 12 solves, not 72.
    double mappedU[std::size(fractions)], mappedV[std::size(fractions)];
    for (size_t k = 0; k < std::size(fractions); ++k) {
      mappedU[k] = result.mapParameter(n0 + (n1 - n0) * fractions[k], true);
      mappedV[k] = result.mapParameter(m0 + (m1 - m0) * fractions[k], false);
    }
    double gap = 0.0;
    for (size_t i = 0; i < std::size(fractions); ++i)
      for (size_t j = 0; j < std::size(fractions); ++j) {
        const double u = n0 + (n1 - n0) * fractions[i], v = m0 + (m1 - m0) * fractions[j];
        gap = std::max(gap, result.nurbs->Value(mappedU[i], mappedV[j]).Distance(basis->Value(u, v)));
      }
    if (gap > 1e-9 * scale)
      throw CadFaceError("the NURBS form's parameters are not a separable change of the face's (off by " +
                         cad_detail::numberText(gap) + ")");
  }
  result.pieces = rationalPieces(result.nurbs, route);
  return result;
}

RevolutionForm revolutionFormOf(const Handle(Geom_Surface)& surface) {
  RevolutionForm form;
  // Planes and B-splines, most faces, are none of the four: no four failed DownCasts for them.
  const Handle(Standard_Type)& type = surface->DynamicType();
  if (type == STANDARD_TYPE(Geom_Plane) || type == STANDARD_TYPE(Geom_BSplineSurface)) return form;
  const auto axisOf = [&](const gp_Ax3& position) {
    form.origin = toGlm(position.Location());
    const gp_Dir& d = position.Direction();
    form.axis = {d.X(), d.Y(), d.Z()};
  };
  if (auto cylinder = Handle(Geom_CylindricalSurface)::DownCast(surface)) {
    axisOf(cylinder->Position());
    form.profile = RevolutionForm::Profile::Line;
  } else if (auto cone = Handle(Geom_ConicalSurface)::DownCast(surface)) {
    axisOf(cone->Position());
    form.profile = RevolutionForm::Profile::Line;
  } else if (auto sphere = Handle(Geom_SphericalSurface)::DownCast(surface)) {
    axisOf(sphere->Position());
    form.profile = RevolutionForm::Profile::Circle;
    form.circleCentre = 0.0;
    form.circleRadius = sphere->Radius();
  } else if (auto torus = Handle(Geom_ToroidalSurface)::DownCast(surface)) {
    // A ring torus only: where the tube reaches the axis, ρ = R + r·cos v changes sign.
    if (!(torus->MajorRadius() > torus->MinorRadius())) return form;
    axisOf(torus->Position());
    form.profile = RevolutionForm::Profile::Circle;
    form.circleCentre = torus->MajorRadius();
    form.circleRadius = torus->MinorRadius();
  }
  return form;
}

glm::dvec3 piecesPoint(const std::vector<BezierPatchPiece>& pieces, glm::dvec2 uv) {
  const BezierPatchPiece* best = nullptr;
  double bestOutside = 1e300;
  for (const auto& piece : pieces) {
    const double du = std::max({piece.u0 - uv.x, uv.x - piece.u1, 0.0});
    const double dv = std::max({piece.v0 - uv.y, uv.y - piece.v1, 0.0});
    if (du + dv < bestOutside) bestOutside = du + dv, best = &piece;
    if (bestOutside == 0.0) break;
  }
  if (!best) return glm::dvec3(0.0);
  const double s = (uv.x - best->u0) / (best->u1 - best->u0);
  const double r = (uv.y - best->v0) / (best->v1 - best->v0);
  return patchPoint(best->patch, s, r);
}

}  // namespace tessera
