#include "cli/outputs.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <sstream>
#include <system_error>

#include "cli/stdio.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/png_writer.h"
#include "io/ply_writer.h"

namespace tessera::cli {
namespace {

namespace fs = std::filesystem;

bool given(const NamedFile& f) { return !f.path.empty() && f.path != kStdioPath; }

// Both exist and are one file (fs::equivalent follows links and compares device and inode).
bool sameExistingFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

// The same file, or the same name once the links in its folders are resolved (outputs may
// not exist yet).
bool sameOutput(const std::string& a, const std::string& b) {
  if (sameExistingFile(a, b)) return true;
  std::error_code ec1, ec2;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a), ec1);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b), ec2);
  return !ec1 && !ec2 && ca == cb;
}

}  // namespace

void checkOutputs(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedFile& out = outputs[i];
    if (!given(out)) continue;
    for (const NamedFile& in : inputs)
      if (given(in) && sameExistingFile(in.path, out.path))
        throw CLI::ValidationError(out.option, "'" + out.path + "' is the " + in.option + " '" +
                                                   in.path +
                                                   "': writing it would destroy the input; "
                                                   "choose another output");
    for (size_t j = 0; j < i; ++j)
      if (given(outputs[j]) && sameOutput(outputs[j].path, out.path))
        throw CLI::ValidationError(out.option, "'" + out.path + "' is also the " +
                                                   outputs[j].option + " output '" +
                                                   outputs[j].path +
                                                   "': give each output its own file");
  }
  for (const NamedFile& out : outputs)
    if (given(out)) validateWritable(out.path);
}

void stageMesh(AtomicFileGroup& group, const std::string& path, const TriangleMesh& mesh,
               const std::string& format, const std::vector<uint32_t>* triangleFace,
               const MeshWriteOptions& options, const GlbInstances* instances) {
  const std::string chosen = meshFormat(path, format);
  group.stage(path, [&](std::ostream& out) {
    if (chosen == "obj")
      writeObj(out, mesh, options);
    else if (chosen == "ply")
      writePly(out, mesh, options);
    else
      writeGlb(out, mesh, triangleFace, instances);
  });
}

void addMeshOutputOptions(CLI::App* cmd, MeshOutputArgs& args) {
  cmd->add_option("--precision", args.precision,
                  "float or double: how OBJ and PLY carry positions and normals. double writes "
                  "17 significant digits in OBJ and `double` properties in PLY, with the values "
                  "computed in double where the command has them; not for .glb (fp32 only)")
      ->check(CLI::IsMember({"float", "double"}))
      ->capture_default_str();
  cmd->add_flag("--metadata", args.metadata,
                "also write where each vertex comes from, where the mesh has it: PLY vertex "
                "properties u, v and patch; OBJ 'g patch_<id>' groups. Off by default (files "
                "stay as before)");
}

MeshWriteOptions meshWriteOptions(const MeshOutputArgs& args, const std::string& path,
                                  const std::string& format) {
  MeshWriteOptions options;
  if (args.precision == "double") {
    if (!path.empty() && meshFormat(path, format) == "glb")
      throw CLI::ValidationError("--precision",
                                 "double is for .obj and .ply outputs: glTF (.glb) has no double "
                                 "vertex attributes; write .obj or .ply, or leave out "
                                 "--precision double");
    options.precision = MeshPrecision::Double;
  }
  options.metadata = args.metadata;
  return options;
}

void writePicture(const std::string& output, const std::vector<uint8_t>& picture, int width,
                  int height) {
  if (output == kStdioPath) {
    std::ostringstream png(std::ios::binary);
    writePng(png, picture, width, height);
    writeStdout(png.str());
  } else {
    writePngFile(output, picture, width, height);
  }
}

}  // namespace tessera::cli
