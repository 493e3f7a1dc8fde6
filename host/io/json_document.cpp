// JSON with lines: nlohmann's SAX parser fed through a character-counting iterator. Why the
// count gives the line of each value: json_document.h.
#include "io/json_document.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <iterator>
#include <nlohmann/json.hpp>
#include <unordered_set>

#include "io/errors.h"
#include "io/quoted_token.h"

namespace tessera {
namespace {

// A forward iterator over the text that writes how many characters have been handed out to
// a counter the parser does not know about (nlohmann's iterator adapter copies the iterator,
// so the count cannot live in the iterator itself).
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* begin, const char* at, size_t* consumed)
      : begin_(begin), at_(at), consumed_(consumed) {}

  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    ++at_;
    *consumed_ = static_cast<size_t>(at_ - begin_);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
  bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

 private:
  const char* begin_;
  const char* at_;
  size_t* consumed_;
};

// 1-based line of a character index, by a cursor that moves incrementally (the parser's
// positions only grow, except for the one character it may give back after a number).
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  // 1 + the number of '\n' before `index`; a '\n' belongs to the line it ends.
  int lineAt(size_t index) {
    index = std::min(index, text_.size());
    for (; pos_ < index; ++pos_)
      if (text_[pos_] == '\n') ++line_;
    for (; pos_ > index; --pos_)
      if (text_[pos_ - 1] == '\n') --line_;
    return line_;
  }

  // 1-based byte column of `index` on its line.
  size_t columnAt(size_t index) const {
    index = std::min(index, text_.size());
    const size_t newline = text_.rfind('\n', index == 0 ? std::string_view::npos : index - 1);
    if (index == 0 || newline == std::string_view::npos) return index + 1;
    return index - newline;
  }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int line_ = 1;
};

bool isNonFiniteSpelling(std::string_view token) {
  std::string lower;
  for (char c : token) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!lower.empty() && (lower[0] == '-' || lower[0] == '+')) lower.erase(0, 1);
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

bool isWordChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
}

// nlohmann's what() reads "[json.exception.parse_error.101] parse error at line L, column C:
// <description>"; the position is ours (same byte), the description is kept, cut short, since
// its "last read" part can be a whole runaway string (and raw bytes of a binary file, shown
// escaped).
std::string parserDescription(const char* what) {
  std::string_view text(what);
  const size_t column = text.find("column ");
  if (column != std::string_view::npos) {
    const size_t colon = text.find(": ", column);
    if (colon != std::string_view::npos) text.remove_prefix(colon + 2);
  }
  constexpr size_t kMaxShown = 160;
  if (text.size() > kMaxShown) return printableText(text.substr(0, kMaxShown)) + "...";
  return printableText(text);
}

using Json = nlohmann::json;

class LocatingSax {
 public:
  LocatingSax(std::string_view text, const size_t& consumed, JsonDocument& doc,
              const std::string& name)
      : text_(text), consumed_(consumed), doc_(doc), name_(name), lines_(text) {}

  bool null() { return add(scalar(JsonType::Null)); }
  bool boolean(bool value) {
    JsonValue v = scalar(JsonType::Boolean);
    v.boolean = value;
    return add(v);
  }
  bool number_integer(Json::number_integer_t value) { return addNumber(double(value), true); }
  bool number_unsigned(Json::number_unsigned_t value) { return addNumber(double(value), true); }
  bool number_float(Json::number_float_t value, const Json::string_t& /*token*/) {
    return addNumber(value, false);
  }
  bool string(Json::string_t& value) {
    JsonValue v = scalar(JsonType::String);
    v.first = static_cast<uint32_t>(doc_.strings.size());
    doc_.strings.push_back(std::move(value));
    return add(v);
  }
  bool binary(Json::binary_t& /*value*/) { return true; }  // never produced from JSON text

  bool start_object(std::size_t /*elements*/) { return open(JsonType::Object); }
  bool key(Json::string_t& key) {
    Open& object = stack_.back();
    const int line = currentLine();
    if (!object.keys.insert(key).second)
      throw InputError(InputErrorKind::Syntax, name_, line,
                       "duplicate key " + quotedString(key) + " in the object that starts on line " +
                           std::to_string(object.value.line));
    pendingKey_ = static_cast<uint32_t>(doc_.strings.size());
    pendingKeyLine_ = line;
    doc_.strings.push_back(std::move(key));
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t /*elements*/) { return open(JsonType::Array); }
  bool end_array() { return close(); }

  bool parse_error(std::size_t position, const std::string& /*lastToken*/,
                   const nlohmann::detail::exception& error) {
    // `position` counts characters read, so the last one read is at position − 1; at the end
    // of the input that is one past the last character: the line after a final '\n'.
    const size_t index = std::min(position == 0 ? 0 : position - 1, text_.size());
    if (index < text_.size() && isWordChar(text_[index])) {
      size_t start = index, end = index;
      while (start > 0 && isWordChar(text_[start - 1])) --start;
      while (end < text_.size() && isWordChar(text_[end])) ++end;
      const std::string_view token = text_.substr(start, end - start);
      // nlohmann reports a literal beyond the double range (1e400) as out_of_range.406.
      if (error.id == 406)
        throw InputError(InputErrorKind::Range, name_, lines_.lineAt(start),
                         quotedToken(token) + " is outside the range of a double");
      if (isNonFiniteSpelling(token))
        throw InputError(InputErrorKind::NonFinite, name_, lines_.lineAt(start),
                         quotedToken(token) +
                             " is not a finite number (JSON has no NaN or Infinity, and a "
                             "scene needs finite numbers)");
    }
    throw InputError(InputErrorKind::Syntax, name_, lines_.lineAt(index),
                     "invalid JSON at column " + std::to_string(lines_.columnAt(index)) + ": " +
                         parserDescription(error.what()));
  }

