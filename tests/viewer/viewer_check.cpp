// Checks of `tessera view`'s scripted output, for ctest (tests/viewer/CMakeLists.txt):
//   viewer_check picture SHOT.png MIN_MESH_FRACTION MIN_COLOURS
//     the screenshot shows a mesh: at least that fraction of its pixels are neither the
//     background (kRenderBackground) nor the overlay's band and letters, and the picture has
//     at least that many distinct colours (shading, not a flat fill);
//   viewer_check mesh FRAME.glb
//     the dumped frame, its vertices welded where positions are equal bit for bit, has no
//     T-junction and no edge used by three triangles (tests/mesh_checks.h).
// Prints what it measured either way; exit 0 when the check holds, 1 when not, 2 on bad input.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#include "mesh_checks.h"
#include "render/offscreen.h"

namespace {

using tessera::TriangleMesh;

int checkPicture(const char* path, double minFraction, size_t minColours) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path, &width, &height, &channels, 4);
  if (!pixels) {
    std::fprintf(stderr, "viewer_check: %s: not a PNG (%s)\n", path, stbi_failure_reason());
    return 2;
  }
  // The overlay: white letters on a band of grey 0.12 (viewer/overlay_text.cpp), UNORM-rounded.
  const std::array<uint8_t, 3> overlay[2] = {{255, 255, 255}, {31, 31, 31}};
  size_t meshPixels = 0;
  std::set<uint32_t> colours;
  for (size_t p = 0; p < size_t(width) * height; ++p) {
    const stbi_uc* c = &pixels[4 * p];
    colours.insert(uint32_t(c[0]) << 16 | uint32_t(c[1]) << 8 | c[2]);
    bool background = std::memcmp(c, tessera::kRenderBackground.data(), 3) == 0;
    for (const auto& o : overlay) background = background || std::memcmp(c, o.data(), 3) == 0;
    if (!background) ++meshPixels;
  }
  stbi_image_free(pixels);
  const double fraction = double(meshPixels) / (double(width) * height);
  std::printf("%s: %dx%d, %zu mesh pixels (%.2f%%, need %.2f%%), %zu colours (need %zu)\n", path,
              width, height, meshPixels, 100 * fraction, 100 * minFraction, colours.size(),
              minColours);
  return fraction >= minFraction && colours.size() >= minColours ? 0 : 1;
}

uint32_t u32At(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | uint8_t(s[at + k]);
  return v;
}

// POSITION and the indices of the one primitive tessera's glTF writer makes (host/io/gltf_writer.h).
bool readGlb(const char* path, TriangleMesh& mesh) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  if (bytes.size() < 28 || bytes.compare(0, 4, "glTF") != 0) return false;
  const uint32_t jsonLength = u32At(bytes, 12);
  const nlohmann::json doc = nlohmann::json::parse(bytes.substr(20, jsonLength));
  const size_t binStart = 20 + size_t(jsonLength) + 8;
  const nlohmann::json& primitive = doc.at("meshes").at(0).at("primitives").at(0);
  auto bytesOf = [&](int accessor, size_t& count, int& componentType) {
    const nlohmann::json& a = doc.at("accessors").at(accessor);
    const nlohmann::json& view = doc.at("bufferViews").at(a.at("bufferView").get<int>());
    count = a.at("count");
    componentType = a.at("componentType");
    return bytes.data() + binStart + view.at("byteOffset").get<size_t>();
  };
  size_t count = 0;
  int type = 0;
  const char* positions = bytesOf(primitive.at("attributes").at("POSITION"), count, type);
  mesh.positions.resize(count);
  std::memcpy(mesh.positions.data(), positions, count * 12);
  const char* indices = bytesOf(primitive.at("indices"), count, type);
  mesh.indices.resize(count);
  for (size_t k = 0; k < count; ++k) {
    if (type == 5123) {
      uint16_t i;
      std::memcpy(&i, indices + 2 * k, 2);
      mesh.indices[k] = i;
    } else {
      std::memcpy(&mesh.indices[k], indices + 4 * k, 4);
    }
  }
  return true;
}

int checkMesh(const char* path) {
  TriangleMesh drawn;
  try {
    if (!readGlb(path, drawn)) throw std::runtime_error("not a GLB");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "viewer_check: %s: %s\n", path, e.what());
    return 2;
  }
  // Each patch writes its own copy of its border vertices; shared ones are equal bit for bit.
  TriangleMesh mesh;
  std::map<std::array<uint32_t, 3>, uint32_t> weld;
  std::vector<uint32_t> welded(drawn.positions.size());
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (size_t v = 0; v < drawn.positions.size(); ++v) {
    std::array<uint32_t, 3> key;
    std::memcpy(key.data(), &drawn.positions[v], sizeof key);
    const auto [it, inserted] = weld.emplace(key, uint32_t(mesh.positions.size()));
    if (inserted) mesh.positions.push_back(drawn.positions[v]);
    welded[v] = it->second;
    lo = glm::min(lo, drawn.positions[v]);
    hi = glm::max(hi, drawn.positions[v]);
  }
  for (uint32_t i : drawn.indices) mesh.indices.push_back(welded[i]);
  const tessera::test::EdgeCensus census = tessera::test::censusOf(mesh, 0.0);
  double largestGap = 0;
  const double eps = 1e-6 * glm::length(glm::dvec3(hi - lo));
  const size_t tJunctions = tessera::test::tJunctionCount(mesh, census, eps, &largestGap);
  std::printf("%s: %zu triangles, %zu vertices welded to %zu; edges: %zu shared, %zu open, "
              "%zu used 3+ times; %zu T-junctions (longest open edge with one: %g)\n",
              path, mesh.triangleCount(), drawn.positions.size(), mesh.positions.size(),
              census.manifoldEdges, census.boundaryEdges, census.overusedEdges, tJunctions,
              largestGap);
  return mesh.triangleCount() > 0 && tJunctions == 0 && census.overusedEdges == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::strcmp(argv[1], "picture") == 0)
    return checkPicture(argv[2], std::atof(argv[3]), size_t(std::atol(argv[4])));
  if (argc == 3 && std::strcmp(argv[1], "mesh") == 0) return checkMesh(argv[2]);
  std::fprintf(stderr, "usage: viewer_check picture SHOT.png MIN_MESH_FRACTION MIN_COLOURS\n"
                       "       viewer_check mesh FRAME.glb\n");
  return 2;
}
