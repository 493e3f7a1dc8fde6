// What the Loop commands (cmd_loop.cpp: loop, limit and the registration; cmd_fit_join.cpp:
// fit, join) share: their parsed arguments, reading a control mesh and making the output mesh.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cli/outputs.h"
#include "loop/shapes.h"
#include "mesh/tessellate.h"

namespace tessera::cli {

struct LoopArgs {
  std::string input, target, output, backend = "auto", device;
  int levels = 2;
  bool limit = false;
  double lambda = 1.0, threshold = 0.0;
  int iterations = 100;
  std::string tolerance = "0.1%";  // fit: ε, model units or a percentage of the target's diagonal
  int maxRounds = 5;               // fit: rounds of fitting, each after a subdivision but the first
  size_t maxTriangles = 100000;    // fit: no subdivision past this many control triangles
  std::optional<int> levelsA, levelsB;  // join; unset: chosen by area (LoopJoinOptions)
  std::vector<double> cut;  // paste: nx ny nz d
  std::string pasteList, pasteFile;  // paste: chosen vertices, 1-based (io/vertex_selection.h)
  std::string picture;      // join: inputs, placement and result as one PNG
  MeshOutputArgs mesh;      // --precision
  std::string boundary = "corner";  // loop, limit: OpenSubdiv's EDGE_AND_CORNER, or "edge"
  uint64_t batchBytes = 0;          // loop, limit on Vulkan: 0 is the device's own bound
};

// A triangle control mesh from OBJ; topology errors name the file and the face's line.
LoopShape readControlMesh(const std::string& path,
                          LoopBoundary boundary = LoopBoundary::EdgeAndCorner);

// Double positions (and normals, if any) as the mesh the writers take: fp32 and double copies.
TriangleMesh loopMesh(const std::vector<glm::dvec3>& positions,
                      const std::vector<uint32_t>& triangles, const std::vector<glm::dvec3>& normals);

int runFit(const LoopArgs& a);
int runJoin(const LoopArgs& a);

}  // namespace tessera::cli
