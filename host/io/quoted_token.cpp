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

std::string quotedToken(std::string_view token) {
  constexpr size_t kMaxShown = 32;
  if (token.size() <= kMaxShown) return "'" + printableText(token) + "'";
  return "'" + printableText(token.substr(0, kMaxShown)) + "...'";
}

}  // namespace tessera
