// Faces and wires → trimmed faces and loops of shared points.
#include "cad/to_trimmed.h"

#include <BRepBndLib.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <cmath>

#include "cad/face_surface.h"
#include "cad/detail/number_text.h"
#include "tessera/errors.h"

namespace tessera {
namespace {

double signedArea(const std::vector<glm::dvec2>& uv) {
  double twice = 0.0;
  for (size_t k = 0; k < uv.size(); ++k) {
    const glm::dvec2 a = uv[k], b = uv[(k + 1) % uv.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

// One wire → one loop: edges in wire order, each edge's samples in the direction the wire uses
// it, mapped through the edge's pcurve on this face (for a seam, the orientation picks which of
// its two pcurves). Consecutive edges share their vertex point once.
TrimLoop wireLoop(const TopoDS_Wire& wire, const TopoDS_Face& face, const CadSurface& surface,
                  uint32_t faceIndex, const std::string& label, const std::string& path, CadImport& in) {
  TrimLoop loop;
  int explored = 0;
  uint32_t firstId = 0, lastId = 0;
  for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next(), ++explored) {
    const TopoDS_Edge& edge = it.Current();
    const int index = in.edges.FindIndex(edge);
    if (index == 0) throw CadFaceError("a wire edge is not in the shape's edge map");
    const EdgeSamples& samples = in.edgeSamples[static_cast<size_t>(index - 1)];
    double pf, pl;
    Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, pf, pl);
    if (pcurve.IsNull())
      throw CadFaceError("edge " + std::to_string(index - 1) + " has no pcurve on the face");
    const double f = samples.params.front(), l = samples.params.back();
    const bool reversed = edge.Orientation() == TopAbs_REVERSED;
    const size_t n = samples.params.size();
    if (explored == 0) firstId = samples.pointIds[reversed ? n - 1 : 0];
    else if (samples.pointIds[reversed ? n - 1 : 0] != lastId)
      throw CadFaceError("the wire is not connected at edge " + std::to_string(index - 1));
    double gap = 0.0;
    for (size_t k = 0; k < n; ++k) {
      const size_t s = reversed ? n - 1 - k : k;
      // Same range is the rule for pcurves (BRep_Tool::SameRange); map linearly if not.
      const double t = l > f ? pf + (samples.params[s] - f) * (pl - pf) / (l - f) : pf;
      const gp_Pnt2d uv = pcurve->Value(t);
      const gp_Pnt onSurface = surface.original->Value(uv.X(), uv.Y());
      gap = std::max(gap, glm::length(glm::dvec3(onSurface.X(), onSurface.Y(), onSurface.Z()) -
                                      in.model.sharedPoints[samples.pointIds[s]]));
      if (k + 1 == n) break;  // the next edge's first point
      loop.uv.push_back(surface.mapUv(uv));
      loop.pointIds.push_back(samples.pointIds[s]);
    }
    const double tolerance = BRep_Tool::Tolerance(edge);
    if (!samples.degenerated && gap > tolerance + 1e-3 * in.delta)
      in.warnings.push_back({faceIndex, static_cast<uint32_t>(index - 1), gap, tolerance,
                             path + ": " + label + ": edge " + std::to_string(index - 1) +
                                 ": its 3D curve and pcurve are " + cad_detail::numberText(gap) +
                                 " apart, beyond its tolerance " + cad_detail::numberText(tolerance)});
    lastId = samples.pointIds[reversed ? 0 : n - 1];
  }
  int edgeCount = 0;
  for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next()) ++edgeCount;
  if (explored != edgeCount)
    throw CadFaceError("the wire explorer ordered " + std::to_string(explored) + " of the wire's " +
                       std::to_string(edgeCount) + " edges");
  if (explored == 0 || lastId != firstId) throw CadFaceError("a wire is not closed");
  if (loop.uv.size() < 2) throw CadFaceError("a wire has fewer than two points");
  return loop;
}

TrimmedFace convertFace(const TopoDS_Face& sourceFace, uint32_t faceIndex, const std::string& label,
                        const std::string& path, CadImport& in) {
  // Loops in the surface's own orientation: outer counter-clockwise, holes clockwise; the
  // face's orientation goes to `reversed` (trimmed_face.h).
  const TopoDS_Face face = TopoDS::Face(sourceFace.Oriented(TopAbs_FORWARD));
  TrimmedFace out;
  out.reversed = sourceFace.Orientation() == TopAbs_REVERSED;
  CadSurface surface = convertFaceSurface(face);
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next())
    out.loops.push_back(wireLoop(TopoDS::Wire(w.Current()), face, surface, faceIndex, label, path, in));
  if (out.loops.empty()) throw CadFaceError("the face has no wire");
  out.pieces = std::move(surface.pieces);
  out.revolution = revolutionFormOf(surface.original);
  size_t outer = 0;
  std::vector<double> areas;
  for (const auto& loop : out.loops) areas.push_back(signedArea(loop.uv));
  for (size_t k = 1; k < areas.size(); ++k)
    if (std::abs(areas[k]) > std::abs(areas[outer])) outer = k;
  for (size_t k = 0; k < out.loops.size(); ++k) {
    const bool wantPositive = k == outer;
    if ((areas[k] > 0.0) != wantPositive) {
      std::reverse(out.loops[k].uv.begin(), out.loops[k].uv.end());
      std::reverse(out.loops[k].pointIds.begin(), out.loops[k].pointIds.end());
      ++in.loopsReversed;
    }
  }
  return out;
}

}  // namespace

