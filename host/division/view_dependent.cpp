#include "division/view_dependent.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "geometry/homogeneous_net.h"
#include "quadtree/quadtree.h"
#include "mesh/triangulate.h"

namespace tessera {

Camera lookAtCamera(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                    double fovY, int width, int height, double nearDistance, double farDistance) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("camera: the viewport must be at least 1×1 pixels");
  if (!(fovY > 0.0 && fovY < 3.14) || !(nearDistance > 0.0 && farDistance > nearDistance))
    throw std::invalid_argument("camera: need 0 < fovY < π and 0 < near < far");
  glm::dmat4 projection =
      glm::perspectiveRH_ZO(fovY, double(width) / height, nearDistance, farDistance);
  projection[1][1] *= -1.0;  // Vulkan: y down
  Camera camera;
  camera.viewProjection = projection * glm::lookAtRH(eye, target, up);
  camera.width = width;
  camera.height = height;
  camera.nearW = nearDistance;
  return camera;
}

void screenSpacePoints(const glm::dvec4* world, size_t count, const Camera& camera,
                       glm::dvec4* screen, double snap) {
  double maxW = 0.0;
  for (size_t k = 0; k < count; ++k) {
    screen[k] = camera.viewProjection * world[k];
    maxW = std::max(maxW, std::abs(screen[k].w));
  }
  for (size_t k = 0; k < count; ++k) {
    glm::dvec4& h = screen[k];
    const double w = std::abs(h.w) <= snap * maxW ? 0.0 : h.w;
    h = glm::dvec4(0.5 * (h.x + w) * camera.width, 0.5 * (h.y + w) * camera.height, 0.0, w);
  }
}

RationalBezierPatch screenSpacePatch(const RationalBezierPatch& world, const Camera& camera,
                                     double snap) {
  RationalBezierPatch screen = world;
  screenSpacePoints(world.cpw.data(), world.cpw.size(), camera, screen.cpw.data(), snap);
  return screen;
}

ViewDivisions viewDivisions(const RationalBezierPatch& world, const Camera& camera,
                            const DivisionOptions& options) {
  validateDivisionInput(world, DivisionMethod::Split);
  const RationalBezierPatch screen = screenSpacePatch(world, camera);
  ViewDivisions result;
  const bool inFront = std::any_of(screen.cpw.begin(), screen.cpw.end(),
                                   [&](const glm::dvec4& h) { return h.w > camera.nearW; });
  if (!inFront) {
    result.divisions.status = DivisionStatus::Culled;
    result.divisions.nu = result.divisions.nv = 0;
    result.divisions.realU = result.divisions.realV = 0.0;
    return result;
  }
  DivisionOptions viewOptions = options;
  viewOptions.clip = {true, double(camera.width), double(camera.height), camera.nearW};
  result.divisions = patchDivisions(screen, viewOptions);
  if (result.divisions.status == DivisionStatus::Unbounded &&
      options.method != DivisionMethod::Subdivided) {
    viewOptions.method = DivisionMethod::Subdivided;
    result.divisions = patchDivisions(screen, viewOptions);
    result.eyePlaneFallback = true;
  }
  return result;
}

TriangleMesh uniformGridMesh(const std::vector<RationalBezierPatch>& patches,
                             const std::vector<Divisions>& counts) {
  if (patches.size() != counts.size())
    throw std::invalid_argument("uniformGridMesh: " + std::to_string(counts.size()) +
                                " counts for " + std::to_string(patches.size()) + " patches");
  // Rule A of the quad-tree (host/quadtree/frontier.cpp) makes each patch's N_u×N_v leaves; the leaf
  // triangulator makes them watertight across patches with different counts. It identifies
  // shared edges and corners by control points, so it gets each patch's projected net.
  QuadtreeOptions grid;
  grid.rule = SplitRule::UniformGrid;
  const std::unique_ptr<NodeClassifier> unused = makeReferenceClassifier();
  const PatchSet one(std::vector<gpu::BicubicPatch>(1));
  std::vector<QuadLeaf> leaves;
  std::vector<BezierPatch> proxies(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    proxies[p].degreeU = patches[p].degreeU;
    proxies[p].degreeV = patches[p].degreeV;
    for (const glm::dvec4& h : patches[p].cpw) {
      if (!(h.w > 0.0))
        throw std::invalid_argument("uniformGridMesh: patch " + std::to_string(p) +
                                    " has a world-space weight ≤ 0");
      proxies[p].cp.push_back(glm::dvec3(h) / h.w);
    }
    if (counts[p].nu <= 0 || counts[p].nv <= 0) continue;  // culled
    grid.gridU = counts[p].nu;
    grid.gridV = counts[p].nv;
    for (QuadLeaf leaf : buildQuadtree(one, grid, *unused).leaves) {
      leaf.patchIndex = static_cast<uint32_t>(p);
      leaves.push_back(leaf);
    }
  }
  const ParamMesh param = triangulateLeaves(leaves, proxies);
  TriangleMesh mesh;
  for (const ParamVertex& pv : param.vertices) {
    const glm::dvec4 h = evaluate(toNet(patches[pv.patchIndex]), pv.u, pv.v);
    mesh.positions.push_back(glm::vec3(glm::dvec3(h) / h.w));
    mesh.uvs.push_back(glm::vec2(pv.u, pv.v));
    mesh.patchIds.push_back(pv.patchIndex);
  }
  mesh.indices = param.indices;
  return mesh;
}

}  // namespace tessera
