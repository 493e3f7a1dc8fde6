#include "io/quoted_token.h"

namespace tessera {

std::string printableText(std::string_view text) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F) {
      out += c;
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xF];
    }
  }
  return out;
}

namespace {

std::string quoted(std::string_view text, char quote, size_t maxShown) {
  const bool cut = text.size() > maxShown;
  return quote + printableText(text.substr(0, maxShown)) + (cut ? "..." : "") + quote;
}

}  // namespace

std::string quotedToken(std::string_view token) { return quoted(token, '\'', 32); }

std::string quotedString(std::string_view text) { return quoted(text, '"', 64); }

}  // namespace tessera
