// The tessellator's output: an indexed triangle mesh in fp32 (what the GPU produces and what
// OBJ/PLY carry by default), with optional double copies of positions and normals. Plain data;
// the writers live in host/io/.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace tessera {

struct TriangleMesh {
  // Per-vertex arrays. normals, uvs and patchIds are either empty or one per position.
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;       // the (u, v) parameter of the vertex on its patch
  std::vector<uint32_t> patchIds;   // index of the source patch
  // Optional double-precision copies, empty or one per position: what a producer that computes
  // in double (Loop on the reference backend, fit, join, the tessellation's vertices evaluated
  // again in double) hands to the writers' double precision (io/mesh_write_options.h).
  std::vector<glm::dvec3> positionsDouble;
  std::vector<glm::dvec3> normalsDouble;
  // Three per triangle, counter-clockwise seen from the side the normals point to.
  std::vector<uint32_t> indices;
  // Optional, empty or one per triangle: its source patch (a welded vertex's patchIds entry
  // names only one of the patches that share it). OBJ's patch groups come from it.
  std::vector<uint32_t> trianglePatchIds;

  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return indices.size() / 3; }

  // Throws std::invalid_argument (a bug in the producer, not bad user input) unless the
  // optional arrays are empty or match the positions, the indices form whole triangles that
  // all point at existing vertices, and every coordinate is finite (OBJ/PLY readers choke on
  // "nan", and a NaN here always means a bug upstream).
  void validate() const {
    auto checkSize = [&](size_t size, const char* name) {
      if (size != 0 && size != positions.size())
        throw std::invalid_argument(std::string("TriangleMesh: ") + name + " has " +
                                    std::to_string(size) + " entries for " +
                                    std::to_string(positions.size()) + " positions");
    };
    checkSize(normals.size(), "normals");
    checkSize(uvs.size(), "uvs");
    checkSize(patchIds.size(), "patchIds");
    checkSize(positionsDouble.size(), "positionsDouble");
    checkSize(normalsDouble.size(), "normalsDouble");
    // Indices are uint32_t, so more vertices could not all be addressed.
    if (positions.size() > std::numeric_limits<uint32_t>::max())
      throw std::invalid_argument("TriangleMesh: more vertices than 32-bit indices can address");
    if (indices.size() % 3 != 0)
      throw std::invalid_argument("TriangleMesh: index count " + std::to_string(indices.size()) +
                                  " is not a multiple of 3");
    if (!trianglePatchIds.empty() && trianglePatchIds.size() != indices.size() / 3)
      throw std::invalid_argument("TriangleMesh: trianglePatchIds has " +
                                  std::to_string(trianglePatchIds.size()) + " entries for " +
                                  std::to_string(indices.size() / 3) + " triangles");
    for (size_t k = 0; k < indices.size(); ++k)
      if (indices[k] >= positions.size())
        throw std::invalid_argument("TriangleMesh: index " + std::to_string(k) + " is " +
                                    std::to_string(indices[k]) + ", but there are only " +
                                    std::to_string(positions.size()) + " vertices");
    auto checkFinite = [](const auto& values, int components, const char* name) {
      for (size_t k = 0; k < values.size(); ++k)
        for (int c = 0; c < components; ++c)
          if (!std::isfinite(values[k][c]))
            throw std::invalid_argument(std::string("TriangleMesh: ") + name + "[" +
                                        std::to_string(k) + "] is not finite");
    };
    checkFinite(positions, 3, "positions");
    checkFinite(normals, 3, "normals");
    checkFinite(uvs, 2, "uvs");
    checkFinite(positionsDouble, 3, "positionsDouble");
    checkFinite(normalsDouble, 3, "normalsDouble");
  }
};

}  // namespace tessera
