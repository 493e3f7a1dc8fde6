// Reading a .glb back in tests, with the container checks of glTF 2.0 §4.4 (Catch2 CHECKs):
// the JSON document, the BIN chunk and an accessor's bytes. test_gltf_writer.cpp reads the
// writer's files with it; test_cad_instances.cpp draws an assembly's nodes back.
#pragma once
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <string>

namespace tessera::test::glb {

// Little-endian values in the BIN chunk (or the container), whatever the host.
inline uint32_t u32At(const std::string& bytes, size_t offset) {
  uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | uint8_t(bytes.at(offset + k));
  return value;
}

inline uint16_t u16At(const std::string& bytes, size_t offset) {
  return uint16_t(uint8_t(bytes.at(offset)) | (uint8_t(bytes.at(offset + 1)) << 8));
}

inline float f32At(const std::string& bytes, size_t offset) {
  const uint32_t bits = u32At(bytes, offset);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// A GLB taken apart with the container checks of glTF 2.0 §4.4.
struct Glb {
  nlohmann::json document;
  std::string bin;  // empty when there is no BIN chunk
};

inline Glb parseGlb(const std::string& bytes) {
  REQUIRE(bytes.size() >= 20);
  CHECK(bytes.substr(0, 4) == "glTF");
  CHECK(u32At(bytes, 4) == 2);
  CHECK(u32At(bytes, 8) == bytes.size());
  const uint32_t jsonLength = u32At(bytes, 12);
  CHECK(u32At(bytes, 16) == 0x4E4F534Au);  // "JSON"
  CHECK(jsonLength % 4 == 0);
  REQUIRE(20 + size_t(jsonLength) <= bytes.size());
  Glb glb;
  glb.document =
      nlohmann::json::parse(bytes.substr(20, jsonLength));  // trailing pad spaces are JSON space
  const size_t binStart = 20 + size_t(jsonLength);
  if (binStart < bytes.size()) {
    REQUIRE(binStart + 8 <= bytes.size());
    const uint32_t binLength = u32At(bytes, binStart);
    CHECK(u32At(bytes, binStart + 4) == 0x004E4942u);  // "BIN\0"
    CHECK(binLength % 4 == 0);
    CHECK(binStart + 8 + binLength == bytes.size());
    glb.bin = bytes.substr(binStart + 8, binLength);
  }
  return glb;
}

// The bytes an accessor covers, after checking its bufferView against the buffer.
struct AccessorData {
  size_t offset = 0, count = 0;
  int componentType = 0;
  std::string type;
  int target = 0;
};

inline AccessorData accessor(const Glb& glb, int index) {
  const nlohmann::json& a = glb.document.at("accessors").at(index);
  const nlohmann::json& view = glb.document.at("bufferViews").at(a.at("bufferView").get<int>());
  const size_t bufferLength = glb.document.at("buffers").at(0).at("byteLength");
  AccessorData data;
  data.offset = view.at("byteOffset").get<size_t>() + a.value("byteOffset", size_t(0));
  data.count = a.at("count");
  data.componentType = a.at("componentType");
  data.type = a.at("type");
  data.target = view.at("target");
  CHECK(view.at("buffer") == 0);
  CHECK(view.at("byteOffset").get<size_t>() % 4 == 0);
  CHECK_FALSE(view.contains("byteStride"));
  CHECK(view.at("byteOffset").get<size_t>() + view.at("byteLength").get<size_t>() <= bufferLength);
  const size_t components = data.type == "VEC3" ? 3 : data.type == "VEC2" ? 2 : 1;
  const size_t componentSize = data.componentType == 5123 ? 2 : 4;
  CHECK(view.at("byteLength").get<size_t>() == data.count * components * componentSize);
  return data;
}

}  // namespace tessera::test::glb
