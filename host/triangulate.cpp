#include "triangulate.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>

namespace tessera {
namespace {

uint32_t bits(float x) {
  uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

uint64_t lineKey(uint32_t patch, float coordinate) {
  return (uint64_t(patch) << 32) | bits(coordinate);
}

struct VertexKeyHash {
  size_t operator()(const std::pair<uint64_t, uint32_t>& k) const {
    return std::hash<uint64_t>()(k.first * 0x9E3779B97F4A7C15ull ^ k.second);
  }
};

class ParamMeshBuilder {
 public:
  explicit ParamMeshBuilder(ParamMesh& mesh) : mesh_(mesh) {}

  uint32_t vertex(uint32_t patch, float u, float v) {
    auto key = std::make_pair(lineKey(patch, u), bits(v));
    auto [it, inserted] = index_.emplace(key, uint32_t(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back({patch, u, v});
    return it->second;
  }

 private:
  ParamMesh& mesh_;
  std::unordered_map<std::pair<uint64_t, uint32_t>, uint32_t, VertexKeyHash> index_;
};

// Sorted coordinates of the leaf corners on each line u = const or v = const of a patch.
// Leaf rectangles copy their parents' split values exactly, so equality of bits is exact.
using LineIndex = std::unordered_map<uint64_t, std::vector<float>>;

void addToLine(LineIndex& lines, uint32_t patch, float line, float along) {
  lines[lineKey(patch, line)].push_back(along);
}

// Coordinates strictly between lo and hi on the given line, ascending.
void between(const LineIndex& lines, uint32_t patch, float line, float lo, float hi,
             std::vector<float>& out) {
  out.clear();
  auto it = lines.find(lineKey(patch, line));
  if (it == lines.end()) return;
  const auto& values = it->second;
  auto first = std::upper_bound(values.begin(), values.end(), lo);
  auto last = std::lower_bound(values.begin(), values.end(), hi);
  if (first < last) out.assign(first, last);
}

}  // namespace

ParamMesh triangulateLeaves(const std::vector<QuadLeaf>& leaves) {
  LineIndex alongU;  // key: v = const, values: u
  LineIndex alongV;  // key: u = const, values: v
  for (const QuadLeaf& leaf : leaves) {
    const gpu::vec4& r = leaf.rect;
    for (float v : {r.y, r.w})
      for (float u : {r.x, r.z}) {
        addToLine(alongU, leaf.patchIndex, v, u);
        addToLine(alongV, leaf.patchIndex, u, v);
      }
  }
  for (LineIndex* lines : {&alongU, &alongV})
    for (auto& [key, values] : *lines) {
      std::sort(values.begin(), values.end());
      values.erase(std::unique(values.begin(), values.end()), values.end());
    }

  ParamMesh mesh;
  ParamMeshBuilder builder(mesh);
  std::vector<uint32_t> ring;
  std::vector<float> extra;
  for (const QuadLeaf& leaf : leaves) {
    const uint32_t p = leaf.patchIndex;
    const gpu::vec4& r = leaf.rect;
    ring.clear();
    // Counter-clockwise: bottom (v0, u rising), right (u1, v rising), top (v1, u falling),
    // left (u0, v falling); each edge contributes its start corner and interior vertices.
    ring.push_back(builder.vertex(p, r.x, r.y));
    between(alongU, p, r.y, r.x, r.z, extra);
    for (float u : extra) ring.push_back(builder.vertex(p, u, r.y));
    ring.push_back(builder.vertex(p, r.z, r.y));
    between(alongV, p, r.z, r.y, r.w, extra);
    for (float v : extra) ring.push_back(builder.vertex(p, r.z, v));
    ring.push_back(builder.vertex(p, r.z, r.w));
    between(alongU, p, r.w, r.x, r.z, extra);
    for (auto it = extra.rbegin(); it != extra.rend(); ++it) ring.push_back(builder.vertex(p, *it, r.w));
    ring.push_back(builder.vertex(p, r.x, r.w));
    between(alongV, p, r.x, r.y, r.w, extra);
    for (auto it = extra.rbegin(); it != extra.rend(); ++it) ring.push_back(builder.vertex(p, r.x, *it));

    if (ring.size() == 4) {
      mesh.indices.insert(mesh.indices.end(), {ring[0], ring[1], ring[2], ring[0], ring[2], ring[3]});
      continue;
    }
    float us = std::clamp(leaf.split.x, r.x, r.z), vs = std::clamp(leaf.split.y, r.y, r.w);
    if (!(us > r.x && us < r.z && vs > r.y && vs < r.w)) {
      us = 0.5f * (r.x + r.z);
      vs = 0.5f * (r.y + r.w);
    }
    uint32_t center = builder.vertex(p, us, vs);
    for (size_t k = 0; k < ring.size(); ++k)
      mesh.indices.insert(mesh.indices.end(), {center, ring[k], ring[(k + 1) % ring.size()]});
  }
  return mesh;
}

}  // namespace tessera
