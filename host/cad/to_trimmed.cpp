// Faces and wires → trimmed faces and loops of shared points.
#include "cad/to_trimmed.h"

#include <BRepBndLib.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_ListIteratorOfListOfCurveRepresentation.hxx>
#include <BRep_GCurve.hxx>
#include <BRep_TEdge.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Plane.hxx>
#include <NCollection_IncAllocator.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>

#include "cad/face_surface.h"
#include "cad/detail/kind_of.h"
#include "cad/detail/number_text.h"
#include "cad/detail/plane_parameters.h"
#include "cad/occt_failure.h"
#include "common/phased_parallel.h"
#include "geometry/general_patch.h"
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

// A loop before the surface is converted: the pcurves' (u, v), not yet mapped to the pieces'.
struct RawLoop {
  std::vector<gp_Pnt2d> uv;
  std::vector<uint32_t> pointIds;
};

// What one face's conversion gives, kept apart per face so faces convert on several threads
// and are then added to the CadImport in face order: the same import whatever the threads.
struct FaceOutcome {
  bool converted = false;
  TrimmedFace face;
  std::array<double, 4> bounds{};
  std::vector<CadEdgeWarning> warnings;
  size_t loopsReversed = 0;
  bool empty = false;      // of zero area: nothing to mesh (CadZeroAreaFace)
  CadFaceFailure failure;  // when not converted: why
};

// A wire's edge with its index in CadImport::edges (0-based) and its first and last shared
// point in the direction the wire uses it: looked up once per edge, not at every use.
struct WireEdge {
  TopoDS_Edge edge;
  size_t index = 0;
  uint32_t firstId = 0, lastId = 0;
};

// `index`: the edge's in CadImport::edges (1-based) where the map's walk gave it, else 0.
WireEdge wireEdge(const TopoDS_Edge& edge, const CadImport& in, int index = 0) {
  if (index == 0) index = in.edges.FindIndex(edge);
  if (index == 0) throw CadFaceError("a wire edge is not in the shape's edge map");
  WireEdge out{edge, size_t(index - 1), 0, 0};
  const EdgeSamples& samples = in.edgeSamples[out.index];
  const bool reversed = edge.Orientation() == TopAbs_REVERSED;
  out.firstId = reversed ? samples.lastId : samples.firstId;
  out.lastId = reversed ? samples.firstId : samples.lastId;
  return out;
}

// The wire's edges in an order where each starts at the previous one's end: the wire's own
// order (or its reverse) when it is one, as exchange files store it, and no closed or seam edge
// makes the vertices ambiguous; otherwise
// BRepTools_WireExplorer's, which needs every edge's pcurve on the face (on a plane without
// stored pcurves, a projection of each edge: most of the import's time once). `walked`: the
// wire's children's edge indices as the map's walk found them (FaceWalk), or null.
std::vector<WireEdge> orderedEdges(const TopoDS_Wire& wire, const TopoDS_Face& face,
                                   const CadImport& in, const int* walked) {
  std::vector<WireEdge> edges;
  edges.reserve(size_t(wire.NbChildren()));
  size_t child = 0;
  for (TopoDS_Iterator it(wire); it.More(); it.Next(), ++child)
    if (it.Value().ShapeType() == TopAbs_EDGE)
      edges.push_back(wireEdge(TopoDS::Edge(it.Value()), in, walked ? walked[child] : 0));
  // Chained by vertices is chained in uv, unless an edge has one vertex at both ends (a closed
  // edge: a torus's seams all meet at its one vertex) or is used twice (a seam, once per side):
  // then only the pcurves tell the order.
  std::vector<const TopoDS_TShape*> tshapes;  // sorted: an edge used twice sits beside itself
  tshapes.reserve(edges.size());
  bool vertexOrderHolds = true;
  for (const WireEdge& edge : edges) {
    if (edge.firstId == edge.lastId && edges.size() > 1) vertexOrderHolds = false;
    tshapes.push_back(edge.edge.TShape().get());
  }
  std::sort(tshapes.begin(), tshapes.end());
  if (std::adjacent_find(tshapes.begin(), tshapes.end()) != tshapes.end()) vertexOrderHolds = false;
  const auto chained = [&] {
    for (size_t k = 0; k < edges.size(); ++k)
      if (edges[k].lastId != edges[(k + 1) % edges.size()].firstId) return false;
    return true;
  };
  if (vertexOrderHolds && chained()) return edges;
  std::reverse(edges.begin(), edges.end());
  if (vertexOrderHolds && chained()) return edges;
  edges.clear();
  {
    // OCCT 7.6.3's explorer only reads the shape (its Init no longer calls BRepTools::Update,
    // which writes the edges' uv points), but older and other versions write: one at a time.
    static std::mutex explorerMutex;
    const std::lock_guard<std::mutex> lock(explorerMutex);
    for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next())
      edges.push_back(wireEdge(it.Current(), in));
  }
  size_t edgeCount = 0;
  for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next()) ++edgeCount;
  if (edges.size() != edgeCount)
    throw CadFaceError("the wire explorer ordered " + std::to_string(edges.size()) +
                       " of the wire's " + std::to_string(edgeCount) + " edges");
  return edges;
}

