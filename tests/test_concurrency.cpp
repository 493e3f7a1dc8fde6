// The thread-safety contract (docs/hardening.md): independent tessellations — each with its
// own Backend, and on Vulkan each with its own vk::Context — may run at the same time on
// different threads, and give exactly the results they give one at a time.
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "quadtree_compare.h"
#include "mesh/tessellate.h"

using namespace tessera;

namespace {

struct Job {
  std::vector<BezierPatch> patches;
  QuadtreeOptions options;
};

// Two jobs that differ in input, rule and thresholds, so a shared cache or buffer would show.
std::vector<Job> twoJobs() {
  Job teapot{readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt"), {}};
  teapot.options.rule = SplitRule::Midpoint;
  teapot.options.linearity = teapot.options.flatness = 0.1f;
  Job teacup{readBpt(TESSERA_SOURCE_DIR "/data/teacup.bpt"), {}};
  teacup.options.rule = SplitRule::TrueMax;
  teacup.options.linearity = teacup.options.flatness = 0.2f;
  return {teapot, teacup};
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void requireSameResult(const Tessellation& alone, const Tessellation& together, size_t job) {
  INFO("job " << job << ": alone " << alone.tree.leaves.size() << " leaves, "
              << alone.mesh.triangleCount() << " triangles; concurrently "
              << together.tree.leaves.size() << " leaves, " << together.mesh.triangleCount()
              << " triangles");
  REQUIRE(alone.tree.leaves.size() > 100);
  REQUIRE(test::identicalTrees(alone.tree, together.tree));
  REQUIRE(sameBits(alone.mesh.indices, together.mesh.indices));
  REQUIRE(sameBits(alone.mesh.positions, together.mesh.positions));
  REQUIRE(sameBits(alone.mesh.normals, together.mesh.normals));
}

// Runs every job on its own backend, first one at a time, then all at once on one thread each
// (repeated, to give a race more chances), and requires identical results.
void runAloneThenTogether(const std::vector<Job>& jobs,
                          const std::vector<Backend*>& backends, int rounds) {
  std::vector<Tessellation> alone;
  for (size_t k = 0; k < jobs.size(); ++k)
    alone.push_back(tessellate(jobs[k].patches, jobs[k].options, *backends[k]));
  for (int round = 0; round < rounds; ++round) {
    std::vector<Tessellation> together(jobs.size());
    std::vector<std::string> errors(jobs.size());
    std::vector<std::thread> threads;
    for (size_t k = 0; k < jobs.size(); ++k)
      threads.emplace_back([&, k] {
        try {
          together[k] = tessellate(jobs[k].patches, jobs[k].options, *backends[k]);
        } catch (const std::exception& e) {
          errors[k] = e.what();
        }
      });
    for (std::thread& t : threads) t.join();
    for (size_t k = 0; k < jobs.size(); ++k) {
      INFO("round " << round << ", job " << k << ": " << errors[k]);
      REQUIRE(errors[k].empty());
      requireSameResult(alone[k], together[k], k);
    }
  }
}

}  // namespace

TEST_CASE("two tessellations on two threads equal the same runs one at a time (CPU)",
          "[tessellate][concurrency]") {
  const std::vector<Job> jobs = twoJobs();
  Backend a = makeMirrorBackend(), b = makeMirrorBackend();
  runAloneThenTogether(jobs, {&a, &b}, 3);
}

TEST_CASE("two tessellations on two threads with two Vulkan contexts equal one at a time",
          "[gpu][tessellate][concurrency]") {
  test::gpuContext();  // a missing device fails here with the usual message
  std::unique_ptr<vk::Context> contexts[2];
  for (auto& context : contexts) {
    vk::ContextOptions options;
    options.validation = vk::Validation::Required;
    context = std::make_unique<vk::Context>(options);
  }
  Backend a = makeVulkanBackend(*contexts[0]), b = makeVulkanBackend(*contexts[1]);
  runAloneThenTogether(twoJobs(), {&a, &b}, 2);
  for (int k = 0; k < 2; ++k) {
    const std::vector<std::string> messages = contexts[k]->validationMessages();
    for (const std::string& m : messages) UNSCOPED_INFO("context " << k << ": " << m);
    REQUIRE(messages.empty());
  }
}
