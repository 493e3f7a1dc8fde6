// Strings from a JSON scene appear in error messages escaped and cut short (issue 18): a name,
// key or type with terminal escapes or a NUL, a 10 MB name, a 10 MB number token. Before, they
// went into the message raw (an ESC drove the terminal, a NUL cut the message in C APIs, a
// 10 MB name made a 10 MB message).
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "input_error_checks.h"
#include "io/errors.h"
#include "io/scene_convert.h"
#include "io/scene_reader.h"

using namespace tessera;

namespace {

// A one-surface scene with `surfaceMembers` spliced into the surface object.
std::string sceneWith(const std::string& surfaceMembers, const std::string& firstPoint = "0") {
  return "{\"tessera_scene\": 1, \"surfaces\": [{\"type\": \"bezier\", \"degree\": [1, 1], "
         "\"points\": [[" + firstPoint + ", 0, 0], [1, 0, 0], [0, 1, 0]]" + surfaceMembers +
         "}]}";
}

// The message reading `text` gives: every byte printable ASCII, at most `maxBytes` long, and
// containing `expected`.
void requireTameMessage(const std::string& text, const std::string& expected) {
  std::istringstream in(text);
  const InputError e =
      test::inputErrorOf([&] { sceneToPatches(parseScene(in, "scene.json")); }, "scene.json");
  const std::string message = e.what();
  INFO("message (" << message.size() << " bytes): " << message.substr(0, 300));
  size_t unprintable = 0;
  for (const char c : message) unprintable += c < 0x20 || c >= 0x7F;
  CHECK(unprintable == 0);
  CHECK(message.size() < 400);
  CHECK(message.find(expected) != std::string::npos);
}

}  // namespace

TEST_CASE("scene: names, keys and tokens in messages are escaped and cut short",
          "[io][scene][bad-inputs]") {
  const std::string escape = "\\u001b[31mred\\u0000cut";  // JSON escapes: ESC and NUL
  SECTION("a surface name with ESC and NUL") {
    requireTameMessage(sceneWith(", \"name\": \"" + escape + "\""),
                       "surface 1 (\"\\x1B[31mred\\x00cut\") has 3 points");
  }
  SECTION("a 10 MB surface name") {
    requireTameMessage(sceneWith(", \"name\": \"" + std::string(10'000'000, 'x') + "\""),
                       "surface 1 (\"" + std::string(64, 'x') + "...\")");
  }
  SECTION("an unknown key with ESC, 1000 bytes long") {
    requireTameMessage(sceneWith(", \"\\u001b" + std::string(1000, 'k') + "\": 1"),
                       "unknown key \"\\x1B" + std::string(63, 'k') + "...\"");
  }
  SECTION("a duplicate key with ESC") {
    requireTameMessage(sceneWith(", \"\\u001bk\": 1, \"\\u001bk\": 2"), "duplicate key \"\\x1Bk\"");
  }
  SECTION("an unknown surface type of 10 MB") {
    const std::string text = "{\"tessera_scene\": 1, \"surfaces\": [{\"type\": \"" +
                             std::string(10'000'000, 't') + "\"}]}";
    requireTameMessage(text, "unknown surface type \"" + std::string(64, 't') + "...\"");
  }
  SECTION("a 10 MB number token") {
    requireTameMessage(sceneWith("", "1" + std::string(10'000'000, '0')),
                       "'1" + std::string(31, '0') + "...' is outside the range of a double");
  }
}
