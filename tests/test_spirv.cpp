// Every SPIR-V module the build embeds passes spirv-val for the Vulkan version we target.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

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