// The pcurve the file stores for `edge` on the face whose surface BRep_Tool::Surface(face, L)
// gives, `onSurface` being L.Predivided(edge.Location()) (SurfaceLocation below), and its range,
// found as BRep_Tool::CurveOnSurface
// finds it (for a seam, the edge's orientation picks which of its two); null when the file
// stores none (BRep_Tool::CurveOnSurface then computes one on a plane). One search of the
// edge's representations where asking whether one is stored and then for it took two. A pointer
// into the edge's representation, which the shape keeps: no handle copied per wire edge (an
// atomic count on geometry that faces converting on other threads share).
const Geom2d_Curve* storedPcurve(const TopoDS_Edge& edge, const Handle(Geom_Surface)& surface,
                                  const TopLoc_Location& onSurface, double& first, double& last) {
  const bool reversed = edge.Orientation() == TopAbs_REVERSED;
  const BRep_TEdge* tedge = static_cast<const BRep_TEdge*>(edge.TShape().get());
  for (BRep_ListIteratorOfListOfCurveRepresentation it(tedge->Curves()); it.More(); it.Next()) {
    const Handle(BRep_CurveRepresentation)& representation = it.Value();
    if (!representation->IsCurveOnSurface(surface, onSurface)) continue;
    const BRep_GCurve* curve = static_cast<const BRep_GCurve*>(representation.get());
    curve->Range(first, last);
    return (curve->IsCurveOnClosedSurface() && reversed ? curve->PCurve2() : curve->PCurve()).get();
  }
  return nullptr;
}

// The face's surface location relative to an edge's (L.Predivided(edge location), as
// BRep_Tool::CurveOnSurface computes it): composed again only when the edge's location changes,
// not for every edge (a wire's edges share theirs), since each composition allocates its list.
class SurfaceLocation {
 public:
  explicit SurfaceLocation(const TopLoc_Location& faceLocation) : face_(faceLocation) {}
  const TopLoc_Location& relativeTo(const TopLoc_Location& edgeLocation) {
    if (!known_ || !(edgeLocation == edge_)) {
      edge_ = edgeLocation;
      onSurface_ = face_.Predivided(edgeLocation);
      known_ = true;
    }
    return onSurface_;
  }

 private:
  TopLoc_Location face_, edge_, onSurface_;
  bool known_ = false;
};

