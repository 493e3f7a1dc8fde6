#include "cad/mesh_cad_file.h"

#include <stdexcept>

#include "cad/cad_file.h"
#include "cad/detail/number_text.h"
#include "cad/to_trimmed.h"
#include "common/stopwatch.h"
#include "tessera/errors.h"

namespace tessera {

CadMeshRun meshCadFile(const std::string& path, const ToleranceSpec& tolerance, bool skipBadFaces,
                       const std::string& skipHint, Backend& backend, TrimClassifier* trim,
                       unsigned threads) {
  if (tolerance.pixels)
    throw std::invalid_argument("a CAD model takes a tolerance in model units or a share of its "
                                "size, not pixels");
  CadMeshRun result;
  Stopwatch clock;
  const CadFile file = readCadFile(path);
  result.readMs = clock.elapsedMs();
  result.diagonal = cadModelDiagonal(file);
  result.delta = tolerance.relative ? tolerance.value * result.diagonal : tolerance.value;
  // (A hair of slack: "0.0000001%" parses to a hair under 10⁻⁹.)
  if (result.delta < (1 - 1e-9) * kSmallestRelativeCadTolerance * result.diagonal)
    throw std::invalid_argument(
        path + ": the tolerance " + cad_detail::numberText(result.delta) +
        " is below the smallest a CAD model takes, 1e-9 of its diagonal (" +
        cad_detail::numberText(kSmallestRelativeCadTolerance * result.diagonal) + " for " +
        cad_detail::numberText(result.diagonal) + ")");
  TrimmedMeshOptions options;
  options.tolerance = result.delta;
  options.threads = threads;
  clock.restart();
  // The import takes the mesher's thread count (0: all cores).
  CadImport import = toTrimmedModel(file, result.delta, options.threads);
  result.importMs = clock.elapsedMs();
  result.faces = size_t(import.faces.Extent());
  result.edges = size_t(import.edges.Extent());
  result.sharedPoints = import.model.sharedPoints.size();
  result.maxChordDeviation = import.maxChordDeviation;
  for (const CadFaceFailure& f : import.failures) result.failures.push_back(f.message);
  for (const CadFaceFailure& f : import.emptyFaces) result.emptyFaces.push_back(f.message);
  for (const CadEdgeWarning& w : import.warnings) result.warnings.push_back(w.message);
  if (!import.failures.empty() && !skipBadFaces) {
    std::string reason = std::to_string(import.failures.size()) + " of " +
                         std::to_string(result.faces) + " faces could not be converted (" +
                         skipHint + " meshes the others):";
    for (const CadFaceFailure& f : import.failures) reason += "\n  " + f.label + ": " + f.reason;
    throw InputError(InputErrorKind::Syntax, path, 0, reason);
  }
  clock.restart();
  result.mesh = meshTrimmedModel(import.model, options, backend, trim);
  result.meshMs = clock.elapsedMs();
  // The faces' indices in the model (TrimmedFace::faceIndex), not their place in the list of
  // faces that converted: what the glb's primitives and the stats name.
  for (uint32_t& face : result.mesh.triangleFace) face = import.model.faces[face].faceIndex;
  for (const TrimmedFace& face : import.model.faces)
    result.faceIndexOfPosition.push_back(face.faceIndex);
  // A face the gap refinement left over δ is said, never passed off as within δ.
  result.faceWarnings = unfinishedRefinementWarnings(result.mesh, result.delta);
  return result;
}

}  // namespace tessera
