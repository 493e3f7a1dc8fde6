// Every SPIR-V module the build embeds passes spirv-val for the Vulkan version we target.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

TEST_CASE("every compiled shader passes spirv-val", "[spirv]") {
  fs::path dir = fs::path(TESSERA_BINARY_DIR) / "shaders";
  int modules = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".spv") continue;
    ++modules;
    std::string command = std::string(TESSERA_SPIRV_VAL) + " --target-env vulkan1.1 '" +
                          entry.path().string() + "'";
    INFO(command);
    REQUIRE(std::system(command.c_str()) == 0);
  }
  REQUIRE(modules >= 1);
}

namespace {

// The OpLoopMerge instructions (one per structured loop) of a SPIR-V module file.
int loopCount(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<uint32_t> words;
  for (uint32_t word; in.read(reinterpret_cast<char*>(&word), sizeof word);) words.push_back(word);
  REQUIRE(words.size() > 5);
  constexpr uint32_t kOpLoopMerge = 246;
  int loops = 0;
  for (size_t i = 5; i < words.size();) {  // after the 5-word header: (word count << 16) | opcode
    const uint32_t count = words[i] >> 16;
    REQUIRE(count > 0);
    loops += (words[i] & 0xffffu) == kOpLoopMerge;
    i += count;
  }
  return loops;
}

}  // namespace

// README command 1's shaders reach the driver unrolled (lib/tolerance_bound.h, TOLERANCE_UNROLL;
// shaders/CMakeLists.txt optimizes them twice): lavapipe compiles every pipeline at every run, and
// unrolling the bound's loops itself cost it ~4× the compile (bench/HISTORY.md, "The Vulkan path's
// fixed cost"). A `break` in those loops, or one spirv-opt run, leaves loops here.
TEST_CASE("rule T's bicubic shaders are compiled with their loops unrolled", "[spirv]") {
  const fs::path dir = fs::path(TESSERA_BINARY_DIR) / "shaders";
  CHECK(loopCount(dir / "quadtree_tolerance_nets.comp.spv") == 0);
  // The grid split's search over k_u × k_v stops at the first counts within δ: data-dependent.
  CHECK(loopCount(dir / "quadtree_tolerance.comp.spv") == 2);
}
