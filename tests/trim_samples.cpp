#include "trim_samples.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace tessera::test {

std::vector<glm::dvec2> circleLoop(glm::dvec2 centre, double radius, int count, bool clockwise) {
  std::vector<glm::dvec2> loop;
  for (int k = 0; k < count; ++k) {
    const double angle = (clockwise ? -2.0 : 2.0) * M_PI * k / count;
    loop.push_back(centre + radius * glm::dvec2(std::cos(angle), std::sin(angle)));
  }
  return loop;
}

bool insideLoops(const std::vector<std::vector<glm::dvec2>>& loops, glm::dvec2 p) {
  bool inside = false;
  for (const auto& loop : loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
        inside = !inside;
    }
  return inside;
}

TrimSet trimSampleSet() {
  std::vector<std::vector<std::vector<glm::dvec2>>> faces;
  std::vector<TrimPieceRect> pieces;
  // 0: the unit square with a hole of radius 0.3 (200 segments), as 2 × 2 pieces.
  faces.push_back({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, circleLoop({0.5, 0.5}, 0.3, 200, true)});
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) pieces.push_back({0, {0.5 * i, 0.5 * j, 0.5 * i + 0.5, 0.5 * j + 0.5}});
  // 1: a five-pointed star in [1, 3] × [2, 4].
  std::vector<glm::dvec2> star;
  for (int k = 0; k < 10; ++k) {
    const double angle = M_PI / 2 + M_PI * k / 5, r = k % 2 ? 0.38 : 0.95;
    star.push_back({2 + r * std::cos(angle), 3 + r * std::sin(angle)});
  }
  faces.push_back({star});
  pieces.push_back({1, {1, 2, 3, 4}});
  // 2: slivers 10⁻⁴ and 10⁻⁶ wide, one tilted.
  faces.push_back({{{0.1, 0.3}, {0.9, 0.3}, {0.9, 0.3001}, {0.1, 0.3001}},
                   {{0.1, 0.6}, {0.9, 0.7}, {0.9, 0.700001}, {0.1, 0.600001}}});
  pieces.push_back({2, {0, 0, 1, 1}});
  // 3: a square whose sides lie on dyadic node sides (u, v = 1/4, 3/4), and a diagonal
  // triangle through dyadic corners.
  faces.push_back({{{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}},
                   {{0.0625, 0.0625}, {0.1875, 0.0625}, {0.0625, 0.1875}}});
  pieces.push_back({3, {0, 0, 1, 1}});
  pieces.push_back({3, {0, 0, 0.5, 0.5}});
  // 4: no loops (all inside).
  faces.push_back({});
  pieces.push_back({4, {0, 0, 1, 1}});
  // 5: a disc far from the origin (the margin grows with the coordinates).
  faces.push_back({circleLoop({1005.0, -45.0}, 3.0, 500, false)});
  pieces.push_back({5, {1000, -50, 1005, -40}});
  pieces.push_back({5, {1005, -50, 1010, -40}});
  return packTrimSet(faces, pieces);
}

NearSideSamples nearSideTrimSamples(uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::vector<std::vector<glm::dvec2>>> faces;
  std::vector<TrimPieceRect> pieces;
  std::vector<gpu::TrimQuery> queries;
  for (uint32_t k = 0; k < count; ++k) {
    const glm::dvec2 origin(std::ldexp(unit(rng), int(rng() % 24) - 4),
                            -std::ldexp(unit(rng), int(rng() % 24) - 4));
    const double size = std::ldexp(1.0 + unit(rng), int(rng() % 8) - 4);
    const glm::dvec4 rect(origin.x, origin.y, origin.x + size, origin.y + 1.5 * size);
    const double scale = std::max({std::abs(rect.x), std::abs(rect.y), std::abs(rect.z), std::abs(rect.w)});
    const double margin = std::ldexp(scale, -18);
    const uint32_t level = rng() % 8, cells = 1u << level;
    const float i = float(rng() % cells), j = float(rng() % cells), cell = 1.0f / float(cells);
    const gpu::vec4 node(i * cell, j * cell, (i + 1) * cell, (j + 1) * cell);
    // The node's side in face uv (double), the segment along it at distance d, slope ±s.
    const double u0 = rect.x + double(node.x) * size, u1 = rect.x + double(node.z) * size;
    const double v0 = rect.y + double(node.y) * 1.5 * size, v1 = rect.y + double(node.w) * 1.5 * size;
    const double d = (4.0 * unit(rng) - 2.0) * margin, slope = (unit(rng) - 0.5) * 1e-5;
    const double along = unit(rng) < 0.5 ? 0.0 : 0.25 * (u1 - u0);
    glm::dvec2 a, b;
    switch (rng() % 4) {
      case 0: a = {u0 + along, v0 - d}; b = {u1, v0 - d + slope * (u1 - u0)}; break;        // below
      case 1: a = {u0 + along, v1 + d}; b = {u1, v1 + d + slope * (u1 - u0)}; break;        // above
      case 2: a = {u0 - d, v0}; b = {u0 - d + slope * (v1 - v0), v1 - along}; break;        // left
      default: a = {u1 + d, v0}; b = {u1 + d + slope * (v1 - v0), v1 - along}; break;       // right
    }
    faces.push_back({{a, b}});
    pieces.push_back({k, rect});
    queries.push_back({node, k, 0u, 0u, 0u});
  }
  return {packTrimSet(faces, pieces), queries};
}

std::vector<gpu::TrimQuery> trimSampleQueries(const TrimSet& set, size_t perPiece, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<gpu::TrimQuery> queries;
  for (uint32_t p = 0; p < set.pieces.size(); ++p)
    for (size_t k = 0; k < perPiece; ++k) {
      gpu::vec4 rect;
      if (k % 2 == 0) {
        const int level = int(rng() % 13);
        const uint32_t cells = 1u << level;
        const float i = float(rng() % cells), j = float(rng() % cells), size = 1.0f / float(cells);
        rect = gpu::vec4(i * size, j * size, (i + 1) * size, (j + 1) * size);
      } else {
        const float a = unit(rng), b = unit(rng), c = unit(rng), d = unit(rng);
        const float scale = std::ldexp(1.0f, -int(rng() % 10));  // narrow ones too
        rect = gpu::vec4(std::min(a, a + (b - a) * scale), std::min(c, c + (d - c) * scale),
                         std::max(a, a + (b - a) * scale), std::max(c, c + (d - c) * scale));
      }
      queries.push_back({rect, p, 0u, 0u, 0u});
    }
  return queries;
}

}  // namespace tessera::test
