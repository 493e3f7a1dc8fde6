#include "loop/bvh.h"

#include <algorithm>
#include <stdexcept>

namespace tessera {
namespace {

// Segment p→q against triangle t: Möller–Trumbore with the parameter limited to [0, 1].
bool segmentHitsTriangle(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3* t) {
  const glm::dvec3 d = q - p, e1 = t[1] - t[0], e2 = t[2] - t[0];
  const glm::dvec3 h = glm::cross(d, e2);
  const double det = glm::dot(e1, h);
  if (std::abs(det) < 1e-300) return false;
  const double inv = 1.0 / det;
  const glm::dvec3 s = p - t[0];
  const double u = inv * glm::dot(s, h);
  if (u < 0.0 || u > 1.0) return false;
  const glm::dvec3 qv = glm::cross(s, e1);
  const double v = inv * glm::dot(d, qv);
  if (v < 0.0 || u + v > 1.0) return false;
  const double along = inv * glm::dot(e2, qv);
  return along >= 0.0 && along <= 1.0;
}

// Ray p + s·d, s > 0, against triangle t (for the inside test).
bool rayHitsTriangle(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3* t) {
  return segmentHitsTriangle(p, p + d, t);
}

}  // namespace

glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

bool trianglesIntersect(const glm::dvec3* a, const glm::dvec3* b) {
  for (int i = 0; i < 3; ++i) {
    if (segmentHitsTriangle(a[i], a[(i + 1) % 3], b)) return true;
    if (segmentHitsTriangle(b[i], b[(i + 1) % 3], a)) return true;
  }
  return false;
}

TriangleBvh::TriangleBvh(std::vector<glm::dvec3> positions, std::vector<uint32_t> triangles)
    : positions_(std::move(positions)), triangles_(std::move(triangles)) {
  if (triangles_.empty() || triangles_.size() % 3)
    throw std::invalid_argument("TriangleBvh: " + std::to_string(triangles_.size()) +
                                " indices do not make a non-empty triangle list");
  for (uint32_t i : triangles_)
    if (i >= positions_.size())
      throw std::invalid_argument("TriangleBvh: index " + std::to_string(i) + " of " +
                                  std::to_string(positions_.size()) + " positions");
  const uint32_t n = uint32_t(triangleCount());
  order_.resize(n);
  std::vector<glm::dvec3> centroids(n);
  for (uint32_t t = 0; t < n; ++t) {
    order_[t] = t;
    glm::dvec3 c[3];
    corners(t, c);
    centroids[t] = (c[0] + c[1] + c[2]) / 3.0;
  }
  nodes_.reserve(2 * n / 4 + 2);
  build(0, n, centroids);
}

const glm::dvec3* TriangleBvh::corners(uint32_t t, glm::dvec3 out[3]) const {
  for (int i = 0; i < 3; ++i) out[i] = positions_[triangles_[3 * t + i]];
  return out;
}

uint32_t TriangleBvh::build(uint32_t first, uint32_t count, std::vector<glm::dvec3>& centroids) {
  const uint32_t index = uint32_t(nodes_.size());
  nodes_.emplace_back();
  Box box, centres;
  for (uint32_t i = first; i < first + count; ++i) {
    glm::dvec3 c[3];
    corners(order_[i], c);
    for (const auto& p : c) box.add(p);
    centres.add(centroids[order_[i]]);
  }
  nodes_[index].box = box;
  if (count <= 4) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  const glm::dvec3 size = centres.hi - centres.lo;
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  const uint32_t half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count, [&](uint32_t a, uint32_t b) {
                     return centroids[a][axis] < centroids[b][axis];
                   });
  const uint32_t left = build(first, half, centroids);
  const uint32_t right = build(first + half, count - half, centroids);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

MeshClosestPoint TriangleBvh::closest(const glm::dvec3& p) const {
  MeshClosestPoint best;
  uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.box.distance2(p) >= best.distance2) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        glm::dvec3 c[3];
        corners(order_[i], c);
        const glm::dvec3 q = closestPointOnTriangle(p, c[0], c[1], c[2]);
        const double d2 = glm::dot(q - p, q - p);
        if (d2 < best.distance2) best = {q, order_[i], d2};
      }
      continue;
    }
    // Visit the nearer child first (pushed last).
    const double dl = nodes_[node.left].box.distance2(p), dr = nodes_[node.right].box.distance2(p);
    stack[top++] = dl < dr ? node.right : node.left;
    stack[top++] = dl < dr ? node.left : node.right;
  }
  return best;
}

void TriangleBvh::forEachIntersecting(const TriangleBvh& other,
                                      const std::function<void(uint32_t, uint32_t)>& visit) const {
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 0u}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const Node &a = nodes_[i], &b = other.nodes_[j];
    if (!a.box.overlaps(b.box)) continue;
    if (a.count > 0 && b.count > 0) {
      for (uint32_t x = a.first; x < a.first + a.count; ++x)
        for (uint32_t y = b.first; y < b.first + b.count; ++y) {
          glm::dvec3 ta[3], tb[3];
          if (trianglesIntersect(corners(order_[x], ta), other.corners(other.order_[y], tb)))
            visit(order_[x], other.order_[y]);
        }
    } else if (b.count > 0 || (a.count == 0 && glm::length(a.box.hi - a.box.lo) >=
                                                   glm::length(b.box.hi - b.box.lo))) {
      stack.push_back({a.left, j});  // descend the larger (or the only inner) node
      stack.push_back({a.right, j});
    } else {
      stack.push_back({i, b.left});
      stack.push_back({i, b.right});
    }
  }
}

bool TriangleBvh::inside(const glm::dvec3& p) const {
  // A direction unlikely to graze an edge or vertex of a modelled mesh, long enough to leave it.
  const glm::dvec3 far = glm::dvec3(0.5773, 0.6128, 0.5397) *
                         (2.0 * glm::length(bounds().hi - bounds().lo) + glm::length(p) + 1.0);
  Box ray;
  ray.add(p);
  ray.add(p + far);
  int crossings = 0;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (!node.box.overlaps(ray)) continue;
    if (node.count == 0) {
      stack.push_back(node.left);
      stack.push_back(node.right);
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      glm::dvec3 c[3];
      crossings += rayHitsTriangle(p, far, corners(order_[i], c));
    }
  }
  return crossings % 2 == 1;
}

void forEachIntersectingBruteForce(const TriangleBvh& a, const TriangleBvh& b,
                                   const std::function<void(uint32_t, uint32_t)>& visit) {
  for (uint32_t x = 0; x < a.triangleCount(); ++x)
    for (uint32_t y = 0; y < b.triangleCount(); ++y) {
      glm::dvec3 ta[3], tb[3];
      if (trianglesIntersect(a.corners(x, ta), b.corners(y, tb))) visit(x, y);
    }
}

}  // namespace tessera
