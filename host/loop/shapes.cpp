#include "loop/shapes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace tessera {
namespace {

// splitmix64: a portable, seedable stream (std:: distributions differ between libraries).
struct Random {
  uint64_t state;
  explicit Random(uint64_t seed) : state(seed * 0x9e3779b97f4a7c15ull + 1) {}
  uint64_t next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double symmetric() { return 2.0 * uniform() - 1.0; }           // [-1, 1)
  glm::dvec3 vector() { return {symmetric(), symmetric(), symmetric()}; }
};

void addTriangle(LoopShape& s, uint32_t a, uint32_t b, uint32_t c) {
  s.topology.triangles.insert(s.topology.triangles.end(), {a, b, c});
}

uint64_t edgeKey(uint32_t a, uint32_t b) {
  return (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

// Flips up to `flips` random interior edges whose ends keep valence ≥ 3 and whose new edge
// does not exist yet: irregular valences on a closed mesh, still a 2-manifold.
void flipEdges(LoopShape& s, int flips, Random& random) {
  auto& tris = s.topology.triangles;
  std::unordered_map<uint64_t, std::array<uint32_t, 2>> edgeFaces;
  std::vector<int> valence(s.positions.size(), 0);
  for (uint32_t f = 0; f < tris.size() / 3; ++f)
    for (int i = 0; i < 3; ++i) {
      auto [it, inserted] = edgeFaces.try_emplace(edgeKey(tris[3 * f + i], tris[3 * f + (i + 1) % 3]),
                                                  std::array<uint32_t, 2>{f, kLoopNone});
      if (!inserted) it->second[1] = f;
      else ++valence[tris[3 * f + i]], ++valence[tris[3 * f + (i + 1) % 3]];
    }
  const uint32_t faceCount = uint32_t(tris.size() / 3);
  for (int attempt = 0, done = 0; done < flips && attempt < 20 * flips; ++attempt) {
    const uint32_t f1 = uint32_t(random.next() % faceCount);
    const int i = int(random.next() % 3);
    uint32_t a = tris[3 * f1 + i], b = tris[3 * f1 + (i + 1) % 3], c = tris[3 * f1 + (i + 2) % 3];
    auto it = edgeFaces.find(edgeKey(a, b));
    const uint32_t f2 = it->second[0] == f1 ? it->second[1] : it->second[0];
    if (f2 == kLoopNone) continue;
    uint32_t d = 0;
    for (int k = 0; k < 3; ++k)
      if (tris[3 * f2 + k] != a && tris[3 * f2 + k] != b) d = tris[3 * f2 + k];
    if (valence[a] <= 3 || valence[b] <= 3 || valence[c] >= 9 || valence[d] >= 9) continue;
    if (edgeFaces.count(edgeKey(c, d))) continue;
    // f1 = (a, b, c), f2 = (b, a, d)  →  f1 = (c, a, d), f2 = (d, b, c).
    edgeFaces.erase(it);
    edgeFaces[edgeKey(c, d)] = {f1, f2};
    for (auto& face : edgeFaces[edgeKey(a, d)]) face = face == f2 ? f1 : face;
    for (auto& face : edgeFaces[edgeKey(b, c)]) face = face == f1 ? f2 : face;
    const uint32_t one[3] = {c, a, d}, two[3] = {d, b, c};
    std::copy(one, one + 3, &tris[3 * f1]);
    std::copy(two, two + 3, &tris[3 * f2]);
    --valence[a], --valence[b], ++valence[c], ++valence[d];
    ++done;
  }
}

}  // namespace

double signedVolume(const LoopShape& s) {
  double volume = 0.0;
  const auto& t = s.topology.triangles;
  for (size_t f = 0; f < t.size(); f += 3)
    volume += glm::dot(s.positions[t[f]], glm::cross(s.positions[t[f + 1]], s.positions[t[f + 2]]));
  return volume / 6.0;
}

LoopShape loopIcosphere(int frequency) {
  LoopShape s;
  s.name = "icosphere" + std::to_string(frequency);
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  const glm::dvec3 corners[12] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                  {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                  {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  const uint32_t faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  // A point a·A + b·B + c·C (a + b + c = n) of a face is keyed by its nonzero (corner, weight)
  // pairs, sorted, so that points on shared edges and corners are made once.
  std::map<std::vector<uint32_t>, uint32_t> index;
  const uint32_t n = uint32_t(frequency);
  auto point = [&](const uint32_t* face, uint32_t a, uint32_t b, uint32_t c) {
    std::vector<std::pair<uint32_t, uint32_t>> parts;
    const uint32_t weights[3] = {a, b, c};
    for (int k = 0; k < 3; ++k)
      if (weights[k]) parts.push_back({face[k], weights[k]});
    std::sort(parts.begin(), parts.end());
    std::vector<uint32_t> key;
    for (auto [corner, weight] : parts) key.insert(key.end(), {corner, weight});
    auto [it, inserted] = index.try_emplace(key, uint32_t(s.positions.size()));
    if (inserted) {
      glm::dvec3 p(0.0);
      for (auto [corner, weight] : parts) p += double(weight) * corners[corner];
      s.positions.push_back(glm::normalize(p));
    }
    return it->second;
  };
  for (const auto& face : faces)
    for (uint32_t i = 0; i < n; ++i)
      for (uint32_t j = 0; i + j < n; ++j) {
        // Sub-triangles of the face's grid, (i, j) counting steps towards corners 1 and 2.
        const uint32_t p0 = point(face, n - i - j, i, j), p1 = point(face, n - i - j - 1, i + 1, j),
                       p2 = point(face, n - i - j - 1, i, j + 1);
        addTriangle(s, p0, p1, p2);
        if (i + j + 2 <= n) addTriangle(s, p1, point(face, n - i - j - 2, i + 1, j + 1), p2);
      }
  s.topology.vertexCount = uint32_t(s.positions.size());
  if (signedVolume(s) < 0)
    for (size_t f = 0; f < s.topology.triangles.size(); f += 3)
      std::swap(s.topology.triangles[f + 1], s.topology.triangles[f + 2]);
  return s;
}

LoopShape loopTetrahedron() {
  LoopShape s;
  s.name = "tetrahedron";
  s.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  s.topology.vertexCount = 4;
  s.topology.triangles = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2};
  if (signedVolume(s) < 0) std::reverse(s.topology.triangles.begin(), s.topology.triangles.end());
  return s;
}

LoopShape loopTorus(int around, int across, double noise, uint32_t seed) {
  LoopShape s;
  s.name = "torus" + std::to_string(around) + "x" + std::to_string(across);
  Random random(seed);
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const double u = 2.0 * M_PI * i / around, v = 2.0 * M_PI * j / across;
      const double r = 1.0 + 0.35 * std::cos(v);
      s.positions.push_back(glm::dvec3(r * std::cos(u), r * std::sin(u), 0.35 * std::sin(v)) +
                            noise * random.vector());
    }
  auto id = [&](int i, int j) { return uint32_t((i % around) * across + (j % across)); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      addTriangle(s, id(i, j), id(i + 1, j), id(i + 1, j + 1));
      addTriangle(s, id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  s.topology.vertexCount = uint32_t(s.positions.size());
  if (signedVolume(s) < 0)
    for (size_t f = 0; f < s.topology.triangles.size(); f += 3)
      std::swap(s.topology.triangles[f + 1], s.topology.triangles[f + 2]);
  return s;
}

LoopShape loopBunny(int frequency, uint32_t seed) {
  LoopShape s = loopIcosphere(frequency);
  s.name = "bunny" + std::to_string(frequency);
  Random random(seed);
  flipEdges(s, int(s.topology.triangles.size() / 3 / 6), random);
  auto bump = [](const glm::dvec3& d, glm::dvec3 centre, double width, double height) {
    centre = glm::normalize(centre);
    const double distance2 = glm::dot(d - centre, d - centre);
    return height * std::exp(-distance2 / (width * width));
  };
  for (auto& p : s.positions) {
    const glm::dvec3 d = p;
    const double radius = 1.0 + bump(d, {0.6, 0.0, 0.8}, 0.45, 0.45) +
                          bump(d, {0.45, 0.25, 1.0}, 0.18, 0.9) +
                          bump(d, {0.45, -0.25, 1.0}, 0.18, 0.9) + 0.02 * random.symmetric();
    p = radius * d * glm::dvec3(1.3, 0.9, 0.8);
  }
  return s;
}

LoopShape loopGrid(int nx, int ny, uint32_t seed) {
  LoopShape s;
  s.name = "grid" + std::to_string(nx) + "x" + std::to_string(ny);
  Random random(seed);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = double(i) / (nx - 1), y = double(j) / (ny - 1);
      s.positions.push_back({x, y, 0.1 * std::sin(3 * x) * std::cos(2 * y) + 0.01 * random.symmetric()});
    }
  auto id = [&](int i, int j) { return uint32_t(j * nx + i); };
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      addTriangle(s, id(i, j), id(i + 1, j), id(i + 1, j + 1));
      addTriangle(s, id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  s.topology.vertexCount = uint32_t(s.positions.size());
  return s;
}

LoopShape loopCreasedCube() {
  LoopShape s;
  s.name = "creased cube";
  for (int k = 0; k < 8; ++k) s.positions.push_back({double(k & 1), double((k >> 1) & 1), double(k >> 2)});
  // Each side as a quad (counter-clockwise from outside), split along its first diagonal.
  const uint32_t sides[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : sides) {
    addTriangle(s, q[0], q[1], q[2]);
    addTriangle(s, q[0], q[2], q[3]);
    for (int i = 0; i < 4; ++i) {
      const uint32_t a = q[i], b = q[(i + 1) % 4];
      if (a < b) s.topology.creases.push_back({a, b});
    }
  }
  // Each cube edge was listed by both of its sides; keep one.
  std::sort(s.topology.creases.begin(), s.topology.creases.end());
  s.topology.creases.erase(std::unique(s.topology.creases.begin(), s.topology.creases.end()),
                           s.topology.creases.end());
  s.topology.vertexCount = 8;
  return s;
}

LoopShape loopCreasedSphere(int frequency, int length) {
  LoopShape s = loopIcosphere(frequency);
  s.name = "creased sphere" + std::to_string(frequency);
  LoopTopology t = buildLoopTopology(s.topology);
  // A deterministic path of distinct vertices: from vertex 0, always to the unvisited
  // neighbour furthest along +x.
  std::vector<uint8_t> visited(t.vertexCount, 0);
  uint32_t v = 0;
  visited[v] = 1;
  for (int step = 0; step < length; ++step) {
    uint32_t best = kLoopNone;
    for (uint32_t k = 0; k < t.valence(v); ++k) {
      const uint32_t w = t.ring(v)[k];
      if (!visited[w] && (best == kLoopNone || s.positions[w].x > s.positions[best].x)) best = w;
    }
    if (best == kLoopNone) break;
    s.topology.creases.push_back({v, best});
    visited[best] = 1;
    v = best;
  }
  // A marked corner away from the crease.
  for (uint32_t w = t.vertexCount; w-- > 0;)
    if (!visited[w]) {
      s.topology.corners.push_back(w);
      break;
    }
  return s;
}

}  // namespace tessera
