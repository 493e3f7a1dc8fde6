// Numbers in CAD messages: %g with 4 significant digits (std::to_string prints 1e-7 as 0.000000).
#pragma once
#include <cstdio>
#include <string>

namespace tessera::cad_detail {

inline std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace tessera::cad_detail