double defaultCadTolerance(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  if (box.IsVoid()) return 1e-3;
  return 1e-3 * std::sqrt(box.SquareExtent());
}

CadImport toTrimmedModel(const CadFile& file, double delta) {
  if (!(delta > 0.0) || !std::isfinite(delta))
    throw ArgumentError("the CAD edge tolerance must be a positive distance, not " +
                        std::to_string(delta));
  CadImport in;
  in.delta = delta;
  TopExp::MapShapes(file.shape, TopAbs_FACE, in.faces);
  TopExp::MapShapes(file.shape, TopAbs_EDGE, in.edges);
  TopExp::MapShapes(file.shape, TopAbs_VERTEX, in.vertices);

  SharedPoints points;
  for (int k = 1; k <= in.vertices.Extent(); ++k) {
    const TopoDS_Vertex& v = TopoDS::Vertex(in.vertices(k));
    const gp_Pnt p = BRep_Tool::Pnt(v);
    points.positions.push_back({p.X(), p.Y(), p.Z()});
    points.tolerances.push_back(BRep_Tool::Tolerance(v));
  }
  for (int k = 1; k <= in.edges.Extent(); ++k) {
    in.edgeSamples.push_back(discretiseEdge(in.edges(k), delta, in.vertices, points));
    in.maxChordDeviation = std::max(in.maxChordDeviation, in.edgeSamples.back().maxChordDeviation);
  }
  in.model.sharedPoints = std::move(points.positions);
  in.pointTolerances = std::move(points.tolerances);

  for (int k = 1; k <= in.faces.Extent(); ++k) {
    const TopoDS_Face& face = TopoDS::Face(in.faces(k));
    const uint32_t index = static_cast<uint32_t>(k - 1);
    std::string label = "face " + std::to_string(index);
    const std::string entity = faceEntityLabel(file, face);
    if (!entity.empty()) label += " (" + entity + ")";
    std::string reason;
    try {
      const size_t warningsBefore = in.warnings.size();
      TrimmedFace converted;
      try {
        converted = convertFace(face, index, label, file.path, in);
      } catch (...) {
        in.warnings.resize(warningsBefore);  // a failed face's warnings go with its failure
        throw;
      }
      converted.faceIndex = index;
      converted.label = label;
      in.model.faces.push_back(std::move(converted));
      continue;
    } catch (const CadFaceError& e) {
      reason = e.what();
    } catch (const Standard_Failure& e) {
      reason = std::string("Open CASCADE: ") + e.DynamicType()->Name() + ": " + e.GetMessageString();
    } catch (const std::exception& e) {
      reason = e.what();
    }
    in.failures.push_back({index, label, reason, file.path + ": " + label + ": " + reason});
  }
  return in;
}

}  // namespace tessera
