// tessera::tessellateCadFile (include/tessera/cad.h): the CLI's CAD run (cad/mesh_cad_file.h)
// on a Tessellator's backend, its result in the public types. Built into libtessera_cad.a with
// host/cad/, apart from libtessera.a, so that only CAD users link Open CASCADE.
#include <tessera/cad.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "api/convert.h"
#include "api/tessellator_access.h"
#include "cad/mesh_cad_file.h"

namespace tessera {

namespace {

// The parts and placements of CadMesh from the run's.
void placeParts(const CadMeshRun& run, CadMesh& out) {
  const GlbInstances& instances = run.glbInstances;
  for (const GlbInstances::Part& p : instances.parts) {
    CadPart part;
    part.firstVertex = p.firstVertex;
    part.vertexCount = p.vertexCount;
    part.firstTriangle = p.firstTriangle;
    part.triangleCount = p.triangleCount;
    part.firstFace = p.faceFirst;
    part.faceCount = p.faceCount;
    out.parts.push_back(part);
  }
  for (const GlbInstances::Placement& placed : instances.placements) {
    CadPlacement placement;
    placement.part = uint32_t(placed.part);
    placement.matrix = placed.matrix;
    placement.firstFace = uint32_t(int64_t(out.parts[placed.part].firstFace) + placed.faceOffset);
    out.placements.push_back(placement);
  }
}

}  // namespace

CadMesh tessellateCadFile(Tessellator& tessellator, const std::string& path,
                          const CadOptions& options) {
  ToleranceSpec tolerance;
  if (options.tolerance != 0) {
    if (!std::isfinite(options.tolerance) || !(options.tolerance > 0))
      throw ArgumentError("CadOptions::tolerance must be finite and > 0 (or 0 for the relative "
                          "one), got " + std::to_string(options.tolerance));
    tolerance.value = options.tolerance;
    tolerance.relative = false;
  } else {
    if (!(options.relativeTolerance > 0 && options.relativeTolerance <= 1))
      throw ArgumentError("CadOptions::relativeTolerance must be in (0, 1], got " +
                          std::to_string(options.relativeTolerance));
    tolerance.value = options.relativeTolerance;
    tolerance.relative = true;
  }
  CadMeshRun run;
  TessellatorAccess::run(tessellator, [&](Backend& backend, vk::Context* context) {
    TrimClassifier* trim = context ? TessellatorAccess::trimClassifier(tessellator) : nullptr;
    run = meshCadFile(path, tolerance, options.skipBadFaces, "CadOptions::skipBadFaces", backend,
                      trim, options.threads,
                      options.expandInstances ? CopyPlacement::InMesh : CopyPlacement::Listed);
  });
  CadMesh out;
  placeParts(run, out);
  out.mesh = api::toMesh(std::move(run.mesh.mesh));
  for (uint32_t& face : out.mesh.patchIds) face = run.faceIndexOfPosition.at(face);
  out.triangleFaces = run.mesh.triangleFace;
  out.faces = run.faces;
  out.facesMeshed = run.mesh.faces.size();
  out.tolerance = run.delta;
  for (const TrimmedFaceStats& f : run.mesh.faces) {
    out.maxDeviation = std::max(out.maxDeviation, f.maxGeometricDeviation);
    out.maxParametricDeviation = std::max(out.maxParametricDeviation, f.maxParametricDeviation);
  }
  out.skippedFaces = run.failures;
  out.emptyFaces = run.emptyFaces;
  out.warnings = run.readerWarnings;
  out.warnings.insert(out.warnings.end(), run.warnings.begin(), run.warnings.end());
  out.warnings.insert(out.warnings.end(), run.faceWarnings.begin(), run.faceWarnings.end());
  return out;
}

}  // namespace tessera
