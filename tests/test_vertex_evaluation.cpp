// PatchEvaluator::evaluateVertices, the evaluation meshes use (shaders/eval_vertices.comp.glsl
// and its fp32 mirror, lib/bicubic_eval.h's evalBicubicVertex; general sets' mirror,
// lib/general_vertex.h): the position and normal bits of evaluate()'s samples, so switching the
// mesh path to it changes no mesh byte; the GPU equal to its mirror bit for bit on lavapipe; and
// tessellate() taking it, not evaluate().
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <utility>

#include "eval/evaluator.h"
#include "general_samples.h"
#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "mesh/tessellate.h"
#include "patch_samples.h"
#include "quadtree/tolerance.h"

using namespace tessera;

namespace {

bool sameBits(const gpu::vec4& a, const gpu::vec4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Vertices whose position or normal differs in any bit from the samples'.
size_t differingVertices(const std::vector<gpu::VertexSample>& vertices,
                         const std::vector<gpu::EvalSample>& samples) {
  REQUIRE(vertices.size() == samples.size());
  size_t differing = 0;
  for (size_t i = 0; i < vertices.size(); ++i) {
    const gpu::vec4 normal(glm::vec3(samples[i].normalKappa), 0.0f);
    differing += !sameBits(vertices[i].position, samples[i].position) ||
                 !sameBits(vertices[i].normal, normal);
  }
  return differing;
}

// Samples where Pu × Pv vanishes, so the normal comes from the degenerate rule (the vertex
// variant's second branch); |Pu × Pv| ≤ 1e-12 is far below any of these sets' ε·L².
size_t degenerateSamples(const std::vector<gpu::EvalSample>& samples) {
  size_t count = 0;
  for (const gpu::EvalSample& s : samples)
    count += glm::length(glm::cross(glm::vec3(s.du), glm::vec3(s.dv))) <= 1e-12f;
  return count;
}

struct PatchCase {
  const char* name;
  std::vector<gpu::BicubicPatch> patches;
};

std::vector<PatchCase> patchCases() {
  return {{"random patches", toGpuPatches(test::randomBicubicPatches(200, 42))},
          {"collapsed-edge patches", toGpuPatches(test::collapsedEdgePatches())}};
}

// Counts which evaluation the mesh path asks for, and evaluates with the mirror.
class CountingEvaluator final : public PatchEvaluator {
 public:
  std::string name() const override { return "counting"; }
  std::vector<gpu::EvalSample> evaluate(const PatchSet& patches,
                                        const std::vector<gpu::EvalQuery>& queries) override {
    ++sampleCalls;
    return mirror_->evaluate(patches, queries);
  }
  std::vector<gpu::VertexSample> evaluateVertices(
      const PatchSet& patches, const std::vector<gpu::EvalQuery>& queries) override {
    ++vertexCalls;
    return mirror_->evaluateVertices(patches, queries);
  }
  void prepare(const PatchSet&) override { ++samplePrepares; }
  void prepareVertices(const PatchSet&) override { ++vertexPrepares; }

  int sampleCalls = 0, vertexCalls = 0, samplePrepares = 0, vertexPrepares = 0;

 private:
  std::unique_ptr<PatchEvaluator> mirror_ = makeMirrorEvaluator();
};

}  // namespace

TEST_CASE("fp32 mirror: evaluateVertices gives evaluate's positions and normals bit for bit",
          "[eval][mirror]") {
  for (const PatchCase& c : patchCases())
    // Shuffled too: the mirror keeps a patch's tolerance while its queries follow each other.
    for (const bool shuffled : {false, true}) {
      // 13² + 40 queries a patch, edges and corners included: over 8,192 for the random set, so
      // the batch takes the mirror's parallel path too.
      auto queries = test::gridQueries(c.patches.size(), 13, 40, 7);
      if (shuffled) std::shuffle(queries.begin(), queries.end(), std::mt19937(3));
      auto mirror = makeMirrorEvaluator();
      const auto samples = mirror->evaluate(c.patches, queries);
      const auto vertices = mirror->evaluateVertices(c.patches, queries);
      INFO(c.name << (shuffled ? ", shuffled" : "") << ": " << queries.size() << " queries, "
                  << degenerateSamples(samples) << " degenerate");
      CHECK(differingVertices(vertices, samples) == 0);
      for (const gpu::VertexSample& v : vertices) REQUIRE((v.position.w == 1 && v.normal.w == 0));
    }
  // The collapsed edges do reach the degenerate rule, the branch that evaluates everything.
  const PatchCase collapsed = patchCases()[1];
  CHECK(degenerateSamples(makeMirrorEvaluator()->evaluate(
            collapsed.patches, test::gridQueries(collapsed.patches.size(), 13, 40, 7))) > 0);
}

TEST_CASE("fp32 mirror: general sets' evaluateVertices gives evaluate's positions and normals",
          "[eval][mirror][general]") {
  // The mirror's vertex path for general patches (shaders/lib/general_vertex.h): first
  // partials only, the length scale once per patch, the common degree pairs compiled apart;
  // every such pair, polynomial and rational, others of runtime degrees up to 7, weights that
  // vanish inside, and a sphere whose collapsed poles take the degenerate rule.
  struct GeneralCase {
    std::string name;
    std::vector<BezierPatch> patches;
  };
  std::vector<GeneralCase> cases;
  uint32_t seed = 60;
  for (int n = 1; n <= 3; ++n)
    for (int m = 1; m <= 3; ++m)
      cases.push_back({"degree " + std::to_string(n) + "x" + std::to_string(m),
                       test::randomGeneralPatches(8, n, m, false, false, ++seed)});
  for (const auto& [n, m] : {std::pair<int, int>{2, 1}, {1, 2}, {2, 2}, {3, 3}})
    cases.push_back({"rational " + std::to_string(n) + "x" + std::to_string(m),
                     test::randomGeneralPatches(8, n, m, true, false, ++seed)});
  cases.push_back({"degree 7x5", test::randomGeneralPatches(8, 7, 5, false, false, ++seed)});
  cases.push_back(
      {"rational 4x3, inner w=0", test::randomGeneralPatches(8, 4, 3, true, true, ++seed)});
  cases.push_back({"rational sphere", test::rationalSphere(2.0)});
  size_t degenerate = 0;
  for (const GeneralCase& c : cases) {
    // A general set even for the bicubic pair (toPatchSet would take the bicubic path).
    const PatchSet set = toGeneralPatchSet(c.patches);
    // Shuffled too: the per-patch tolerance must follow the query's patch, not the last one.
    for (const bool shuffled : {false, true}) {
      auto queries = test::gridQueries(c.patches.size(), 13, 40, 8);
      if (shuffled) std::shuffle(queries.begin(), queries.end(), std::mt19937(9));
      auto mirror = makeMirrorEvaluator();
      const auto samples = mirror->evaluate(set, queries);
      const auto vertices = mirror->evaluateVertices(set, queries);
      INFO(c.name << (shuffled ? ", shuffled" : "") << ": " << queries.size() << " queries");
      CHECK(differingVertices(vertices, samples) == 0);
      if (!shuffled) degenerate += degenerateSamples(samples);
    }
  }
  CHECK(degenerate > 0);  // the degenerate rule's branch was taken
}

namespace {

// The Vulkan evaluator's vertices against its mirror's (bit for bit where the device rounds as
// the mirror does, lavapipe) and against its own evaluate()'s samples; `queries` in patch
// order make the shader's runs (VertexEvalPush) full, cut at patch changes, and shuffled
// nearly every run is one query long. One evaluator for all cases: lavapipe compiles each
// pipeline at its first use.
void checkVertexShaderParity(vk::Context& context, PatchEvaluator& vulkan, const std::string& name,
                             const PatchSet& set, std::vector<gpu::EvalQuery> queries) {
  for (const bool shuffled : {false, true}) {
    if (shuffled) std::shuffle(queries.begin(), queries.end(), std::mt19937(5));
    const auto gpu = vulkan.evaluateVertices(set, queries);
    const auto gpuSamples = vulkan.evaluate(set, queries);
    const auto cpu = makeMirrorEvaluator()->evaluateVertices(set, queries);
    REQUIRE(gpu.size() == queries.size());
    size_t mirrorMismatches = 0;
    double maxPositionDiff = 0, maxNormalDiff = 0, maxCoordinate = 0;
    for (size_t i = 0; i < gpu.size(); ++i) {
      mirrorMismatches +=
          !sameBits(gpu[i].position, cpu[i].position) || !sameBits(gpu[i].normal, cpu[i].normal);
      for (int k = 0; k < 3; ++k) {
        maxCoordinate = std::max(maxCoordinate, double(std::fabs(gpu[i].position[k])));
        maxPositionDiff =
            std::max(maxPositionDiff, double(std::fabs(gpu[i].position[k] - cpu[i].position[k])));
        maxNormalDiff =
            std::max(maxNormalDiff, double(std::fabs(gpu[i].normal[k] - cpu[i].normal[k])));
      }
    }
    const size_t sampleMismatches = differingVertices(gpu, gpuSamples);
    // The samples read in place (the mesh path's useVertexSamples) are evaluateVertices' bytes.
    std::vector<gpu::VertexSample> inPlace;
    vulkan.useVertexSamples(set, std::vector<gpu::EvalQuery>(queries),
                            [&](const gpu::VertexSample* s) { inPlace.assign(s, s + gpu.size()); });
    REQUIRE(std::memcmp(inPlace.data(), gpu.data(), gpu.size() * sizeof gpu[0]) == 0);
    WARN(name << (shuffled ? ", shuffled," : "") << " on " << context.info().name << ": "
              << queries.size() << " vertices, " << mirrorMismatches
              << " differ from the mirror in any bit (max |Δp| " << maxPositionDiff
              << ", max |Δn| " << maxNormalDiff << "), " << sampleMismatches
              << " from evaluate()'s samples");
    if (test::exactMirrorArithmetic()) {
      REQUIRE(mirrorMismatches == 0);
      REQUIRE(sampleMismatches == 0);
    } else {
      REQUIRE(maxPositionDiff <= 1e-6 * std::max(1.0, maxCoordinate));
      REQUIRE(maxNormalDiff <= 3e-5);
    }
  }
}

}  // namespace

TEST_CASE("eval_vertices shader equals its fp32 mirror and eval.comp's positions and normals",
          "[gpu][parity]") {
  vk::Context& context = test::gpuContext();
  const auto vulkan = makeVulkanEvaluator(context);
  for (const PatchCase& c : patchCases())
    checkVertexShaderParity(context, *vulkan, c.name, c.patches,
                            test::gridQueries(c.patches.size(), 9, 64, 1234));
  test::requireValidationClean();
}

TEST_CASE("useVertexSamples without queries calls no evaluation and hands over no samples",
          "[eval]") {
  // A trimmed group whose every leaf is trimmed away has no vertex (face_tessellation.cpp).
  for (const PatchCase& c : patchCases()) {
    CountingEvaluator counting;
    int uses = 0;
    const gpu::VertexSample unset{};
    const gpu::VertexSample* handed = &unset;
    counting.useVertexSamples(c.patches, {}, [&](const gpu::VertexSample* samples) {
      ++uses;
      handed = samples;
    });
    INFO(c.name);
    CHECK(uses == 1);
    CHECK(handed == nullptr);
    CHECK(counting.vertexCalls == 0);
    CHECK(counting.sampleCalls == 0);
  }
}

TEST_CASE("tessellate evaluates its vertices with evaluateVertices, not evaluate", "[eval]") {
  const std::vector<BezierPatch> teapot = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend backend = makeMirrorBackend();
  auto counting = std::make_unique<CountingEvaluator>();
  CountingEvaluator& calls = *counting;
  backend.evaluator = std::move(counting);
  const Tessellation t =
      tessellate(teapot, toleranceOptions(resolveTolerance(parseTolerance("1%"), teapot)), backend);
  CHECK(t.mesh.vertexCount() > 0);
  CHECK(calls.vertexCalls == 1);
  CHECK(calls.vertexPrepares == 1);
  CHECK(calls.sampleCalls == 0);
  CHECK(calls.samplePrepares == 0);
}
