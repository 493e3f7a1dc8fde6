// How the OBJ and PLY writers put a TriangleMesh out (glTF has no double attributes and its
// writer takes none of this).
#pragma once

namespace tessera {

enum class MeshPrecision {
  Float,   // positions and normals as fp32 (the shortest text that reads back to the float)
  Double,  // as double: TriangleMesh::positionsDouble / normalsDouble when the producer filled
           // them, else the fp32 values widened (exact, but no more accurate)
};

struct MeshWriteOptions {
  MeshPrecision precision = MeshPrecision::Float;
  // Also the patch metadata, where the mesh has it: PLY vertex properties u, v (float) and
  // patch (uint), the names assimp, VTK and meshio read; OBJ `g patch_<id>` lines before each
  // run of triangles of one patch (trianglePatchIds). Off by default, so files written before
  // stay byte for byte the same.
  bool metadata = false;
};

}  // namespace tessera
