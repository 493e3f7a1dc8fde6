// A JSON document parsed with the 1-based line of every value, so readers of JSON formats
// (the scene reader) can name the line of the value they reject, as the text readers do.
//
// How the lines are found: nlohmann-json's SAX parser reads its input one character at a
// time through an iterator; ours counts the characters handed out. When the parser reports a
// value, the last character read is the value's last character — or, after a number, the one
// character it looked ahead to see the number end, which is still on the number's line (a
// '\n' ends the line it is on). So the value's line is the line of the last character read.
// For a container ('[' or '{') that is its opening bracket. Syntax errors come with nlohmann's
// byte offset, mapped to a line the same way. The tests pin the exact lines (test_scene_reader).
//
// Strictness beyond RFC 8259 as nlohmann implements it (no comments, no trailing commas,
// nothing after the top-level value, valid UTF-8): a key repeated in one object is a Syntax
// error, and so is nesting deeper than kJsonMaxDepth. NaN, Infinity and inf, which some writers
// emit although JSON has no such literals, are reported as NonFinite rather than as a bare
// syntax error.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tessera {

constexpr int kJsonMaxDepth = 64;

enum class JsonType : uint8_t { Null, Boolean, Number, String, Array, Object };

const char* jsonTypeName(JsonType type);  // "null", "a boolean", "a number", ...

// One value. Containers hold their elements in JsonDocument::values[first, first + count);
// an object's elements are its members' values, each with the index of its key.
struct JsonValue {
  JsonType type = JsonType::Null;
  bool boolean = false;
  // For numbers: the token had no fraction or exponent and fit a 64-bit integer.
  bool integer = false;
  int line = 0;     // 1-based line of the value (its opening bracket for a container)
  int keyLine = 0;  // object members: the line of the key
  double number = 0.0;  // numbers; always finite (see parseJsonDocument)
  uint32_t first = 0;   // containers: first element; strings: index into JsonDocument::strings
  uint32_t count = 0;   // containers: element count
  uint32_t key = UINT32_MAX;  // object members: index of the key in JsonDocument::strings
};

struct JsonDocument {
  std::vector<JsonValue> values;
  std::vector<std::string> strings;
  uint32_t rootIndex = 0;

  const JsonValue& root() const { return values[rootIndex]; }
  // Element k of an array or object.
  const JsonValue& element(const JsonValue& container, size_t k) const {
    return values[container.first + k];
  }
  const std::string& text(const JsonValue& string) const { return strings[string.first]; }
  const std::string& keyOf(const JsonValue& member) const { return strings[member.key]; }
  // The member of `object` named `key`, or nullptr.
  const JsonValue* member(const JsonValue& object, std::string_view key) const;
};

// Parses `text`. Throws InputError (host/io/errors.h) naming `nameForMessages` and the line:
// Syntax for malformed JSON (the reason gives the column and nlohmann's description),
// duplicate keys and excessive nesting; NonFinite for NaN/Infinity literals; Range for a
// number literal beyond the range of a double (1e400).
JsonDocument parseJsonDocument(std::string_view text, const std::string& nameForMessages);

// A number as written in messages: an integer token as an integer, others in the shortest
// form that reads back to the same double ("1e+300", "0.1", "5.0").
std::string formatJsonNumber(double value, bool integer);

}  // namespace tessera
