// Issue 18, "stream large meshes to the output": the tea set tessellated in patch groups of 1,
// 3 and 7 (mesh/streamed_tessellation.h) gives the held mesh's triangles, the same set of
// position triples (corners in order up to rotation), in every mode of the watertight tests,
// and the streamed mesh is as closed: no crack, T-junction, over-used or inconsistent edge,
// no zero-area triangle. Vertex numbering differs (the held mesh numbers in the whole tree's
// leaf order), so the files are not byte for byte the same; the stream writer's files are
// writeObj's, writePly's and writeGlb's bytes for the mesh it was given.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "common/memory_budget.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "io/gltf_writer.h"
#include "io/mesh_stream_writer.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "mesh/shared_edges.h"
#include "mesh/streamed_tessellation.h"
#include "quadtree/tolerance.h"
#include "sweep_share.h"
#include "tea_set_settings.h"
#include "tessellation_defects.h"

using namespace tessera;

namespace {

std::vector<BezierPatch> teaSetModel(const std::string& model) {
  return readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + model + ".bpt");
}

using Triple = std::array<float, 9>;

// Each triangle as its three positions, rotated to start at the smallest (orientation kept),
// sorted.
std::vector<Triple> triangleSet(const TriangleMesh& mesh) {
  std::vector<Triple> triples;
  for (size_t k = 0; k < mesh.indices.size(); k += 3) {
    std::array<std::array<float, 3>, 3> corners;
    for (int c = 0; c < 3; ++c) {
      const glm::vec3& p = mesh.positions[mesh.indices[k + size_t(c)]];
      corners[size_t(c)] = {p.x, p.y, p.z};
    }
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    Triple t;
    for (size_t c = 0; c < 9; ++c) t[c] = corners[c / 3][c % 3];
    triples.push_back(t);
  }
  std::sort(triples.begin(), triples.end());
  return triples;
}

struct Streamed {
  Tessellation whole;  // the chunks put together, as a reader of the file would have them
  StreamedTessellationStats stats;
  std::string obj, ply, glb;  // what MeshStreamWriter writes
};

// The chunk's vertices and triangles after the mesh's, as a reader of the file has them.
void appendChunk(TriangleMesh& mesh, const MeshChunk& c) {
  mesh.positions.insert(mesh.positions.end(), c.positions.begin(), c.positions.end());
  mesh.normals.insert(mesh.normals.end(), c.normals.begin(), c.normals.end());
  mesh.uvs.insert(mesh.uvs.end(), c.uvs.begin(), c.uvs.end());
  mesh.patchIds.insert(mesh.patchIds.end(), c.patchIds.begin(), c.patchIds.end());
  mesh.indices.insert(mesh.indices.end(), c.indices.begin(), c.indices.end());
}

Streamed stream(const std::vector<BezierPatch>& patches, const QuadtreeOptions& options,
                Backend& backend, size_t groupSize) {
  Streamed s;
  MeshStreamWriter obj(MeshStreamWriter::Format::Obj, "streamed.obj");
  MeshStreamWriter ply(MeshStreamWriter::Format::Ply, "streamed.ply");
  MeshStreamWriter glb(MeshStreamWriter::Format::Glb, "streamed.glb");
  TriangleMesh& mesh = s.whole.mesh;
  s.stats = tessellateStreamed(patches, options, backend, groupSize, [&](const MeshChunk& c) {
    obj.add(c);
    ply.add(c);
    glb.add(c);
    appendChunk(mesh, c);
    s.whole.trianglePatch.insert(s.whole.trianglePatch.end(), c.trianglePatch.begin(),
                                 c.trianglePatch.end());
  });
  std::ostringstream objText, plyText, glbBytes;
  obj.finish(objText);
  ply.finish(plyText);
  glb.finish(glbBytes);
  s.obj = objText.str();
  s.ply = plyText.str();
  s.glb = glbBytes.str();
  return s;
}

