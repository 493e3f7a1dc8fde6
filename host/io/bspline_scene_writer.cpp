#include "io/bspline_scene_writer.h"

#include <cstdio>
#include <ostream>

#include "io/atomic_file.h"

namespace tessera {

namespace {

// printf-formatted rather than through a JSON DOM: a 1,500² net is 2.25 million points.
void writeNumbers(std::ostream& out, const std::vector<double>& values) {
  char buffer[32];
  for (size_t k = 0; k < values.size(); ++k) {
    std::snprintf(buffer, sizeof buffer, k == 0 ? "%.17g" : ", %.17g", values[k]);
    out << buffer;
  }
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

void writeBSplineScene(const std::string& path, const std::vector<NamedBSpline>& surfaces) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "{\n  \"tessera_scene\": 1,\n  \"surfaces\": [";
    for (size_t s = 0; s < surfaces.size(); ++s) {
      const BSplineSurface& b = *surfaces[s].surface;
      out << (s == 0 ? "\n" : ",\n") << "    {\"type\": \"bspline\", \"name\": "
          << quoted(surfaces[s].name) << ", \"degree\": [" << b.degreeU << ", " << b.degreeV
          << "], \"count\": [" << b.countU << ", " << b.countV << "],\n     \"knots_u\": [";
      writeNumbers(out, b.knotsU);
      out << "],\n     \"knots_v\": [";
      writeNumbers(out, b.knotsV);
      out << "],\n     \"points\": [";
      char buffer[96];
      for (size_t k = 0; k < b.cp.size(); ++k) {
        std::snprintf(buffer, sizeof buffer, "%s[%.17g, %.17g, %.17g]", k == 0 ? "" : ", ",
                      b.cp[k].x, b.cp[k].y, b.cp[k].z);
        out << buffer;
      }
      out << "]}";
    }
    out << "\n  ]\n}\n";
  });
}

}  // namespace tessera
