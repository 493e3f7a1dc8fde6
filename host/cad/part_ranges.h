// Where an assembly's parts lie in the mesh that holds each once (CopyPlacement::Listed,
// cad/mesh_cad_file.h): the ranges of vertices and triangles an engine draws instanced
// (CadMesh::parts, include/tessera/cad.h).
#pragma once
#include <cstdint>
#include <vector>

#include "io/gltf_writer.h"
#include "mesh/mesh.h"

namespace tessera {

struct PartRange {
  uint32_t firstVertex = 0, vertexCount = 0;
  uint32_t firstTriangle = 0, triangleCount = 0;
};

// Per part of `instances`, its vertices and triangles among the mesh's first
// instances.vertices and instances.triangles (triangleFace: each triangle's face number). The
// mesher emits faces in order and a part's faces are consecutive and weld to nothing else, so
// each part's are one range; std::logic_error if the mesh breaks that (a triangle of the part
// outside its run, or a vertex that another triangle uses too). A part with no triangles (its
// faces all failed) has empty ranges at 0.
std::vector<PartRange> partRangesOf(const TriangleMesh& mesh,
                                    const std::vector<uint32_t>& triangleFace,
                                    const GlbInstances& instances);

}  // namespace tessera
