// One comparison of two triangulations (ParamMesh) field by field, bit for bit, for the tests
// that hold a fast or parallel path to the general one.
#pragma once
#include <catch2/catch.hpp>

#include "mesh/triangulate.h"

namespace tessera::test {

inline void requireSameParamMesh(const ParamMesh& a, const ParamMesh& b) {
  REQUIRE(a.vertices.size() == b.vertices.size());
  for (size_t i = 0; i < a.vertices.size(); ++i) {
    INFO("vertex " << i);
    REQUIRE(a.vertices[i].patchIndex == b.vertices[i].patchIndex);
    REQUIRE(a.vertices[i].u == b.vertices[i].u);
    REQUIRE(a.vertices[i].v == b.vertices[i].v);
  }
  REQUIRE(a.indices == b.indices);
  REQUIRE(a.trianglePatch == b.trianglePatch);
  REQUIRE(a.cornerUv == b.cornerUv);
  REQUIRE(a.droppedTriangles == b.droppedTriangles);
  REQUIRE(a.diagonalFans == b.diagonalFans);
  REQUIRE(a.sharedEdgeGroups == b.sharedEdgeGroups);
  REQUIRE(a.seamKeys.size() == b.seamKeys.size());
  for (size_t i = 0; i < a.seamKeys.size(); ++i) {
    INFO("seam key " << i);
    REQUIRE(a.seamKeys[i].kind == b.seamKeys[i].kind);
    REQUIRE(a.seamKeys[i].group == b.seamKeys[i].group);
    REQUIRE(a.seamKeys[i].parameter == b.seamKeys[i].parameter);
    REQUIRE(a.seamKeys[i].point == b.seamKeys[i].point);
  }
}

}  // namespace tessera::test
