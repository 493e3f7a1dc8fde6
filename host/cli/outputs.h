// The files one run writes: checked before the work (no output is an input or another output,
// every output's directory takes a new file), then written together at the end
// (AtomicFileGroup, host/io/atomic_file.h): all of them or none.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/gltf_writer.h"
#include "io/mesh_write_options.h"
#include "mesh/tessellate.h"

// CLI::App by name only (commands.h says why).
namespace CLI {
class App;
}  // namespace CLI

namespace tessera::cli {

// A file named on the command line and the option (or argument) that named it, for messages.
struct NamedFile {
  std::string option;  // "-o", "--stats", "input", ...
  std::string path;    // empty (not given) and "-" (standard input or output) are skipped
};

// Refuses, as a bad command line (CLI::ValidationError, exit 1), an output that is the same
// file as an input (compared by identity: device and inode, so a hard link, a symbolic link or
// another spelling of the name is caught) or as another output (the same name once links in
// its folders are resolved, or the same inode). Then checks that every output can be written
// (validateWritable: an InputError of kind Io naming it, exit 5), before any work is done.
void checkOutputs(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

// Stages `mesh` in `group`, in `format` or that of `path`'s extension (checkMeshFormat).
// triangleFace (a CAD model's face per triangle) gives a .glb one primitive per face;
// `instances` (an assembly's parts placed more than once) gives it a node per placement
// instead of the copies' triangles. OBJ and PLY take every triangle.
void stageMesh(AtomicFileGroup& group, const std::string& path, const TriangleMesh& mesh,
               const std::string& format = "", const std::vector<uint32_t>* triangleFace = nullptr,
               const MeshWriteOptions& options = {}, const GlbInstances* instances = nullptr);

// The mesh options of every command that writes one: --precision float|double, --metadata.
struct MeshOutputArgs {
  std::string precision = "float";
  bool metadata = false;
};
void addMeshOutputOptions(CLI::App* cmd, MeshOutputArgs& args);

// The writers' options for the mesh output `path` (in `format`, or by its extension). Refuses
// --precision double for glb (CLI::ValidationError, exit 1): glTF has no double attributes.
MeshWriteOptions meshWriteOptions(const MeshOutputArgs& args, const std::string& path,
                                  const std::string& format = "");

// `render`'s RGBA8 picture as a PNG to `output`, or whole to standard output for "-" (a failure
// leaves stdout empty).
void writePicture(const std::string& output, const std::vector<uint8_t>& picture, int width,
                  int height);

}  // namespace tessera::cli