// One wire → one loop: edges in wire order, each edge's samples in the direction the wire uses
// it, mapped through the edge's pcurve on this face (for a seam, the orientation picks which of
// its two pcurves; on a plane without a stored pcurve, the plane's parameters of the edge's 3D
// points, which is what OCCT's computed pcurve, their projection, gives). Consecutive edges
// share their vertex point once. `basis` is the face's surface (faceBasisSurface).
RawLoop wireLoop(const TopoDS_Wire& wire, const TopoDS_Face& face,
                 const Handle(Geom_Surface)& basis, uint32_t faceIndex, const std::string& label,
                 const std::string& path, const CadImport& in, const int* walked,
                 FaceOutcome& outcome) {
  RawLoop loop;
  const Geom_Plane* plane = cad_detail::kindOf<Geom_Plane>(basis.get());
  const cad_detail::PlaneParameters planeParameters(plane ? plane->Pln() : gp_Pln());
  TopLoc_Location faceLocation;  // the face's surface as stored, for storedPcurve
  const Handle(Geom_Surface)& faceSurface = BRep_Tool::Surface(face, faceLocation);
  SurfaceLocation surfaceLocation(faceLocation);
  uint32_t firstId = 0, lastId = 0;
  const std::vector<WireEdge> edges = orderedEdges(wire, face, in, walked);
  size_t points = 0;
  for (const WireEdge& edge : edges) points += in.edgeSamples[edge.index].params.size() - 1;
  loop.uv.reserve(points);
  loop.pointIds.reserve(points);
  for (size_t e = 0; e < edges.size(); ++e) {
    const TopoDS_Edge& edge = edges[e].edge;
    const int index = int(edges[e].index) + 1;
    const EdgeSamples& samples = in.edgeSamples[edges[e].index];
    double pf = 0, pl = 0;
    const Geom2d_Curve* pcurve = storedPcurve(edge, faceSurface, surfaceLocation.relativeTo(edge.Location()), pf, pl);
    const bool projected = !pcurve && plane && !samples.degenerated;
    Handle(Geom2d_Curve) computed;  // BRep_Tool's own pcurve, kept while in use
    if (!pcurve && !projected) {
      computed = BRep_Tool::CurveOnSurface(edge, face, pf, pl);
      if (computed.IsNull())
        throw CadFaceError("edge " + std::to_string(in.edgeNumber(index - 1)) +
                           " has no pcurve on the face");
      pcurve = computed.get();
    }
    const double f = samples.params.front(), l = samples.params.back();
    const bool reversed = edge.Orientation() == TopAbs_REVERSED;
    const size_t n = samples.params.size();
    if (e == 0) firstId = samples.pointId(reversed ? n - 1 : 0);
    else if (samples.pointId(reversed ? n - 1 : 0) != lastId)
      throw CadFaceError("the wire is not connected at edge " +
                         std::to_string(in.edgeNumber(index - 1)));
    double gap = 0.0;
    for (size_t k = 0; k < n; ++k) {
      const size_t s = reversed ? n - 1 - k : k;
      gp_Pnt2d uv;
      if (projected) {
        const glm::dvec3& c = samples.curvePoints[s];
        uv = planeParameters(gp_Pnt(c.x, c.y, c.z));  // ElSLib::Parameters(plane, point)
      } else {
        // Same range is the rule for pcurves (BRep_Tool::SameRange); map linearly if not.
        const double t = l > f ? pf + (samples.params[s] - f) * (pl - pf) / (l - f) : pf;
        uv = pcurve->Value(t);
      }
      const gp_Pnt onSurface = basis->Value(uv.X(), uv.Y());
      gap = std::max(gap, glm::length(glm::dvec3(onSurface.X(), onSurface.Y(), onSurface.Z()) -
                                      in.model.sharedPoints[samples.pointId(s)]));
      if (k + 1 == n) break;  // the next edge's first point
      loop.uv.push_back(uv);
      loop.pointIds.push_back(samples.pointId(s));
    }
    const double tolerance = BRep_Tool::Tolerance(edge);
    if (!samples.degenerated && gap > tolerance + 1e-3 * in.delta)
      outcome.warnings.push_back(
          cadEdgeWarning(path, faceIndex, label, in.edgeNumber(index - 1), gap, tolerance));
    lastId = samples.pointId(reversed ? 0 : n - 1);
  }
  if (edges.empty() || lastId != firstId) throw CadFaceError("a wire is not closed");
  if (loop.uv.size() < 2) throw CadFaceError("a wire has fewer than two points");
  return loop;
}

