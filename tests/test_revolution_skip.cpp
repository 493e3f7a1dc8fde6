// The nodes of surfaces of revolution skip rule T's parametric classifier
// (RevisingClassifier::rewritesWhole, trim/revolution_bound.h): the distance bound assigns
// their decisions whole, so the trees must be the ones built when every node still went to
// the inner classifier, bit for bit, on every face of a known form in the FreeCAD IDF library,
// and the inner classifier must see none of those nodes.
#ifdef TESSERA_HAVE_CAD
#include <catch2/catch.hpp>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cad/cad_file.h"
#include "cad/to_trimmed.h"
#include "geometry/model_frame.h"
#include "mesh/tessellate.h"
#include "quadtree/quadtree.h"
#include "trim/face_surface.h"
#include "trim/face_tessellation.h"
#include "sweep_share.h"
#include "trim/revolution_bound.h"

using namespace tessera;

namespace {

// Passes batches to the mirror, counting the nodes it is asked to decide.
class CountingClassifier final : public NodeClassifier {
 public:
  std::string name() const override { return "counting " + mirror_->name(); }
  void classify(const PatchSet& patches, const std::vector<gpu::QuadNode>& nodes,
                const QuadtreeOptions& options, std::vector<gpu::NodeDecision>& decisions,
                LevelStats& stats) override {
    seen += nodes.size();
    mirror_->classify(patches, nodes, options, decisions, stats);
  }
  size_t seen = 0;

 private:
  std::unique_ptr<NodeClassifier> mirror_ = makeMirrorClassifier();
};

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool sameLeaf(const QuadLeaf& a, const QuadLeaf& b) {
  return sameBits(a.rect, b.rect) && a.patchIndex == b.patchIndex && a.level == b.level &&
         a.cause == b.cause && a.path == b.path && sameBits(a.linearity, b.linearity) &&
         sameBits(a.flatness, b.flatness) && sameBits(a.split, b.split) &&
         a.diagonal == b.diagonal;
}

}  // namespace

TEST_CASE("revolution skip: surfaces of revolution get the same trees without rule T's "
          "parametric classifier, bit for bit, on the IDF library",
          "[cad][trim][revolution-skip]") {
  const std::string library = "/usr/share/freecad/Mod/Idf/Idflibs";
  REQUIRE(std::filesystem::exists(library));  // freecad-common (scripts/deps.sh)
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(library))
    if (entry.path().extension() == ".stp") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  // Under the sanitizers (sweep_share.h) a spread share of the files: the same code on fewer
  // faces. The Release run compares every face of known form.
  files = test::sweptSubset(files);
  const bool everyFile = test::sweepShare() == 1.0;
  size_t faces = 0, leaves = 0;
  for (const std::string& path : files) {
    const CadFile file = readCadFile(path);
    Bnd_Box box;
    BRepBndLib::Add(file.shape, box);
    const CadImport import = toTrimmedModel(file, 1e-3 * std::sqrt(box.SquareExtent()));
    const ModelFrame frame = trimmedModelFrame(import.model);
    const QuadtreeOptions options = toleranceOptions(import.delta / frame.scale);
    for (const TrimmedFace& face : import.model.faces) {
      if (face.revolution.profile == RevolutionForm::Profile::None) continue;
      std::vector<BezierPatch> patches;
      for (const BezierPatchPiece& piece : face.pieces) patches.push_back(piece.patch);
      const PatchSet patchSet = toPatchSet(toLocalFrame(std::move(patches), frame));
      const FaceSurface surface(face);
      std::vector<RevolutionBoundClassifier::Patch> known;
      for (size_t piece = 0; piece < face.pieces.size(); ++piece)
        known.push_back({&face.revolution, &surface, piece});

      CountingClassifier skipped, full;
      RevolutionBoundClassifier skipping(skipped, known, frame.scale);
      RevolutionBoundClassifier everyNode(full, known, frame.scale);
      everyNode.setSkipRewritten(false);
      const QuadtreeResult a = buildQuadtree(patchSet, options, skipping);
      const QuadtreeResult b = buildQuadtree(patchSet, options, everyNode);
      INFO(path << ", face " << face.faceIndex);
      CHECK(skipped.seen == 0);
      CHECK(full.seen > 0);
      REQUIRE(a.leaves.size() == b.leaves.size());
      for (size_t k = 0; k < a.leaves.size(); ++k) REQUIRE(sameLeaf(a.leaves[k], b.leaves[k]));
      ++faces;
      leaves += a.leaves.size();
    }
  }
  WARN(faces << " faces of known form, " << leaves << " leaves compared");
  CHECK(faces > (everyFile ? 500 : 50));  // the library's cylinders alone are 536
}

#endif
