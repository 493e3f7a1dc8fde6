// Bounding-volume hierarchy over a triangle mesh (double precision): closest points (fitting,
// Suzuki et al.), triangle pairs whose boxes overlap another hierarchy's (joining: the paper's
// interference test, which it did by brute force and named its bottleneck), and ray-parity
// inside tests. Median splits on the longest axis of the centroids, at most 4 triangles a leaf.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace tessera {

struct Box {
  glm::dvec3 lo{1e300}, hi{-1e300};
  void add(const glm::dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  void add(const Box& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
  bool overlaps(const Box& b) const {
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y &&
           lo.z <= b.hi.z && b.lo.z <= hi.z;
  }
  double distance2(const glm::dvec3& p) const {
    const glm::dvec3 d = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0));
    return glm::dot(d, d);
  }
};

// The nearest point of a triangle mesh (not geometry/closest_point.h's ClosestPoint on a
// patch: one name for two structs in one namespace breaks the one-definition rule).
struct MeshClosestPoint {
  glm::dvec3 point{0.0};
  uint32_t triangle = 0;
  double distance2 = 1e300;
};

// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection §5.1.5).
glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c);
// Whether two triangles intersect: an edge of one crosses the other (coplanar contact is not
// counted).
bool trianglesIntersect(const glm::dvec3* a, const glm::dvec3* b);

class TriangleBvh {
 public:
  TriangleBvh(std::vector<glm::dvec3> positions, std::vector<uint32_t> triangles);

  MeshClosestPoint closest(const glm::dvec3& p) const;
  // Calls visit(mine, theirs) for every pair of intersecting triangles (trianglesIntersect).
  void forEachIntersecting(const TriangleBvh& other,
                           const std::function<void(uint32_t, uint32_t)>& visit) const;
  // Whether p lies inside the closed mesh: the parity of crossings along a fixed ray.
  bool inside(const glm::dvec3& p) const;

  size_t triangleCount() const { return triangles_.size() / 3; }
  const glm::dvec3* corners(uint32_t t, glm::dvec3 out[3]) const;
  const Box& bounds() const { return nodes_[0].box; }

 private:
  struct Node {
    Box box;
    uint32_t first = 0, count = 0;  // leaf: order_[first .. first + count)
    uint32_t left = 0, right = 0;   // inner node when count == 0
  };
  uint32_t build(uint32_t first, uint32_t count, std::vector<glm::dvec3>& centroids);

  std::vector<glm::dvec3> positions_;
  std::vector<uint32_t> triangles_;
  std::vector<uint32_t> order_;
  std::vector<Node> nodes_;
};

// All intersecting triangle pairs by testing every pair (the paper's method; for the bench).
void forEachIntersectingBruteForce(const TriangleBvh& a, const TriangleBvh& b,
                                   const std::function<void(uint32_t, uint32_t)>& visit);

}  // namespace tessera