// Reads the shape and `in` (its maps, edge samples and shared points) only: faces convert on
// several threads at once.
// `walked`: the face's wires' edge indices in their order (from mapWalkedFaces), or null.
TrimmedFace convertFace(const TopoDS_Face& sourceFace, uint32_t faceIndex, const std::string& label,
                        const std::string& path, const CadImport& in, const int* walked,
                        FaceOutcome& outcome) {
  // Loops in the surface's own orientation: outer counter-clockwise, holes clockwise; the
  // face's orientation goes to `reversed` (trimmed_face.h).
  const TopoDS_Face face = TopoDS::Face(sourceFace.Oriented(TopAbs_FORWARD));
  TrimmedFace out;
  out.reversed = sourceFace.Orientation() == TopAbs_REVERSED;
  // The loops first, in the pcurves' (u, v): their extent bounds the surface's conversion
  // (BRepTools::UVBounds would compute every planar pcurve again), then mapped to the pieces'.
  const Handle(Geom_Surface) basis = faceBasisSurface(face);
  std::vector<RawLoop> raw;
  // The face's wires are its children: the order TopExp_Explorer(face, TopAbs_WIRE) gives,
  // without the explorer's stack allocated per face.
  for (TopoDS_Iterator w(face); w.More(); w.Next()) {
    if (w.Value().ShapeType() == TopAbs_WIRE)
      raw.push_back(wireLoop(TopoDS::Wire(w.Value()), face, basis, faceIndex, label, path, in,
                             walked, outcome));
    if (walked) walked += w.Value().NbChildren();
  }
  if (raw.empty()) throw CadFaceError("the face has no wire");
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (const RawLoop& loop : raw)
    for (const gp_Pnt2d& uv : loop.uv)
      u0 = std::min(u0, uv.X()), u1 = std::max(u1, uv.X()), v0 = std::min(v0, uv.Y()), v1 = std::max(v1, uv.Y());
  CadSurface surface = convertFaceSurface(basis, u0, u1, v0, v1);
  outcome.bounds = {u0, u1, v0, v1};
  std::vector<gp_Pnt2d> all;  // every loop's points, mapped together (mapUvs shares solves)
  for (const RawLoop& loop : raw) all.insert(all.end(), loop.uv.begin(), loop.uv.end());
  const std::vector<glm::dvec2> mappedUvs = surface.mapUvs(all);
  size_t next = 0;
  for (const RawLoop& loop : raw) {
    TrimLoop mapped;
    mapped.pointIds = loop.pointIds;
    mapped.uv.assign(mappedUvs.begin() + ptrdiff_t(next), mappedUvs.begin() + ptrdiff_t(next + loop.uv.size()));
    next += loop.uv.size();
    out.loops.push_back(std::move(mapped));
  }
  // The pieces as the tessellator takes them (a control point beyond 10³⁸ or not finite, a
  // weight out of range): this face's failure, not NaN in the trees.
  for (size_t k = 0; k < surface.pieces.size(); ++k) {
    try {
      validateTessellationPatch(surface.pieces[k].patch,
                                "its surface's piece " + std::to_string(k));
    } catch (const std::invalid_argument& e) {
      throw CadFaceError(e.what());
    }
  }
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
      ++outcome.loopsReversed;
    }
  }
  return out;
}

// One face, its failure caught: the message names the file, the face and its entity.
FaceOutcome faceOutcome(const CadFile& file, const CadImport& in, int k, const int* walked) {
  const TopoDS_Face& face = TopoDS::Face(in.faces(k));
  const uint32_t index = in.faceNumber(size_t(k - 1));
  std::string label = cadFaceLabel(index, faceEntityLabel(file, face));
  FaceOutcome outcome;
  std::string reason;
  bool empty = false;
  try {
    outcome.face = convertFace(face, index, label, file.path, in, walked, outcome);
    outcome.face.faceIndex = index;
    outcome.face.label = std::move(label);
    outcome.converted = true;
    return outcome;
  } catch (const CadZeroAreaFace& e) {
    reason = e.what();
    empty = true;
  } catch (const CadFaceError& e) {
    reason = e.what();
  } catch (const Standard_Failure& e) {
    reason = std::string("Open CASCADE: ") + e.DynamicType()->Name() + ": " + e.GetMessageString();
  } catch (const std::exception& e) {
    reason = e.what();
  }
  outcome = FaceOutcome();  // a failed (or empty) face's warnings go with it
  outcome.empty = empty;
  outcome.failure = {index, label, reason, file.path + ": " + label + ": " + reason};
  return outcome;
}

