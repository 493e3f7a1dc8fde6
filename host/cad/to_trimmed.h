// B-rep shape → TrimmedModel (host/trim/trimmed_face.h), the input of the trimmed-face mesher
// (docs/cad.md). Every face's surface becomes rational Bézier pieces (face_surface.h); every
// edge is discretised once to δ (edge_samples.h) and its samples are shared points; each
// face's wires become loops of those points, mapped to uv through the face's own pcurves.
#pragma once
#include <TopTools_IndexedMapOfShape.hxx>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "cad/cad_file.h"
#include "cad/edge_samples.h"
#include "trim/trimmed_face.h"

namespace tessera {

struct CadFaceFailure {
  uint32_t faceIndex = 0;
  std::string label;    // "face 3 (#345 AdvancedFace)"
  std::string reason;
  std::string message;  // "<file>: face 3 (#345 AdvancedFace): <reason>"
};

// An edge whose 3D curve and pcurve on a face lie farther apart than the edge's tolerance claims
// (a file's SameParameter flag can be wrong): the face's boundary points (the edge's shared 3D
// samples) are then off the face's surface by up to `gap`. The face is kept; the gap is told.
struct CadEdgeWarning {
  uint32_t faceIndex = 0;
  uint32_t edgeIndex = 0;
  double gap = 0.0;        // the largest |S(pcurve(t)) − C(t)| over the edge's samples
  double tolerance = 0.0;  // what OCCT's tolerance said
  std::string message;
};

// An indexed map of shapes that moves by exchanging its content: OCCT 7.6's maps have no move,
// so moving a CadImport (assigning a new import to an old one, say) copied its three maps, a
// node and a hash per shape. The moved-from map holds what the target held.
struct MovableShapeMap : TopTools_IndexedMapOfShape {
  MovableShapeMap() = default;
  MovableShapeMap(MovableShapeMap&& other) noexcept { Exchange(other); }
  MovableShapeMap& operator=(MovableShapeMap&& other) noexcept {
    Exchange(other);
    return *this;
  }
};

// The numbers the model's faces and edges go by in messages, TrimmedFace::faceIndex and
// CadEdgeWarning, where the shape converted is not the file's whole shape: an assembly's part
// meshed once for all its instances (instances.h) keeps the numbers its first instance has in
// the whole model. Empty: the maps' own indices.
struct CadNumbering {
  std::vector<uint32_t> faces;  // per face of CadImport::faces
  std::vector<uint32_t> edges;  // per edge of CadImport::edges
};

struct CadImport {
  TrimmedModel model;                  // the faces that converted
  std::vector<CadFaceFailure> failures;  // the faces that did not, never dropped silently
  // Faces of zero area (CadZeroAreaFace: a sliver whose wires run back and forth along one
  // curve): nothing to mesh, so neither converted nor failed; named here, never dropped
  // silently. Their edges are discretised as every edge and used by the faces beside them.
  std::vector<CadFaceFailure> emptyFaces;
  std::vector<CadEdgeWarning> warnings;  // edges off their faces' surfaces beyond tolerance
  // The B-rep's maps (index k ↔ OCCT's index k + 1): faces in TrimmedFace::faceIndex order.
  // TrimmedFace::faceIndex is the map's index k, or numbering.faces[k] where numbered.
  MovableShapeMap faces, edges, vertices;
  CadNumbering numbering;
  uint32_t faceNumber(size_t k) const {
    return numbering.faces.empty() ? uint32_t(k) : numbering.faces[k];
  }
  uint32_t edgeNumber(size_t e) const {
    return numbering.edges.empty() ? uint32_t(e) : numbering.edges[e];
  }
  std::vector<EdgeSamples> edgeSamples;  // per edge of `edges`
  // Per face of model.faces: the (u0, u1, v0, v1) its surface was converted over, the extent
  // of its loops in the pcurves' (u, v) (convertFaceSurface(faceBasisSurface(face), ...)
  // rebuilds the same pieces and the same mapUv).
  std::vector<std::array<double, 4>> uvBounds;
  std::vector<double> pointTolerances;   // per shared point: its vertex's or edge's tolerance
  double delta = 0.0;
  double maxChordDeviation = 0.0;        // measured over every edge
  size_t loopsReversed = 0;              // loops whose uv orientation had to be flipped
};

// δ by default: 0.1% of the shape's bounding-box diagonal (the CLI's rule T default).
double defaultCadTolerance(const TopoDS_Shape& shape);

// The model's bounding-box diagonal, for every caller that takes a δ from it (meshCadFile, the
// CLI's `info`). InputError naming the file where Open CASCADE cannot bound the shape (its
// exception) or the diagonal is not finite (a coordinate at 10³⁰⁰): an infinite δ ended deep in
// the import as an internal error.
double cadModelDiagonal(const CadFile& file);

// The diagonal `measure` gives, with cadModelDiagonal's checks (instances.h measures an
// assembly's from its parts' boxes).
double checkedCadDiagonal(const CadFile& file, const std::function<double()>& measure);

// Converts every face; a face that fails is listed in failures (with the file's path and the
// face's index and entity), a face of zero area in emptyFaces, and the rest go on. Throws
// ArgumentError unless delta > 0. Edges, then faces, are converted on `threads` threads (0: all
// cores, as TrimmedMeshOptions::threads); the import is the same, bit for bit, whatever the count.
// `numbering`: the faces' and edges' numbers where the shape is part of a larger model (one per
// face and edge of the shape's maps, in TopExp::MapShapes order; empty: their indices).
CadImport toTrimmedModel(const CadFile& file, double delta, unsigned threads = 0,
                         CadNumbering numbering = {});

// "face 3 (#345 AdvancedFace)": how a message names a face, by its number and its entity
// (faceEntityLabel; empty: none).
std::string cadFaceLabel(uint32_t faceNumber, const std::string& entity);

// The warning of an edge whose 3D curve and pcurve on the face lie `gap` apart.
CadEdgeWarning cadEdgeWarning(const std::string& path, uint32_t faceNumber,
                              const std::string& faceLabel, uint32_t edgeNumber, double gap,
                              double tolerance);

}  // namespace tessera
