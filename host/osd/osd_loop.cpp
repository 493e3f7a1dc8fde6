#include "osd/osd_loop.h"

#include <opensubdiv/far/topologyDescriptor.h>

#include <stdexcept>
#include <string>

namespace tessera::osd {

using namespace OpenSubdiv;

std::unique_ptr<TopologyRefiner> makeLoopRefiner(const LoopControlTopology& control,
                                                 BoundaryRule boundary) {
  using Descriptor = Far::TopologyDescriptor;
  using Factory = Far::TopologyRefinerFactory<Descriptor>;
  const int faces = int(control.triangles.size() / 3);
  std::vector<int> vertsPerFace(faces, 3);
  std::vector<int> indices(control.triangles.begin(), control.triangles.end());
  std::vector<int> creasePairs;
  for (const auto& c : control.creases) creasePairs.insert(creasePairs.end(), {int(c[0]), int(c[1])});
  std::vector<float> creaseWeights(control.creases.size(), Sdc::Crease::SHARPNESS_INFINITE);
  std::vector<int> corners(control.corners.begin(), control.corners.end());
  std::vector<float> cornerWeights(corners.size(), Sdc::Crease::SHARPNESS_INFINITE);

  Descriptor d;
  d.numVertices = int(control.vertexCount);
  d.numFaces = faces;
  d.numVertsPerFace = vertsPerFace.data();
  d.vertIndicesPerFace = indices.data();
  d.numCreases = int(control.creases.size());
  d.creaseVertexIndexPairs = creasePairs.data();
  d.creaseWeights = creaseWeights.data();
  d.numCorners = int(corners.size());
  d.cornerVertexIndices = corners.data();
  d.cornerWeights = cornerWeights.data();

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(boundary);
  TopologyRefiner* refiner = Factory::Create(d, Factory::Options(Sdc::SCHEME_LOOP, options));
  if (!refiner) throw std::runtime_error("OpenSubdiv rejected the Loop control mesh");
  return std::unique_ptr<TopologyRefiner>(refiner);
}

std::vector<std::vector<uint32_t>> matchVertices(const TopologyRefiner& refiner,
                                                 const std::vector<LoopTopology>& levels) {
  std::vector<std::vector<uint32_t>> ours(1);
  for (int v = 0; v < refiner.GetLevel(0).GetNumVertices(); ++v) ours[0].push_back(uint32_t(v));
  for (int l = 0; l < refiner.GetMaxLevel() && l + 1 < int(levels.size()); ++l) {
    const Far::TopologyLevel& level = refiner.GetLevel(l);
    const LoopTopology& t = levels[l];
    std::vector<uint32_t> next(refiner.GetLevel(l + 1).GetNumVertices(), kLoopNone);
    for (int v = 0; v < level.GetNumVertices(); ++v)
      next[level.GetVertexChildVertex(v)] = ours[l][v];  // an even vertex keeps its index
    for (int e = 0; e < level.GetNumEdges(); ++e) {
      const auto ends = level.GetEdgeVertices(e);
      const uint32_t edge = t.edgeBetween(ours[l][ends[0]], ours[l][ends[1]]);
      if (edge == kLoopNone)
        throw std::runtime_error("OpenSubdiv edge " + std::to_string(e) + " of level " +
                                 std::to_string(l) + " is not one of ours");
      next[level.GetEdgeChildVertex(e)] = t.vertexCount + edge;
    }
    ours.push_back(std::move(next));
  }
  return ours;
}

}  // namespace tessera::osd