// The shape's faces, edges and vertices in one depth-first walk: each map gets its shapes in
// the order TopExp::MapShapes gives them (its explorer walks the same tree, depth first, with
// the same composed orientations and locations, and stops at the type it maps), without
// walking the shape three times (a tenth of the import's time, all before the threads start).
// A face or edge met again (an edge is met once per face that uses it) is not walked again: the
// maps compare shapes without their orientation (TopTools_ShapeMapHasher), a shape met again
// has the same TShape and location, so its sub-shapes are those already mapped, and Add keeps
// the first-mapped one. The maps come out as the full walk's, with half the edges' walks and
// the vertices' location compositions.
void mapSubShapes(const TopoDS_Shape& shape, CadImport& in) {
  const auto mappedBefore = [&](TopTools_IndexedMapOfShape& map) {
    const int extent = map.Extent();
    return map.Add(shape) <= extent;
  };
  switch (shape.ShapeType()) {
    case TopAbs_FACE:
      if (mappedBefore(in.faces)) return;
      break;
    case TopAbs_EDGE:
      if (mappedBefore(in.edges)) return;
      break;
    case TopAbs_VERTEX: in.vertices.Add(shape); return;
    default: break;
  }
  for (TopoDS_Iterator it(shape); it.More(); it.Next()) mapSubShapes(it.Value(), in);
}

// The faces under the shape's compounds, solids and shells, in the order mapSubShapes maps them,
// without walking into them (walkFace does, on all threads). False where something other than
// a face hangs there (a free wire, edge or vertex): the caller then maps it all with mapSubShapes.
bool mapFaces(const TopoDS_Shape& shape, CadImport& in) {
  switch (shape.ShapeType()) {
    case TopAbs_FACE: in.faces.Add(shape); return true;
    case TopAbs_WIRE:
    case TopAbs_EDGE:
    case TopAbs_VERTEX: return false;
    default: break;
  }
  for (TopoDS_Iterator it(shape); it.More(); it.Next())
    if (!mapFaces(it.Value(), in)) return false;
  return true;
}

// One face's part of mapSubShapes's walk, gathered on its own thread: the face's edges in the
// walk's order (wires in order, each wire's edges), each followed by its children (vertices),
// located and oriented as the walk composes them. The walk was a tenth of the import's thread
// time and all of it serial, most of it in TopoDS_Iterator (cache misses on the shape's lists);
// mapWalkedFaces then only adds the shapes to the maps. `plain` is false where the face holds
// something else (a wire or vertex directly under the face, say): mapSubShapes then maps all.
struct FaceWalk {
  std::vector<TopoDS_Shape> shapes;  // edge, its vertices, next edge, ...
  std::vector<uint8_t> vertexCounts;  // per edge
  bool plain = true;
  // Where the face's edges' indices in CadImport::edges start in the flat list of every face's
  // (mapWalkedFaces): the face's conversion then needs no look-up of its wires' edges.
  size_t firstUse = 0;
};

// An edge's first and last vertex's shared points as TopExp::Vertices finds them on the edge
// taken FORWARD (discretiseEdge), read off the walk; `known` false where the walk cannot tell
// (an edge neither FORWARD nor REVERSED in its wire, or without both vertices).
struct EdgeEnds {
  uint32_t firstId = 0, lastId = 0;
  bool known = false;
};

// `shapes`: an edge as the walk met it (its orientation composed), then its `count` vertices,
// whose indices in CadImport::vertices are `indices`. TopExp::Vertices reads the vertices' own
// orientations (the last FORWARD one first, the last REVERSED one last); the walk's are
// composed with the edge's.
EdgeEnds edgeEnds(const TopoDS_Shape* shapes, const int* indices, size_t count) {
  EdgeEnds ends;
  const TopAbs_Orientation edge = shapes[0].Orientation();
  if (edge != TopAbs_FORWARD && edge != TopAbs_REVERSED) return ends;
  bool first = false, last = false;
  for (size_t v = 0; v < count; ++v) {
    TopAbs_Orientation own = shapes[1 + v].Orientation();
    if (edge == TopAbs_REVERSED) own = TopAbs::Reverse(own);  // INTERNAL, EXTERNAL kept
    if (own == TopAbs_FORWARD)
      ends.firstId = uint32_t(indices[v] - 1), first = true;
    else if (own == TopAbs_REVERSED)
      ends.lastId = uint32_t(indices[v] - 1), last = true;
  }
  ends.known = first && last;
  return ends;
}

