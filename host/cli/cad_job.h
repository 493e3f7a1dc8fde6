// `tessera tessellate`, `stats` and `render` on a CAD model (issue 17): a .step/.stp,
// .iges/.igs or .brep file read through Open CASCADE (host/cad/), its faces meshed as trimmed
// faces (host/trim/) at one δ for the whole model, watertight across faces.
#pragma once
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "cli/cli_support.h"
#include "quadtree/tolerance.h"
#include "trim/mesher.h"
#include "cad/mesh_cad_file.h"  // OCCT-free: the result type exists in every build

namespace tessera::cli {

// By extension, case-insensitively, whether or not this tessera was built with Open CASCADE.
bool isCadInput(const std::string& path);

struct CadJob {
  std::string input;
  ToleranceSpec tolerance;    // model units or a share of the model's diagonal; not pixels
  bool skipBadFaces = false;  // write the faces that converted when some did not
};

// What a CAD run gives: the mesh, δ, counts, failures and warnings (cad/mesh_cad_file.h).
using CadResult = CadMeshRun;

// Reads and meshes the model on chosen's backend. A face that does not convert is an
// InputError naming the file and every failed face, unless job.skipBadFaces (then the faces
// are listed in CadResult::failures and the others meshed). Built without Open CASCADE: an
// InputError saying so.
CadResult runCadJob(const CadJob& job, ChosenBackend& chosen);

// The statistics report of a CAD run: δ, faces, edges, triangles, deviation per face.
nlohmann::json cadStatsToJson(const CadResult& result);

// What `tessellate` and `stats` take for a CAD model, from their shared options.
struct CadCommand {
  std::string input, output, stats;  // output and stats may be empty (not written)
  std::string tolerance;             // --tolerance as given; empty: 0.1% of the diagonal
  std::string method;                // -m as given: only T (or nothing) applies
  std::string backend = "auto", device;
  std::vector<std::string> formats;  // --format
  bool json = false, quiet = false, skipBadFaces = false;
  bool camera = false;               // --view / --view-projection given
  bool lowerBound = false;           // --lower-bound given
};

// `tessera tessellate model.step`: reads, meshes and writes (the glb with one primitive per
// face), both outputs or neither. Options that do not apply to a CAD model (-m A..D, a pixel
// tolerance, a camera, --lower-bound, standard input) are a bad command line. Returns the exit
// code; errors propagate to runReportingErrors.
int tessellateCadModel(const CadCommand& command);

}  // namespace tessera::cli
