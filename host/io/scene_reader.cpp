// JSON scene parsing: the document is parsed once with the line of every value
// (io/json_document.h), then walked with the scene's rules. Format: docs/scene_format.md.
#include "io/scene_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "common/memory_budget.h"
#include "io/errors.h"
#include "io/input_limit.h"
#include "io/quoted_token.h"
#include "io/json_document.h"
#include "io/text_lines.h"
#include "bspline/knots.h"

namespace tessera {
namespace {

// Surfaces with more control points per direction are taken for a corrupt file.
constexpr long long kSceneMaxCount = 1000000;

bool isNonFiniteSpelling(const std::string& s) {
  std::string lower;
  for (char c : s) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  if (!lower.empty() && (lower[0] == '-' || lower[0] == '+')) lower.erase(0, 1);
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

std::string joinKeys(std::initializer_list<const char*> keys) {
  std::string out;
  for (const char* k : keys) out += (out.empty() ? "\"" : ", \"") + std::string(k) + "\"";
  return out;
}

class SceneParser {
 public:
  SceneParser(const JsonDocument& doc, const std::string& name) : doc_(doc), name_(name) {}

  Scene parse() {
    const JsonValue& root = doc_.root();
    if (root.type != JsonType::Object)
      fail(InputErrorKind::Syntax, root.line,
           std::string("a scene is an object {\"tessera_scene\": 1, \"surfaces\": [...]}, found ") +
               jsonTypeName(root.type));
    checkKeys(root, {"tessera_scene", "surfaces", "comment"}, "the scene object");

    const JsonValue* version = doc_.member(root, "tessera_scene");
    if (!version)
      fail(InputErrorKind::Syntax, root.line,
           "not a Tessera scene: the top-level object has no \"tessera_scene\" version");
    if (version->type != JsonType::Number || !version->integer ||
        version->number != kSceneFormatVersion)
      fail(InputErrorKind::Syntax, version->line,
           "unsupported scene version " + shown(*version) + ": this reader reads version " +
               std::to_string(kSceneFormatVersion));

    const JsonValue& surfaces = required(root, "surfaces", JsonType::Array, "the scene object");
    if (surfaces.count == 0)
      fail(InputErrorKind::Count, surfaces.line,
           "\"surfaces\" is empty: a scene needs at least one surface");

    Scene scene;
    scene.source = name_;
    for (uint32_t k = 0; k < surfaces.count; ++k) parseSurface(doc_.element(surfaces, k), k, scene);
    return scene;
  }

 private:
  [[noreturn]] void fail(InputErrorKind kind, int line, const std::string& reason) const {
    throw InputError(kind, name_, line, reason);
  }

  // A value as it appears in a message.
  std::string shown(const JsonValue& v) const {
    switch (v.type) {
      case JsonType::Number: return formatJsonNumber(v.number, v.integer);
      case JsonType::String: return quotedString(doc_.text(v));
      case JsonType::Boolean: return v.boolean ? "true" : "false";
      default: return jsonTypeName(v.type);
    }
  }

  void checkKeys(const JsonValue& object, std::initializer_list<const char*> allowed,
                 const std::string& what) const {
    for (uint32_t k = 0; k < object.count; ++k) {
      const JsonValue& member = doc_.element(object, k);
      const std::string& key = doc_.keyOf(member);
      bool known = false;
      for (const char* a : allowed) known = known || key == a;
      if (!known)
        fail(InputErrorKind::Syntax, member.keyLine,
             "unknown key " + quotedString(key) + " in " + what + " (expected " + joinKeys(allowed) + ")");
    }
  }

  void validateType(const JsonValue& v, JsonType type, const std::string& what) const {
    if (v.type != type)
      fail(InputErrorKind::Syntax, v.line,
           what + " must be " + jsonTypeName(type) + ", found " + jsonTypeName(v.type));
  }

  const JsonValue& required(const JsonValue& object, const char* key, JsonType type,
                            const std::string& what) const {
    const JsonValue* v = doc_.member(object, key);
    if (!v) fail(InputErrorKind::Syntax, object.line, what + " has no \"" + key + "\"");
    validateType(*v, type, "\"" + std::string(key) + "\" of " + what);
    return *v;
  }

  // A finite number with |value| ≤ 1e15, as in the text formats.
  double finiteNumber(const JsonValue& v, const std::string& what) const {
    if (v.type == JsonType::String && isNonFiniteSpelling(doc_.text(v)))
      fail(InputErrorKind::NonFinite, v.line,
           shown(v) + " is not a finite number (" + what + ")");
    validateType(v, JsonType::Number, what);
    // parseJsonDocument already turned NaN, Infinity and 1e400 into errors; kept for safety.
    if (!std::isfinite(v.number))
      fail(InputErrorKind::NonFinite, v.line, "a non-finite number (" + what + ")");
    if (std::fabs(v.number) > kMaxAbsInputCoordinate)
      fail(InputErrorKind::Range, v.line,
           shown(v) + " exceeds the largest accepted magnitude 1e15 (" + what + ")");
    return v.number;
  }

  long long integer(const JsonValue& v, const std::string& what) const {
    validateType(v, JsonType::Number, what);
    if (!v.integer)
      fail(InputErrorKind::Syntax, v.line, what + " must be an integer, found " + shown(v));
    return static_cast<long long>(v.number);
  }

  // A two-element array of integers, e.g. "degree": [3, 2].
  const JsonValue& pair(const JsonValue& surface, const char* key, const std::string& what) const {
    const JsonValue& v = required(surface, key, JsonType::Array, what);
    if (v.count != 2)
      fail(InputErrorKind::Syntax, v.line,
           "\"" + std::string(key) + "\" of " + what + " must be [u, v] (two integers), found " +
               std::to_string(v.count) + " elements");
    return v;
  }

  std::array<int, 2> degrees(const JsonValue& surface, const std::string& what) const {
    const JsonValue& v = pair(surface, "degree", what);
    std::array<int, 2> degree{};
    for (int d = 0; d < 2; ++d) {
      const JsonValue& e = doc_.element(v, d);
      const std::string direction = d == 0 ? "u" : "v";
      const long long value = integer(e, "degree in " + direction + " of " + what);
      if (value < 1 || value > kMaxDegree)
        fail(InputErrorKind::Degree, e.line,
             "degree in " + direction + " of " + what + " is " + shown(e) + "; must be 1.." +
                 std::to_string(kMaxDegree));
      degree[d] = static_cast<int>(value);
    }
    return degree;
  }

  // The "points" array with exactly `expected` elements, each [x, y, z].
  std::vector<glm::dvec3> points(const JsonValue& surface, size_t expected,
                                 const std::string& needs, const std::string& what) const {
    const JsonValue& list = required(surface, "points", JsonType::Array, what);
    if (list.count > expected)
      fail(InputErrorKind::Count, doc_.element(list, expected).line,
           what + " has " + std::to_string(list.count) + " points; " + needs + " needs " +
               std::to_string(expected) + " (point " + std::to_string(expected + 1) +
               " is one too many)");
    if (list.count < expected)
      fail(InputErrorKind::Count, list.line,
           what + " has " + std::to_string(list.count) + " points; " + needs + " needs " +
               std::to_string(expected));
    std::vector<glm::dvec3> out(expected);
    for (size_t k = 0; k < expected; ++k) {
      const JsonValue& p = doc_.element(list, k);
      const std::string pointName = "point " + std::to_string(k + 1) + " of " + what;
      if (p.type != JsonType::Array || p.count != 3)
        fail(InputErrorKind::Syntax, p.line,
             pointName + " must be [x, y, z], found " +
                 (p.type == JsonType::Array ? "an array of " + std::to_string(p.count)
                                            : std::string(jsonTypeName(p.type))));
      for (int c = 0; c < 3; ++c)
        out[k][c] = finiteNumber(doc_.element(p, c), std::string(1, "xyz"[c]) + " of " + pointName);
    }
    return out;
  }

  std::vector<double> weights(const JsonValue& list, int degreeU, int degreeV,
                              const std::string& what) const {
    const size_t expected = static_cast<size_t>((degreeU + 1) * (degreeV + 1));
    if (list.count != expected)
      fail(InputErrorKind::Count, list.line,
           what + " has " + std::to_string(list.count) + " weights for " +
               std::to_string(expected) + " points");
    std::vector<double> w(expected);
    bool anyPositive = false;
    for (size_t k = 0; k < expected; ++k) {
      const JsonValue& e = doc_.element(list, k);
      const std::string weightName = "weight " + std::to_string(k + 1) + " of " + what;
      w[k] = finiteNumber(e, weightName);
      if (w[k] < 0.0)
        fail(InputErrorKind::Weight, e.line,
             weightName + " is " + shown(e) + "; weights must be ≥ 0");
      anyPositive = anyPositive || w[k] > 0.0;
    }
    if (!anyPositive)
      fail(InputErrorKind::Weight, list.line, "all weights of " + what + " are zero");
    // At a corner only its own control point has a nonzero basis function, so the rational
    // surface there is b·w / w: undefined for w = 0. Inner zero weights are fine (the point
    // then has no influence); docs/scene_format.md.
    const int corners[4][2] = {{0, 0}, {0, degreeV}, {degreeU, 0}, {degreeU, degreeV}};
    for (const auto& c : corners) {
      const size_t k = static_cast<size_t>(c[0] * (degreeV + 1) + c[1]);
      if (w[k] == 0.0)
        fail(InputErrorKind::Weight, doc_.element(list, k).line,
             "weight " + std::to_string(k + 1) + " of " + what + " (the corner b_" +
                 std::to_string(c[0]) + "," + std::to_string(c[1]) +
                 ") is zero: the surface would be undefined at that corner (only inner weights "
                 "may be zero)");
    }
    return w;
  }

  std::vector<double> knots(const JsonValue& surface, const char* key, int degree, int count,
                            const std::string& what) const {
    const JsonValue& list = required(surface, key, JsonType::Array, what);
    std::vector<double> x(list.count);
    for (uint32_t k = 0; k < list.count; ++k)
      x[k] = finiteNumber(doc_.element(list, k),
                          "knot " + std::to_string(k + 1) + " of " + key + " of " + what);
    try {
      validateKnots(degree, count, x, key);
    } catch (const std::invalid_argument& e) {
      // Point at the first decreasing knot when that is the trouble, else at the array.
      int line = list.line;
      if (x.size() == static_cast<size_t>(count + degree + 1))
        for (size_t k = 1; k < x.size(); ++k)
          if (x[k] < x[k - 1]) {
            line = doc_.element(list, k).line;
            break;
          }
      fail(InputErrorKind::Knots, line, std::string(e.what()) + " (" + what + ")");
    }
    return x;
  }

  void parseSurface(const JsonValue& surface, uint32_t k, Scene& scene) const {
    std::string what = "surface " + std::to_string(k + 1);
    if (surface.type != JsonType::Object)
      fail(InputErrorKind::Syntax, surface.line,
           what + " must be an object, found " + jsonTypeName(surface.type));
    SceneSurfaceRef ref;
    ref.line = surface.line;
    if (const JsonValue* name = doc_.member(surface, "name")) {
      validateType(*name, JsonType::String, "\"name\" of " + what);
      ref.name = doc_.text(*name);
      what += " (" + quotedString(ref.name) + ")";
    }
    const JsonValue& typeValue = required(surface, "type", JsonType::String, what);
    const std::string& type = doc_.text(typeValue);
    if (type == "bezier") {
      checkKeys(surface, {"type", "degree", "points", "weights", "name", "comment"}, what);
      const std::array<int, 2> degree = degrees(surface, what);
      ref.degreeLine = doc_.member(surface, "degree")->line;
      const size_t count = static_cast<size_t>((degree[0] + 1) * (degree[1] + 1));
      const std::string needs = "degree [" + std::to_string(degree[0]) + ", " +
                                std::to_string(degree[1]) + "] (row by row, (n+1)(m+1))";
      std::vector<glm::dvec3> cp = points(surface, count, needs, what);
      if (const JsonValue* w = doc_.member(surface, "weights")) {
        validateType(*w, JsonType::Array, "\"weights\" of " + what);
        const std::vector<double> weight = weights(*w, degree[0], degree[1], what);
        RationalBezierPatch patch;
        patch.degreeU = degree[0];
        patch.degreeV = degree[1];
        patch.cpw.resize(count);
        for (size_t i = 0; i < count; ++i) patch.cpw[i] = glm::dvec4(cp[i] * weight[i], weight[i]);
        ref.type = SceneSurfaceType::Rational;
        ref.index = scene.rational.size();
        ref.weightsLine = w->line;
        scene.rational.push_back(std::move(patch));
      } else {
        BezierPatch patch;
        patch.degreeU = degree[0];
        patch.degreeV = degree[1];
        patch.cp = std::move(cp);
        ref.type = SceneSurfaceType::Bezier;
        ref.index = scene.bezier.size();
        scene.bezier.push_back(std::move(patch));
      }
    } else if (type == "bspline") {
      checkKeys(surface,
                {"type", "degree", "count", "knots_u", "knots_v", "points", "name", "comment"},
                what);
      const std::array<int, 2> degree = degrees(surface, what);
      ref.degreeLine = doc_.member(surface, "degree")->line;
      const JsonValue& countValue = pair(surface, "count", what);
      std::array<int, 2> count{};
      for (int d = 0; d < 2; ++d) {
        const JsonValue& e = doc_.element(countValue, d);
        const std::string direction = d == 0 ? "u" : "v";
        const long long n = integer(e, "count in " + direction + " of " + what);
        if (n < degree[d] + 1)
          fail(InputErrorKind::Count, e.line,
               "count in " + direction + " of " + what + " is " + shown(e) + "; degree " +
                   std::to_string(degree[d]) + " needs at least " + std::to_string(degree[d] + 1) +
                   " control points");
        if (n > kSceneMaxCount)
          fail(InputErrorKind::Count, e.line,
               "count in " + direction + " of " + what + " is " + shown(e) + "; at most " +
                   std::to_string(kSceneMaxCount) + " control points per direction");
        count[d] = static_cast<int>(n);
      }
      BSplineSurface spline;
      spline.degreeU = degree[0];
      spline.degreeV = degree[1];
      spline.countU = count[0];
      spline.countV = count[1];
      const std::string needs = "count [" + std::to_string(count[0]) + ", " +
                                std::to_string(count[1]) + "] (row by row, nu·nv)";
      spline.cp = points(surface, static_cast<size_t>(count[0]) * static_cast<size_t>(count[1]),
                         needs, what);
      spline.knotsU = knots(surface, "knots_u", degree[0], count[0], what);
      spline.knotsV = knots(surface, "knots_v", degree[1], count[1], what);
      ref.type = SceneSurfaceType::BSpline;
      ref.index = scene.bsplines.size();
      scene.bsplines.push_back(std::move(spline));
    } else {
      fail(InputErrorKind::Syntax, typeValue.line,
           "unknown surface type " + quotedString(type) + " (" + what +
               "; expected \"bezier\" or \"bspline\")");
    }
    scene.order.push_back(std::move(ref));
  }

  const JsonDocument& doc_;
  const std::string& name_;
};

}  // namespace

uint64_t estimatedSceneBytes(std::string_view text) {
  // Every value but the root ends before a ',' or a closing bracket, so values ≤ commas +
  // containers + 1 (a comma inside a string only raises the bound). Each is a JsonValue,
  // held in a vector that may have doubled past it; each number then becomes a double of the
  // scene.
  const uint64_t values = uint64_t(std::count(text.begin(), text.end(), ',')) +
                          uint64_t(std::count(text.begin(), text.end(), '[')) +
                          uint64_t(std::count(text.begin(), text.end(), '{')) + 1;
  return text.size() + values * (2 * sizeof(JsonValue) + sizeof(double));
}

Scene parseScene(std::istream& in, const std::string& nameForMessages) {
  // JSON holds no raw NUL (RFC 8259: control characters are escaped), so the parser fails at
  // the first one whatever follows it.
  const std::string text = readWhole(in, nameForMessages, /*stopAfterNul=*/true);
  requireWithinMemoryBudget(estimatedSceneBytes(text),
                            nameForMessages + ": its JSON document and scene (" +
                                formatByteSize(text.size()) + " of text)");
  const JsonDocument doc = parseJsonDocument(text, nameForMessages);
  return SceneParser(doc, nameForMessages).parse();
}

Scene readScene(const std::string& path) {
  std::ifstream file = openForReading(path, "a .json scene file");
  BoundedInput in(file, path);
  return parseScene(in.stream(), path);
}

}  // namespace tessera