FaceWalk walkFace(const TopoDS_Shape& face) {
  FaceWalk walk;
  // Sized first (an edge has two vertices, mostly): grown, the vectors copied every shape.
  size_t edges = 0;
  for (TopoDS_Iterator w(face); w.More(); w.Next()) edges += size_t(w.Value().NbChildren());
  walk.shapes.reserve(3 * edges);
  walk.vertexCounts.reserve(edges);
  for (TopoDS_Iterator w(face); w.More() && walk.plain; w.Next()) {
    if (w.Value().ShapeType() != TopAbs_WIRE) walk.plain = false;
    for (TopoDS_Iterator e(w.Value()); e.More() && walk.plain; e.Next()) {
      if (e.Value().ShapeType() != TopAbs_EDGE) walk.plain = false;
      walk.shapes.push_back(e.Value());
      uint8_t count = 0;
      for (TopoDS_Iterator v(e.Value()); v.More() && walk.plain; v.Next()) {
        if (v.Value().ShapeType() != TopAbs_VERTEX || count == UINT8_MAX) walk.plain = false;
        walk.shapes.push_back(v.Value());
        ++count;
      }
      walk.vertexCounts.push_back(count);
    }
  }
  return walk;
}

// The faces' edges and vertices into the maps, face by face in face order: as mapSubShapes adds
// them (an edge's vertices only where the edge is met first); each use's edge index into
// `uses` (face by face, one list: not a heap block a face), each edge's ends into `ends` (edge
// order). False where a face was not plain.
bool mapWalkedFaces(std::vector<FaceWalk>& walks, CadImport& in, std::vector<int>& uses,
                    std::vector<EdgeEnds>& ends) {
  size_t useCount = 0;
  for (const FaceWalk& walk : walks) {
    if (!walk.plain) return false;
    useCount += walk.vertexCounts.size();
  }
  // Sized once for what comes (an edge is used by two faces, a closed shell has fewer vertices
  // than edges): grown by doubling, each growth hashed every shape again. The maps' order is
  // their indices', whatever the buckets.
  in.edges.ReSize(int(useCount / 2));
  in.vertices.ReSize(int(useCount / 2));
  uses.reserve(useCount);
  ends.reserve(useCount / 2);
  int vertexIndices[UINT8_MAX];
  for (FaceWalk& walk : walks) {
    size_t next = 0;
    walk.firstUse = uses.size();
    for (const uint8_t count : walk.vertexCounts) {
      const int extent = in.edges.Extent();
      const int index = in.edges.Add(walk.shapes[next]);
      uses.push_back(index);
      if (index > extent) {  // met first: its vertices added, as mapSubShapes adds them
        for (size_t v = 0; v < count; ++v)
          vertexIndices[v] = in.vertices.Add(walk.shapes[next + 1 + v]);
        ends.push_back(edgeEnds(&walk.shapes[next], vertexIndices, count));
      }
      next += 1 + size_t(count);
    }
  }
  return true;
}

// Maps the shape's faces, edges and vertices as mapSubShapes does, from the faces' walks where
// the shape is faces under compounds, solids and shells (`walked`: mapFaces said so, and the
// faces were walked). True where the walks gave the maps (then `uses` holds the faces' edge
// indices and `ends` every edge's); false where mapSubShapes did.
bool mapShape(const TopoDS_Shape& shape, bool walked, std::vector<FaceWalk>& walks, CadImport& in,
              std::vector<int>& uses, std::vector<EdgeEnds>& ends) {
  if (walked && mapWalkedFaces(walks, in, uses, ends)) return true;
  uses.clear();
  ends.clear();
  for (TopTools_IndexedMapOfShape* map : {&in.faces, &in.edges, &in.vertices}) map->Clear(Standard_False);
  mapSubShapes(shape, in);
  return false;
}

// The vertices' points, the shared points' first ones (vertex k of the map is point k − 1).
SharedPoints vertexPoints(const CadImport& in) {
  SharedPoints points;
  points.positions.reserve(size_t(in.vertices.Extent()));
  points.tolerances.reserve(size_t(in.vertices.Extent()));
  for (int k = 1; k <= in.vertices.Extent(); ++k) {
    const TopoDS_Vertex& v = TopoDS::Vertex(in.vertices(k));
    const gp_Pnt p = BRep_Tool::Pnt(v);
    points.positions.push_back({p.X(), p.Y(), p.Z()});
    points.tolerances.push_back(BRep_Tool::Tolerance(v));
  }
  return points;
}

