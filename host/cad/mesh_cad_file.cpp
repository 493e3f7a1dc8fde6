#include "cad/mesh_cad_file.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "cad/cad_file.h"
#include "cad/detail/number_text.h"
#include "cad/instances.h"
#include "cad/to_trimmed.h"
#include "common/stopwatch.h"
#include "tessera/errors.h"

namespace tessera {

namespace {

// Messages of the converted faces and of the copies, by face number (the order they had when
// every instance was converted).
template <typename Message>
std::vector<Message> inFaceOrder(std::vector<Message> own, std::vector<Message> copies) {
  if (copies.empty()) return own;
  own.insert(own.end(), std::make_move_iterator(copies.begin()),
             std::make_move_iterator(copies.end()));
  std::stable_sort(own.begin(), own.end(),
                   [](const Message& a, const Message& b) { return a.faceIndex < b.faceIndex; });
  return own;
}

void requireModelTolerance(const ToleranceSpec& tolerance) {
  if (tolerance.pixels)
    throw std::invalid_argument("a CAD model takes a tolerance in model units or a share of its "
                                "size, not pixels");
}

}  // namespace

CadMeshRun meshCadFile(const std::string& path, const ToleranceSpec& tolerance, bool skipBadFaces,
                       const std::string& skipHint, Backend& backend, TrimClassifier* trim,
                       unsigned threads, CopyPlacement copies) {
  requireModelTolerance(tolerance);
  const Stopwatch clock;
  const CadFile file = readCadFile(path);
  const double readMs = clock.elapsedMs();
  TrimmedMeshOptions options;
  options.threads = threads;
  CadMeshRun result =
      meshCadModel(file, tolerance, skipBadFaces, skipHint, backend, trim, options, copies);
  result.readMs = readMs;
  return result;
}

CadMeshRun meshCadModel(const CadFile& file, const ToleranceSpec& tolerance, bool skipBadFaces,
                        const std::string& skipHint, Backend& backend, TrimClassifier* trim,
                        TrimmedMeshOptions options, CopyPlacement copies) {
  requireModelTolerance(tolerance);
  const std::string& path = file.path;
  CadMeshRun result;
  Stopwatch clock;
  // An assembly's repeated parts once (instances.h).
  const InstancePlan plan = planCadInstances(file);
  result.importMs = clock.elapsedMs();
  result.diagonal = plannedModelDiagonal(plan, file);
  result.delta = tolerance.relative ? tolerance.value * result.diagonal : tolerance.value;
  // (A hair of slack: "0.0000001%" parses to a hair under 10⁻⁹.)
  if (result.delta < (1 - 1e-9) * kSmallestRelativeCadTolerance * result.diagonal)
    throw std::invalid_argument(
        path + ": the tolerance " + cad_detail::numberText(result.delta) +
        " is below the smallest a CAD model takes, 1e-9 of its diagonal (" +
        cad_detail::numberText(kSmallestRelativeCadTolerance * result.diagonal) + " for " +
        cad_detail::numberText(result.diagonal) + ")");
  options.tolerance = result.delta;
  clock.restart();
  // The import takes the mesher's thread count (0: all cores).
  CadImport import = plan.meshShape.IsNull()
                         ? toTrimmedModel(file, result.delta, options.threads)
                         : toTrimmedModel(CadFile{file.path, plan.meshShape, file.faceEntities},
                                          result.delta, options.threads, plan.numbering);
  result.importMs += clock.elapsedMs();
  result.faces = plan.meshShape.IsNull() ? size_t(import.faces.Extent()) : plan.modelFaces;
  result.edges = plan.meshShape.IsNull() ? size_t(import.edges.Extent()) : plan.modelEdges;
  result.sharedPoints = import.model.sharedPoints.size();
  result.maxChordDeviation = import.maxChordDeviation;
  result.readerWarnings = file.readerWarnings;
  const std::vector<CadFaceFailure> failures =
      inFaceOrder(import.failures, copiedFaceFailures(plan, file, import, import.failures));
  const std::vector<CadFaceFailure> emptyFaces =
      inFaceOrder(import.emptyFaces, copiedFaceFailures(plan, file, import, import.emptyFaces));
  for (const CadFaceFailure& f : failures) result.failures.push_back(f.message);
  for (const CadFaceFailure& f : emptyFaces) result.emptyFaces.push_back(f.message);
  for (const CadEdgeWarning& w :
       inFaceOrder(import.warnings, copiedEdgeWarnings(plan, file, import)))
    result.warnings.push_back(w.message);
  if (!failures.empty() && !skipBadFaces) {
    std::string reason = std::to_string(failures.size()) + " of " + std::to_string(result.faces) +
                         " faces could not be converted (" + skipHint + " meshes the others):";
    for (const CadFaceFailure& f : failures) reason += "\n  " + f.label + ": " + f.reason;
    throw InputError(InputErrorKind::Syntax, path, 0, reason);
  }
  clock.restart();
  result.mesh = meshTrimmedModel(import.model, options, backend, trim);
  for (const TrimmedFace& face : import.model.faces)
    result.faceIndexOfPosition.push_back(face.faceIndex);
  const uint64_t placedVertices = result.mesh.mesh.vertexCount();
  const uint64_t placedTriangles = result.mesh.mesh.triangleCount();
  CopiesSize copied = addInstanceCopies(plan, result.mesh, result.faceIndexOfPosition, copies);
  if (copies == CopyPlacement::Listed) {
    result.listedVertices = copied.vertices;
    result.listedTriangles = copied.triangles;
  }
  result.glbInstances =
      glbInstancesOf(plan, placedVertices, placedTriangles, std::move(copied.parts));
  result.meshMs = clock.elapsedMs();
  // The faces' numbers in the model (TrimmedFace::faceIndex, a copy's own), not their place in
  // the list of faces meshed: what the glb's primitives and the stats name.
  for (uint32_t& face : result.mesh.triangleFace) face = result.faceIndexOfPosition[face];
  // A face the gap refinement left over δ is said, never passed off as within δ.
  result.faceWarnings = unfinishedRefinementWarnings(result.mesh, result.delta);
  return result;
}

}  // namespace tessera