 private:
  struct Open {
    JsonValue value;
    std::vector<JsonValue> elements;
    std::unordered_set<std::string> keys;
  };

  int currentLine() { return lines_.lineAt(consumed_ == 0 ? 0 : consumed_ - 1); }

  JsonValue scalar(JsonType type) {
    JsonValue v;
    v.type = type;
    v.line = currentLine();
    return v;
  }

  bool addNumber(double value, bool integer) {
    JsonValue v = scalar(JsonType::Number);
    v.number = value;
    v.integer = integer;
    return add(v);
  }

  bool add(JsonValue v) {
    if (stack_.empty()) {
      doc_.rootIndex = pushValue(v);
      return true;
    }
    Open& parent = stack_.back();
    if (parent.value.type == JsonType::Object) {
      v.key = pendingKey_;
      v.keyLine = pendingKeyLine_;
    }
    parent.elements.push_back(v);
    return true;
  }

  uint32_t pushValue(const JsonValue& v) {
    if (doc_.values.size() >= UINT32_MAX - 1)
      throw InputError(InputErrorKind::Range, name_, v.line, "too many JSON values");
    doc_.values.push_back(v);
    return static_cast<uint32_t>(doc_.values.size() - 1);
  }

  bool open(JsonType type) {
    const JsonValue v = scalar(type);
    if (stack_.size() >= static_cast<size_t>(kJsonMaxDepth))
      throw InputError(InputErrorKind::Syntax, name_, v.line,
                       "JSON nested deeper than " + std::to_string(kJsonMaxDepth) + " levels");
    // An object member's key must survive the members inside it.
    Open opened;
    opened.value = v;
    if (!stack_.empty() && stack_.back().value.type == JsonType::Object) {
      opened.value.key = pendingKey_;
      opened.value.keyLine = pendingKeyLine_;
    }
    stack_.push_back(std::move(opened));
    return true;
  }

  // Elements go to the document only when their container closes, so that each container's
  // elements are contiguous; nested containers were placed before, their indices stay valid.
  bool close() {
    Open closed = std::move(stack_.back());
    stack_.pop_back();
    JsonValue v = closed.value;
    v.first = static_cast<uint32_t>(doc_.values.size());
    v.count = static_cast<uint32_t>(closed.elements.size());
    for (const JsonValue& element : closed.elements) pushValue(element);
    if (stack_.empty()) {
      doc_.rootIndex = pushValue(v);
    } else {
      stack_.back().elements.push_back(v);  // key and keyLine were set in open()
    }
    return true;
  }

  std::string_view text_;
  const size_t& consumed_;
  JsonDocument& doc_;
  const std::string& name_;
  LineCursor lines_;
  std::vector<Open> stack_;
  uint32_t pendingKey_ = UINT32_MAX;
  int pendingKeyLine_ = 0;
};

}  // namespace

const char* jsonTypeName(JsonType type) {
  switch (type) {
    case JsonType::Null: return "null";
    case JsonType::Boolean: return "a boolean";
    case JsonType::Number: return "a number";
    case JsonType::String: return "a string";
    case JsonType::Array: return "an array";
    case JsonType::Object: return "an object";
  }
  return "an unknown value";
}

const JsonValue* JsonDocument::member(const JsonValue& object, std::string_view key) const {
  if (object.type != JsonType::Object) return nullptr;
  for (uint32_t k = 0; k < object.count; ++k) {
    const JsonValue& v = values[object.first + k];
    if (strings[v.key] == key) return &v;
  }
  return nullptr;
}

JsonDocument parseJsonDocument(std::string_view text, const std::string& nameForMessages) {
  JsonDocument doc;
  size_t consumed = 0;
  LocatingSax sax(text, consumed, doc, nameForMessages);
  const char* begin = text.data();
  CountingIterator first(begin, begin, &consumed);
  CountingIterator last(begin, begin + text.size(), &consumed);
  // Strict: no comments, nothing after the top-level value. Every failure throws from `sax`.
  Json::sax_parse(first, last, &sax, nlohmann::json::input_format_t::json, true, false);
  return doc;
}

std::string formatJsonNumber(double value, bool integer) {
  constexpr double kLongLongRange = 9223372036854775808.0;  // 2^63
  if (integer && std::fabs(value) < kLongLongRange)
    return std::to_string(static_cast<long long>(value));
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (ec != std::errc()) return "?";
  std::string text(buffer, end);
  // "5.0" stays recognisably not an integer.
  if (std::isfinite(value) && text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

}  // namespace tessera
