// findSharedEdges sorts one pool of side keys instead of filling a std::map from key to sides
// (a vector per key and per side): the groups must come out numbered as the map numbered them
// (its key order, members in the order seen), since the mesh's vertex order follows them. The
// map's version is kept here as the reference, on the tea set and on random patches built to
// collide (few distinct coordinates, -0 and +0, mixed degrees so one key is a prefix of
// another, weights on some).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <random>
#include <string>

#include "io/bpt_reader.h"
#include "mesh/shared_edges.h"

using namespace tessera;

namespace {

PatchTopology mapReference(const std::vector<BezierPatch>& patches) {
  using Key = std::vector<uint64_t>;
  const auto keyOf = [](const BezierPatch& patch, const std::vector<size_t>& indices) {
    Key key;
    for (size_t k : indices)
      for (double x : {patch.cp[k].x, patch.cp[k].y, patch.cp[k].z,
                       patch.weights.empty() ? 1.0 : patch.weights[k]}) {
        if (x == 0.0) x = 0.0;
        uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        key.push_back(b);
      }
    return key;
  };
  PatchTopology topology;
  topology.sides.resize(patches.size());
  struct Member {
    uint32_t patch;
    int side;
    bool reversed;
  };
  std::map<Key, std::vector<Member>> curves;
  for (uint32_t p = 0; p < patches.size(); ++p)
    for (int side = 0; side < 4; ++side) {
      const BezierPatch& patch = patches[p];
      const int n = patch.degreeU, m = patch.degreeV;
      std::vector<size_t> indices;
      if (side == kSideV0 || side == kSideV1)
        for (int i = 0; i <= n; ++i) indices.push_back(size_t(i * (m + 1) + (side == kSideV0 ? 0 : m)));
      else
        for (int j = 0; j <= m; ++j) indices.push_back(size_t((side == kSideU0 ? 0 : n) * (m + 1) + j));
      if (std::all_of(indices.begin(), indices.end(),
                      [&](size_t k) { return patch.cp[k] == patch.cp[indices[0]]; })) {
        topology.sides[p][side].collapsed = true;
        ++topology.collapsedSides;
        continue;
      }
      const Key forward = keyOf(patch, indices);
      std::reverse(indices.begin(), indices.end());
      const Key backward = keyOf(patch, indices);
      const bool reversed = backward < forward;
      curves[reversed ? backward : forward].push_back({p, side, reversed});
    }
  for (const auto& [key, members] : curves) {
    if (members.size() < 2) continue;
    const int32_t group = int32_t(topology.groupCount++);
    for (const Member& m : members) {
      topology.sides[m.patch][m.side].group = group;
      topology.sides[m.patch][m.side].reversed = m.reversed;
      ++topology.sharedSides;
    }
  }
  return topology;
}

void requireSameTopology(const PatchTopology& a, const PatchTopology& b) {
  REQUIRE(a.groupCount == b.groupCount);
  REQUIRE(a.sharedSides == b.sharedSides);
  REQUIRE(a.collapsedSides == b.collapsedSides);
  REQUIRE(a.sides.size() == b.sides.size());
  for (size_t p = 0; p < a.sides.size(); ++p)
    for (int s = 0; s < 4; ++s) {
      INFO("patch " << p << ", side " << s);
      REQUIRE(a.sides[p][s].group == b.sides[p][s].group);
      REQUIRE(a.sides[p][s].reversed == b.sides[p][s].reversed);
      REQUIRE(a.sides[p][s].collapsed == b.sides[p][s].collapsed);
    }
}

}  // namespace

TEST_CASE("findSharedEdges numbers its groups as the map from key to sides did",
          "[mesh][shared_edges]") {
  SECTION("the tea set") {
    for (const char* model : {"teapot", "teacup", "teaspoon"}) {
      INFO(model);
      const std::vector<BezierPatch> patches =
          readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + model + ".bpt");
      const PatchTopology topology = findSharedEdges(patches);
      REQUIRE(topology.groupCount > 0);
      requireSameTopology(topology, mapReference(patches));
    }
  }
  SECTION("random patches that collide") {
    std::mt19937 random(17);
    const double values[] = {0.0, -0.0, 1.0, 2.0};
    for (int trial = 0; trial < 50; ++trial) {
      std::vector<BezierPatch> patches;
      for (int p = 0; p < 40; ++p) {
        BezierPatch patch;
        patch.degreeU = 1 + int(random() % 3);
        patch.degreeV = 1 + int(random() % 3);
        const size_t count = size_t(patch.degreeU + 1) * size_t(patch.degreeV + 1);
        for (size_t k = 0; k < count; ++k)
          patch.cp.push_back(glm::dvec3(values[random() % 4], values[random() % 2],
                                        values[random() % 4 == 0 ? 2 : 0]));
        if (random() % 3 == 0)
          for (size_t k = 0; k < count; ++k) patch.weights.push_back(random() % 2 ? 1.0 : 0.5);
        patches.push_back(patch);
      }
      INFO("trial " << trial);
      const PatchTopology topology = findSharedEdges(patches);
      requireSameTopology(topology, mapReference(patches));
      if (trial == 0) REQUIRE(topology.groupCount > 0);
    }
  }
}
