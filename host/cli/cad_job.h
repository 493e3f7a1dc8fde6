// `tessera tessellate`, `stats`, `render` and `info` on a CAD model (issue 17): a .step/.stp,
// .iges/.igs or .brep file read through Open CASCADE (host/cad/), its faces meshed as trimmed
// faces (host/trim/) at one δ for the whole model, watertight across faces.
//
// A link-time seam: the CLI's shared objects call these three entry points, and each of the
// two executables links one definition of them.
// - tessera-cad: cad_job.cpp, with tessera_cad and Open CASCADE; it runs the model itself.
// - tessera: cad_handoff.cpp, which links no Open CASCADE (so that a run on a patch file does
//   not load its ~30 libraries); each entry point replaces the process, before it reads or
//   writes anything, with the tessera-cad beside the running executable, on the same command
//   line and environment. Without that file: an InputError (exit 2) naming its path.
#pragma once
#include <string>
#include <vector>

#include "render/offscreen.h"
#include "quadtree/tolerance.h"

namespace tessera::cli {

// The file name of the executable with the CAD readers, looked for in the directory of the
// running tessera (an install puts both in bin/).
inline constexpr const char* kCadExecutableName = "tessera-cad";

// What `tessellate` and `stats` take for a CAD model, from their shared options.
struct CadCommand {
  std::string input, output, stats;  // output and stats may be empty (not written)
  std::string tolerance;             // --tolerance as given; empty: 0.1% of the diagonal
  std::string method;                // -m as given: only T (or nothing) applies
  std::string backend = "auto", device;
  std::vector<std::string> formats;  // --format
  bool json = false, quiet = false;
  bool skipBadFaces = false;         // write the faces that converted when some did not
  bool camera = false;               // --view / --view-projection given
  bool lowerBound = false;           // --lower-bound given
};

// `tessera tessellate model.step`: reads, meshes and writes (the glb with one primitive per
// face), both outputs or neither. Options that do not apply to a CAD model (-m A..D, a pixel
// tolerance, a camera, --lower-bound, standard input) are a bad command line. A face that does
// not convert is an InputError naming the file and every failed face, unless skipBadFaces.
// Returns the exit code; errors propagate to runReportingErrors.
int tessellateCadModel(const CadCommand& command);

// What `render` takes for a CAD model, its options already checked (cmd_render.cpp).
struct CadRenderCommand {
  std::string input, output;  // output: a .png, or "-" for standard output
  std::string device;
  ToleranceSpec tolerance;    // model units or a share of the diagonal; not pixels
  RenderOptions options;      // --colour patch colours by face
  bool quiet = false;
};

// `tessera render model.step`: the trimmed faces meshed at one δ on the Vulkan device that
// draws, then drawn. Returns the exit code.
int renderCadModel(const CadRenderCommand& command);

// `tessera info model.step`: faces, edges and shared points once converted at the default δ
// (0.1% of the diagonal), with every face that failed and every edge warning.
int describeCadModel(const std::string& input);

}  // namespace tessera::cli