// The faces' outcomes into the import, in face order.
void addOutcomes(std::vector<FaceOutcome>& outcomes, CadImport& in) {
  in.model.faces.reserve(outcomes.size());
  in.uvBounds.reserve(outcomes.size());
  for (FaceOutcome& outcome : outcomes) {
    if (!outcome.converted) {
      (outcome.empty ? in.emptyFaces : in.failures).push_back(std::move(outcome.failure));
      continue;
    }
    in.model.faces.push_back(std::move(outcome.face));
    in.uvBounds.push_back(outcome.bounds);
    in.warnings.insert(in.warnings.end(), outcome.warnings.begin(), outcome.warnings.end());
    in.loopsReversed += outcome.loopsReversed;
  }
}

}  // namespace

std::string cadFaceLabel(uint32_t faceNumber, const std::string& entity) {
  // Built in one string, which the face then takes (the concatenations and the copy were
  // four allocations a face).
  std::string label;
  label.reserve(entity.size() + 24);
  label += "face ";
  label += std::to_string(faceNumber);
  if (!entity.empty()) label += " (", label += entity, label += ')';
  return label;
}

CadEdgeWarning cadEdgeWarning(const std::string& path, uint32_t faceNumber,
                              const std::string& faceLabel, uint32_t edgeNumber, double gap,
                              double tolerance) {
  return {faceNumber, edgeNumber, gap, tolerance,
          path + ": " + faceLabel + ": edge " + std::to_string(edgeNumber) +
              ": its 3D curve and pcurve are " + cad_detail::numberText(gap) +
              " apart, beyond its tolerance " + cad_detail::numberText(tolerance)};
}

double defaultCadTolerance(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  if (box.IsVoid()) return 1e-3;
  return 1e-3 * std::sqrt(box.SquareExtent());
}

double cadModelDiagonal(const CadFile& file) {
  return checkedCadDiagonal(file, [&] {
    return defaultCadTolerance(file.shape) / 1e-3;  // 0.1% of the diagonal
  });
}

double checkedCadDiagonal(const CadFile& file, const std::function<double()>& measure) {
  double diagonal = 0;
  try {
    diagonal = measure();
  } catch (const Standard_Failure& failure) {
    throwAsInputError(failure, file.path, "measuring its bounding box");
  }
  if (!std::isfinite(diagonal))
    throw InputError(InputErrorKind::Range, file.path, 0,
                     "its bounding box is not finite (a coordinate near 1e308 or beyond): the "
                     "model has no size to mesh it at");
  return diagonal;
}