void requireSameAsHeld(const std::string& what, const std::vector<BezierPatch>& patches,
                       const Tessellation& held, const Streamed& s) {
  INFO(what << ": " << held.mesh.triangleCount() << " triangles held, "
            << s.whole.mesh.triangleCount() << " streamed in " << s.stats.groups << " groups");
  REQUIRE(held.mesh.triangleCount() > 0);
  CHECK(s.stats.totals.triangles == held.stats.triangles);
  CHECK(s.stats.totals.leaves == held.stats.leaves);
  CHECK(s.stats.totals.depth == held.stats.depth);
  REQUIRE(triangleSet(s.whole.mesh) == triangleSet(held.mesh));
  // Closedness: the census of the streamed mesh itself (its own numbering).
  const test::EdgeCensus c = test::censusOf(s.whole.mesh, 0.0);
  CHECK(c.overusedEdges == 0);
  CHECK(c.inconsistentEdges == 0);
  CHECK(c.degenerateTriangles == 0);
  double longest = 0;
  CHECK(test::tJunctionCount(s.whole.mesh, c, 1e-6 * controlPointDiagonal(patches), &longest) ==
        0);
  // Open edges: as many as the held mesh has (those on the model's open sides): a seam vertex
  // written twice would open the edges at it.
  CHECK(c.boundaryEdges == test::censusOf(held.mesh, 0.0).boundaryEdges);
  // The stream writer's bytes are the held writers' for the same mesh.
  std::ostringstream obj, ply, glb;
  writeObj(obj, s.whole.mesh);
  writePly(ply, s.whole.mesh);
  writeGlb(glb, s.whole.mesh);
  CHECK(s.obj == obj.str());
  CHECK(s.ply == ply.str());
  CHECK(s.glb == glb.str());
}

// Each setting streams in one group size, taking 7, 3 and 1 in turn (groups of one patch make
// every seam cross groups; 3 and 7 split the model's patch rings unevenly), each size over five
// or six settings per model. The finest settings (every third, from A 4x4: B, C and D at 0.02,
// T at 0.01%) take groups of 7: a group of one rebuilds each of its neighbours' trees.
void requireTeaSetModelStreamsAsHeld(const std::string& model) {
  Backend cpu = makeMirrorBackend();
  const std::vector<BezierPatch> patches = teaSetModel(model);
  const std::vector<test::TeaSetSetting> settings = test::teaSetSettings(patches);
  const size_t groupSizes[] = {7, 3, 1};
  // Under the sanitizers (sweep_share.h) a spread share of the settings, without C and D at
  // 0.02: their curvature searches take most of the time, on no path of their own.
  std::vector<size_t> chosen;
  for (size_t k = 0; k < settings.size(); ++k)
    if (test::sweepShare() == 1.0 || (settings[k].name != "C 0.02" && settings[k].name != "D 0.02"))
      chosen.push_back(k);
  for (size_t k : test::sweptSubset(chosen)) {
    const size_t group = groupSizes[k % 3];
    const Tessellation held = tessellate(patches, settings[k].options, cpu);
    requireSameAsHeld(model + " " + settings[k].name + ", groups of " + std::to_string(group),
                      patches, held, stream(patches, settings[k].options, cpu, group));
  }
}

}  // namespace

TEST_CASE("streamed teapot meshes are the held ones in every mode", "[streamed][watertight]") {
  requireTeaSetModelStreamsAsHeld("teapot");
}
TEST_CASE("streamed teacup meshes are the held ones in every mode", "[streamed][watertight]") {
  requireTeaSetModelStreamsAsHeld("teacup");
}
TEST_CASE("streamed teaspoon meshes are the held ones in every mode", "[streamed][watertight]") {
  requireTeaSetModelStreamsAsHeld("teaspoon");
}

TEST_CASE("a streamed group that does not fit the memory budget is refused", "[streamed]") {
  const std::vector<BezierPatch> patches = teaSetModel("teapot");
  Backend cpu = makeMirrorBackend();
  // Rule T at 0.01% of the diagonal: a large tree at little cost (D 0.02 is as large and
  // spends ten times as long on its curvature searches).
  const QuadtreeOptions options =
      toleranceOptions(resolveTolerance(parseTolerance("0.01%"), patches));
  const uint64_t budget = memoryBudget();
  // 12.5 MiB: the held teapot needs more; a group of 4 patches with its neighbours fits in
  // 12, one of 8 needs more than 13 (measured with the centred-form bound, `--stream-patches`).
  setMemoryBudget(25u << 19);
  size_t chunks = 0;
  const auto count = [&](const MeshChunk&) { ++chunks; };
  CHECK_THROWS_AS(tessellate(patches, options, cpu), MemoryLimitError);
  // Groups of 4 patches fit; automatic sizing finds a size that fits too.
  CHECK_NOTHROW(tessellateStreamed(patches, options, cpu, 4, count));
  CHECK(chunks == 8);
  CHECK(tessellateStreamed(patches, options, cpu, 0, count).totals.triangles > 0);
  // Groups of 8 patches with their neighbours do not fit.
  CHECK_THROWS_WITH(tessellateStreamed(patches, options, cpu, 8, count),
                    Catch::Contains("streamed patches ") &&
                        Catch::Contains("more than the memory budget of 12.5 MiB"));
  setMemoryBudget(budget);
}

