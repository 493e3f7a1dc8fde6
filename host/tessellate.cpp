#include "tessellate.h"

#include <chrono>

#include "triangulate.h"

namespace tessera {
namespace {

double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

Backend makeCpuBackend() {
  return {"cpu", makeParallelMirrorClassifier(), makeMirrorEvaluator()};
}

Backend makeVulkanBackend(vk::Context& context) {
  auto classifier = makeVulkanClassifier(context);
  auto evaluator = makeVulkanEvaluator(context);
  return {"vulkan", std::move(classifier), std::move(evaluator)};
}

Tessellation tessellate(const std::vector<BezierPatch>& patches, const QuadtreeOptions& options,
                        Backend& backend) {
  auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < patches.size(); ++i)
    if (patches[i].degreeU != 3 || patches[i].degreeV != 3)
      throw std::invalid_argument("patch " + std::to_string(i) + " has degree " +
                                  std::to_string(patches[i].degreeU) + "x" +
                                  std::to_string(patches[i].degreeV) +
                                  ": adaptive tessellation takes bicubic patches");
  std::vector<gpu::BicubicPatch> gpuPatches = toGpuPatches(patches);

  Tessellation result;
  auto t = std::chrono::steady_clock::now();
  result.tree = buildQuadtree(gpuPatches, options, *backend.classifier);
  result.stats.treeMs = msSince(t);

  t = std::chrono::steady_clock::now();
  ParamMesh param = triangulateLeaves(result.tree.leaves);
  result.stats.triangulateMs = msSince(t);

  t = std::chrono::steady_clock::now();
  std::vector<gpu::EvalQuery> queries(param.vertices.size());
  for (size_t i = 0; i < queries.size(); ++i)
    queries[i] = {param.vertices[i].patchIndex, param.vertices[i].u, param.vertices[i].v, 0};
  std::vector<gpu::EvalSample> samples = backend.evaluator->evaluate(gpuPatches, queries);
  result.stats.evaluateMs = msSince(t);

  TriangleMesh& mesh = result.mesh;
  mesh.positions.resize(samples.size());
  mesh.normals.resize(samples.size());
  mesh.uvs.resize(samples.size());
  mesh.patchIds.resize(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    mesh.positions[i] = glm::vec3(samples[i].position);
    mesh.normals[i] = glm::vec3(samples[i].normalKappa);
    mesh.uvs[i] = glm::vec2(param.vertices[i].u, param.vertices[i].v);
    mesh.patchIds[i] = param.vertices[i].patchIndex;
  }
  // A triangle with two corners at one point (a collapsed patch edge) has no area: drop it.
  mesh.indices.reserve(param.indices.size());
  for (size_t k = 0; k < param.indices.size(); k += 3) {
    uint32_t a = param.indices[k], b = param.indices[k + 1], c = param.indices[k + 2];
    const glm::vec3 &pa = mesh.positions[a], &pb = mesh.positions[b], &pc = mesh.positions[c];
    if (pa == pb || pb == pc || pc == pa) {
      ++result.stats.degenerateTrianglesDropped;
      continue;
    }
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  }

  TessellationStats& s = result.stats;
  s.patches = patches.size();
  s.leaves = result.tree.leaves.size();
  s.depth = result.tree.depth;
  s.levels = result.tree.levels;
  s.triangles = mesh.triangleCount();
  s.vertices = mesh.vertexCount();
  s.totalMs = msSince(start);
  return result;
}

}  // namespace tessera