namespace {

// A mesh position is fp32 (kMaxPatchCoordinate): a shared point that is not finite or beyond
// 10³⁸ cannot be one. A damaged .brep put a vertex at 10³⁰⁰; the mesher's distance measure then
// met NaN and the run ended as an internal error (exit 70).
void requireMeshablePoint(const glm::dvec3& p, const std::string& path, const std::string& what) {
  if (!isMeshablePoint(p))
    throw InputError(InputErrorKind::Range, path, 0,
                     what + ": a point (" + cad_detail::numberText(p.x) + ", " +
                         cad_detail::numberText(p.y) + ", " + cad_detail::numberText(p.z) +
                         ") is not finite or exceeds 1e38 (the mesh is fp32)");
}

// A numbering is the caller's (instances.cpp): one number per face and edge of the maps.
void requireNumberingFits(const CadImport& in) {
  const CadNumbering& n = in.numbering;
  if ((n.faces.empty() && n.edges.empty()) ||
      (n.faces.size() == size_t(in.faces.Extent()) && n.edges.size() == size_t(in.edges.Extent())))
    return;
  throw std::logic_error("toTrimmedModel: a numbering of " + std::to_string(n.faces.size()) +
                         " faces and " + std::to_string(n.edges.size()) + " edges for a shape of " +
                         std::to_string(in.faces.Extent()) + " and " +
                         std::to_string(in.edges.Extent()));
}

// toTrimmedModel's work, its arguments checked.
CadImport importShape(const CadFile& file, double delta, unsigned threads, CadNumbering numbering) {
  CadImport in;
  in.delta = delta;
  in.numbering = std::move(numbering);
  // The maps' nodes from one block allocator: a node per shape, freed together with the maps
  // (malloc was a fifth of the walk; the maps take their shapes on one thread, mapShape).
  const Handle(NCollection_BaseAllocator) nodes = new NCollection_IncAllocator;
  for (TopTools_IndexedMapOfShape* map : {&in.faces, &in.edges, &in.vertices}) map->Clear(nodes);
  const bool walkable = mapFaces(file.shape, in);

  // Three loops on all threads, each followed by a step in order on one thread, in one fan-out
  // (runPhases: the worker is woken once a model, not three times; a phase's item throwing
  // ends the import as a loop in order would). Each item reads the shape and what the steps
  // before wrote, and writes its own slot: the import is the same whatever the threads.
  std::vector<FaceWalk> walks;
  std::vector<int> uses;       // the faces' edges' indices, where the walks gave the maps
  std::vector<EdgeEnds> ends;  // per edge, likewise
  bool fromWalks = false;
  SharedPoints points;
  EdgeSampleBudget edgeBudget(delta);  // all edges' samples against the memory budget
  std::vector<FaceOutcome> outcomes;
  const std::vector<ParallelPhase> phases = {
      // The faces' part of the shape's walk; then the maps, in the walk's order.
      {[&] {
         walks.resize(walkable ? size_t(in.faces.Extent()) : 0);
         return walks.size();
       },
       4, [&](size_t f) { walks[f] = walkFace(in.faces(int(f) + 1)); },
       [&] {
         fromWalks = mapShape(file.shape, walkable, walks, in, uses, ends);
         requireNumberingFits(in);
         points = vertexPoints(in);
         for (size_t k = 0; k < points.positions.size(); ++k)
           requireMeshablePoint(points.positions[k], file.path, "vertex " + std::to_string(k));
         in.edgeSamples.resize(size_t(in.edges.Extent()));
       }},
      // Each edge reads its own edge; then their interior points numbered in edge order.
      {[&] { return in.edgeSamples.size(); }, 4,
       [&](size_t e) {
         const TopoDS_Shape& edge = in.edges(int(e) + 1);
         in.edgeSamples[e] =
             fromWalks && ends[e].known
                 ? discretiseEdge(edge, delta, ends[e].firstId, ends[e].lastId, &edgeBudget)
                 : discretiseEdge(edge, delta, in.vertices, &edgeBudget);
       },
       [&] {
         for (size_t e = 0; e < in.edgeSamples.size(); ++e) {
           EdgeSamples& samples = in.edgeSamples[e];
           for (const glm::dvec3& p : samples.curvePoints)
             requireMeshablePoint(p, file.path, "edge " + std::to_string(in.edgeNumber(e)));
           shareInteriorSamples(samples, points);
           in.maxChordDeviation = std::max(in.maxChordDeviation, samples.maxChordDeviation);
         }
         in.model.sharedPoints = std::move(points.positions);
         in.pointTolerances = std::move(points.tolerances);
         outcomes.resize(size_t(in.faces.Extent()));
       }},
      // Each face reads the shape and the edges' samples, writes its own outcome (OCCT's calls
      // here only read: docs/cad.md, "Threads"); then added in face order.
      {[&] { return outcomes.size(); }, 4,
       [&](size_t f) {
         outcomes[f] = faceOutcome(file, in, int(f) + 1,
                                   fromWalks ? uses.data() + walks[f].firstUse : nullptr);
       },
       [&] { addOutcomes(outcomes, in); }},
  };
  runPhases(phases, threads);
  return in;
}

}  // namespace

CadImport toTrimmedModel(const CadFile& file, double delta, unsigned threads,
                         CadNumbering numbering) {
  if (!(delta > 0.0) || !std::isfinite(delta))
    throw ArgumentError("the CAD edge tolerance must be a positive distance, not " +
                        std::to_string(delta));
  // A face's Open CASCADE exception is its failure (faceOutcome); one outside a face (an edge's
  // curve, the shape's walk) is the file's.
  try {
    return importShape(file, delta, threads, std::move(numbering));
  } catch (const Standard_Failure& failure) {
    throwAsInputError(failure, file.path, "converting its faces and edges");
  }
}

}  // namespace tessera