TEST_CASE("Vulkan's streamed teapot is the held mirror mesh", "[gpu][streamed]") {
  const std::vector<BezierPatch> patches = teaSetModel("teapot");
  Backend gpu = makeVulkanBackend(test::gpuContext());
  Backend cpu = makeMirrorBackend();
  for (const test::TeaSetSetting& setting : test::teaSetSettings(patches)) {
    if (setting.name != "B 0.1" && setting.name != "T 0.1%") continue;
    const Tessellation held = tessellate(patches, setting.options, cpu);
    const Streamed s = stream(patches, setting.options, gpu, 3);
    if (test::gpuContext().info().isLavapipe())
      requireSameAsHeld("teapot " + setting.name + " on Vulkan, groups of 3", patches, held, s);
    else
      CHECK(s.stats.totals.triangles > 0);
  }
  test::requireValidationClean();
}

namespace {

// `chunks` through MeshStreamWriter's GLB, and writeGlb of them put together.
std::pair<std::string, std::string> glbStreamedAndHeld(const std::vector<MeshChunk>& chunks) {
  MeshStreamWriter writer(MeshStreamWriter::Format::Glb, "parts.glb");
  TriangleMesh mesh;
  for (const MeshChunk& c : chunks) {
    writer.add(c);
    appendChunk(mesh, c);
  }
  std::ostringstream streamed, held;
  writer.finish(streamed);
  writeGlb(held, mesh);
  return {streamed.str(), held.str()};
}

MeshChunk fan(uint32_t first, size_t vertices, uint32_t patch) {
  MeshChunk c;
  for (size_t i = 0; i < vertices; ++i) {
    const float a = float(i) * 0.1f;
    c.positions.push_back({std::cos(a), std::sin(a), float(first) * 0.01f});
    c.normals.push_back({0.f, 0.5f, 2.f});
    c.uvs.push_back({a, 1.f - a});
    c.patchIds.push_back(patch);
  }
  return c;
}

}  // namespace

TEST_CASE("the GLB stream writer gives writeGlb's bytes in the cases the tea set misses",
          "[streamed][gltf]") {
  SECTION("a zero normal whose triangles come in later chunks, 16-bit indices, odd count") {
    MeshChunk a = fan(0, 4, 1), b = fan(4, 3, 2);
    a.normals[0] = glm::vec3(0);  // the collapsed corner
    a.indices = {0, 1, 2};
    b.normals[1] = glm::vec3(-0.f, 0.f, 0.f);
    b.indices = {0, 2, 4, 0, 3, 5, 5, 6, 0};  // vertex 0 again, and chunk b's own zero (5)
    const auto [streamed, held] = glbStreamedAndHeld({a, b});
    REQUIRE(held.size() > 0);
    CHECK(streamed == held);
  }
  SECTION("32-bit indices, and a patch id past 2^24 (no _PATCH_ID)") {
    MeshChunk a = fan(0, 40000, 3), b = fan(40000, 30000, 1u << 24);
    a.indices = {0, 1, 2};
    b.indices = {0, 40001, 69999};
    const auto [streamed, held] = glbStreamedAndHeld({a, b});
    CHECK(held.find("_PATCH_ID") == std::string::npos);
    CHECK(held.find("\"componentType\":5125") != std::string::npos);
    CHECK(streamed == held);
  }
  SECTION("no triangles: an empty scene") {
    const auto [streamed, held] = glbStreamedAndHeld({fan(0, 3, 0)});
    CHECK(held.find("\"buffers\"") == std::string::npos);
    CHECK(streamed == held);
  }
  SECTION("a malformed chunk is refused") {
    MeshStreamWriter writer(MeshStreamWriter::Format::Glb, "bad.glb");
    MeshChunk c = fan(0, 3, 0);
    c.indices = {0, 1, 3};
    CHECK_THROWS_AS(writer.add(c), std::invalid_argument);
  }
}
