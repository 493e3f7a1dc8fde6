// Checks of `tessera view`'s scripted output, for ctest (tests/viewer/CMakeLists.txt):
//   viewer_check picture SHOT.png MIN_MESH_FRACTION MIN_COLOURS
//     the screenshot shows a mesh: at least that fraction of its pixels are neither the
//     background (kRenderBackground) nor the overlay's band and letters, and the picture has
//     at least that many distinct colours (shading, not a flat fill);
//   viewer_check mesh FRAME.glb
//     the dumped frame, its vertices welded where positions are equal bit for bit, has no
//     T-junction and no edge used by three triangles (tests/mesh_checks.h);
//   viewer_check keys LOG DIR
//     the run of keys_script.txt: its log (every frame's status line, every key's effect) and
//     the pictures and meshes it wrote into DIR show that each key and the drag did their job
//     (checkKeys below says how);
//   viewer_check keys-log LOG DX DY
//     the log of real X input (real_input.sh): the same rules on the log, and its drags add
//     up to (DX, DY) pixels.
// Prints what it measured either way; exit 0 when the check holds, 1 when not, 2 on bad input.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#include "mesh_checks.h"
#include "render/offscreen.h"

namespace {

using tessera::TriangleMesh;

int checkPicture(const char* path, double minFraction, size_t minColours) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path, &width, &height, &channels, 4);
  if (!pixels) {
    std::fprintf(stderr, "viewer_check: %s: not a PNG (%s)\n", path, stbi_failure_reason());
    return 2;
  }
  // The overlay: white letters on a band of grey 0.12 (viewer/overlay_text.cpp), UNORM-rounded.
  const std::array<uint8_t, 3> overlay[2] = {{255, 255, 255}, {31, 31, 31}};
  size_t meshPixels = 0;
  std::set<uint32_t> colours;
  for (size_t p = 0; p < size_t(width) * height; ++p) {
    const stbi_uc* c = &pixels[4 * p];
    colours.insert(uint32_t(c[0]) << 16 | uint32_t(c[1]) << 8 | c[2]);
    bool background = std::memcmp(c, tessera::kRenderBackground.data(), 3) == 0;
    for (const auto& o : overlay) background = background || std::memcmp(c, o.data(), 3) == 0;
    if (!background) ++meshPixels;
  }
  stbi_image_free(pixels);
  const double fraction = double(meshPixels) / (double(width) * height);
  std::printf("%s: %dx%d, %zu mesh pixels (%.2f%%, need %.2f%%), %zu colours (need %zu)\n", path,
              width, height, meshPixels, 100 * fraction, 100 * minFraction, colours.size(),
              minColours);
  return fraction >= minFraction && colours.size() >= minColours ? 0 : 1;
}

uint32_t u32At(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | uint8_t(s[at + k]);
  return v;
}

// POSITION and the indices of the one primitive tessera's glTF writer makes (host/io/gltf_writer.h).
bool readGlb(const char* path, TriangleMesh& mesh) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  if (bytes.size() < 28 || bytes.compare(0, 4, "glTF") != 0) return false;
  const uint32_t jsonLength = u32At(bytes, 12);
  const nlohmann::json doc = nlohmann::json::parse(bytes.substr(20, jsonLength));
  const size_t binStart = 20 + size_t(jsonLength) + 8;
  const nlohmann::json& primitive = doc.at("meshes").at(0).at("primitives").at(0);
  auto bytesOf = [&](int accessor, size_t& count, int& componentType) {
    const nlohmann::json& a = doc.at("accessors").at(accessor);
    const nlohmann::json& view = doc.at("bufferViews").at(a.at("bufferView").get<int>());
    count = a.at("count");
    componentType = a.at("componentType");
    return bytes.data() + binStart + view.at("byteOffset").get<size_t>();
  };
  size_t count = 0;
  int type = 0;
  const char* positions = bytesOf(primitive.at("attributes").at("POSITION"), count, type);
  mesh.positions.resize(count);
  std::memcpy(mesh.positions.data(), positions, count * 12);
  const char* indices = bytesOf(primitive.at("indices"), count, type);
  mesh.indices.resize(count);
  for (size_t k = 0; k < count; ++k) {
    if (type == 5123) {
      uint16_t i;
      std::memcpy(&i, indices + 2 * k, 2);
      mesh.indices[k] = i;
    } else {
      std::memcpy(&mesh.indices[k], indices + 4 * k, 4);
    }
  }
  return true;
}

int checkMesh(const char* path) {
  TriangleMesh drawn;
  try {
    if (!readGlb(path, drawn)) throw std::runtime_error("not a GLB");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "viewer_check: %s: %s\n", path, e.what());
    return 2;
  }
  // Each patch writes its own copy of its border vertices; shared ones are equal bit for bit.
  TriangleMesh mesh;
  std::map<std::array<uint32_t, 3>, uint32_t> weld;
  std::vector<uint32_t> welded(drawn.positions.size());
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (size_t v = 0; v < drawn.positions.size(); ++v) {
    std::array<uint32_t, 3> key;
    std::memcpy(key.data(), &drawn.positions[v], sizeof key);
    const auto [it, inserted] = weld.emplace(key, uint32_t(mesh.positions.size()));
    if (inserted) mesh.positions.push_back(drawn.positions[v]);
    welded[v] = it->second;
    lo = glm::min(lo, drawn.positions[v]);
    hi = glm::max(hi, drawn.positions[v]);
  }
  for (uint32_t i : drawn.indices) mesh.indices.push_back(welded[i]);
  const tessera::test::EdgeCensus census = tessera::test::censusOf(mesh, 0.0);
  double largestGap = 0;
  const double eps = 1e-6 * glm::length(glm::dvec3(hi - lo));
  const size_t tJunctions = tessera::test::tJunctionCount(mesh, census, eps, &largestGap);
  std::printf("%s: %zu triangles, %zu vertices welded to %zu; edges: %zu shared, %zu open, "
              "%zu used 3+ times; %zu T-junctions (longest open edge with one: %g)\n",
              path, mesh.triangleCount(), drawn.positions.size(), mesh.positions.size(),
              census.manifoldEdges, census.boundaryEdges, census.overusedEdges, tJunctions,
              largestGap);
  return mesh.triangleCount() > 0 && tJunctions == 0 && census.overusedEdges == 0 ? 0 : 1;
}

// ---- viewer_check keys -------------------------------------------------------------------

// One frame's status line, as the log prints it (viewer/view_state.h, statusLine).
struct FrameStatus {
  double fps = 0;
  size_t triangles = 0;
  double error = 0, tolerance = 0;
  std::string colour;
  bool wire = false, frozen = false;
};

struct KeysLog {
  std::map<int, FrameStatus> frames;
  std::vector<std::pair<int, std::string>> events;  // (frame, what the key or mouse did)
};

bool readKeysLog(const char* path, KeysLog& log) {
  std::ifstream in(path);
  if (!in) return false;
  const std::regex status(
      R"(view: frame (\d+): ([0-9.]+) frames/s  (\d+) triangles  error ([0-9.]+) px )"
      R"(\(tolerance ([0-9.e+-]+) px\)  (shaded|patch|level)( wire)?(  FROZEN)?)");
  const std::regex event(R"(view: frame (\d+): (.*))");
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_match(line, m, status)) {
      FrameStatus f{std::stod(m[2]), std::stoul(m[3]), std::stod(m[4]), std::stod(m[5]),
                    m[6], m[7].matched, m[8].matched};
      log.frames[std::stoi(m[1])] = f;
    } else if (std::regex_match(line, m, event)) {
      log.events.emplace_back(std::stoi(m[1]), m[2]);
    }
  }
  return true;
}

struct Rgb {
  int r, g, b;
};

std::vector<Rgb> meshPixels(const std::string& path, int& width, int& height) {
  int channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (!pixels) throw std::runtime_error(path + ": not a PNG");
  const std::array<uint8_t, 3> overlay[2] = {{255, 255, 255}, {31, 31, 31}};
  std::vector<Rgb> out;
  for (size_t p = 0; p < size_t(width) * height; ++p) {
    const stbi_uc* c = &pixels[4 * p];
    bool background = std::memcmp(c, tessera::kRenderBackground.data(), 3) == 0;
    for (const auto& o : overlay) background = background || std::memcmp(c, o.data(), 3) == 0;
    if (!background) out.push_back({c[0], c[1], c[2]});
  }
  stbi_image_free(pixels);
  return out;
}

// The wireframe darkens edges to a quarter of the surface's colour (shaders/mesh.frag.glsl);
// lit or not, the filled surface stays above this grey (ambient 0.2 of the porcelain: ~106).
double darkFraction(const std::vector<Rgb>& pixels) {
  size_t dark = 0;
  for (const Rgb& p : pixels) dark += std::max({p.r, p.g, p.b}) < 80;
  return pixels.empty() ? 0 : double(dark) / double(pixels.size());
}

// The mesh's pixels matched to a palette's colours. Light scales a colour (shading in linear
// light, then gamma: the result is the sRGB colour times one factor), so a pixel's direction
// in RGB is its palette colour's; pixels brighter than 60 are matched within 2 degrees.
// Returns the share of those pixels matched, and how many colours got at least 0.5% of them.
std::pair<double, int> paletteMatch(const std::vector<Rgb>& pixels,
                                    const std::vector<std::array<uint8_t, 3>>& palette) {
  std::vector<size_t> hits(palette.size(), 0);
  size_t bright = 0, matched = 0;
  const double cosLimit = std::cos(2.0 * 3.14159265358979 / 180);
  for (const Rgb& p : pixels) {
    if (std::max({p.r, p.g, p.b}) <= 60) continue;
    ++bright;
    const double pl = std::sqrt(double(p.r * p.r + p.g * p.g + p.b * p.b));
    for (size_t k = 0; k < palette.size(); ++k) {
      const auto& c = palette[k];
      const double cl = std::sqrt(double(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
      if ((p.r * c[0] + p.g * c[1] + p.b * c[2]) / (pl * cl) >= cosLimit) {
        ++hits[k];
        ++matched;
        break;
      }
    }
  }
  int used = 0;
  for (size_t h : hits) used += h >= 0.005 * double(bright) && h > 0;
  return {bright ? double(matched) / double(bright) : 0.0, used};
}

std::vector<std::array<uint8_t, 3>> palette(tessera::RenderOptions::Colour colour, int size) {
  std::vector<std::array<uint8_t, 3>> out;
  for (int k = 0; k < size; ++k) out.push_back(tessera::paletteColour(colour, k));
  return out;
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) throw std::runtime_error(path + ": cannot be read");
  return buffer.str();
}

// The checks of one run: each printed as it is made, the failures counted.
struct Checks {
  int failures = 0;
  void operator()(bool ok, const std::string& what) {
    std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
    failures += !ok;
  }
  int exitCode() const {
    std::printf("%d failed\n", failures);
    return failures == 0 ? 0 : 1;
  }
};

bool readNonEmptyLog(const char* path, KeysLog& log) {
  if (readKeysLog(path, log) && !log.frames.empty()) return true;
  std::fprintf(stderr, "viewer_check: %s: no status lines\n", path);
  return false;
}

// The rules every log of key presses obeys, scripted or real:
// - every frame has its status line, with frames/s (from frame 1 on), triangles > 0, an error
//   within the tolerance while the mesh is not frozen;
// - each key's effect is seen between its frame's line and the one before: W flips " wire"
//   and keeps the triangles; C goes shaded -> patch -> level -> shaded; + doubles the
//   tolerance, fewer triangles and a larger error, - the opposite; F flips FROZEN, and frozen
//   frames keep their triangles while a drag turns the camera (the error moves) and the wheel
//   brings it nearer (the error grows); thawed, the wheel nearer gives more triangles and
//   farther fewer; every key and the mouse show up at least once.
// Adds up the drags the log reports.
void checkLogRules(KeysLog& log, Checks& expect, double& dragX, double& dragY) {
  const int lastFrame = log.frames.rbegin()->first;
  expect(int(log.frames.size()) == lastFrame + 1,
         "a status line for each of frames 0.." + std::to_string(lastFrame));
  size_t framesOk = 0;
  for (const auto& [frame, f] : log.frames) {
    const std::string at = "frame " + std::to_string(frame) + ": ";
    const bool ok = (frame == 0 || f.fps > 0) && f.triangles > 0 &&
                    (f.frozen || (f.error > 0 && f.error <= f.tolerance));
    if (!ok)
      expect(false, at + std::to_string(f.fps) + " frames/s, " + std::to_string(f.triangles) +
                        " triangles, error " + std::to_string(f.error) + " px, tolerance " +
                        std::to_string(f.tolerance));
    framesOk += ok;
  }
  expect(framesOk == log.frames.size(),
         std::to_string(framesOk) + " of " + std::to_string(log.frames.size()) +
             " frames: frames/s > 0 (after frame 0), triangles > 0, error > 0 and within the "
             "tolerance (unless frozen)");
  dragX = dragY = 0;
  std::set<std::string> seen;
  for (const auto& [frame, what] : log.events) {
    if (frame == 0 || !log.frames.count(frame) || !log.frames.count(frame - 1)) {
      expect(false, what + " at frame " + std::to_string(frame) + " has no frame before it");
      continue;
    }
    const FrameStatus &before = log.frames[frame - 1], &after = log.frames[frame];
    const std::string at = "frame " + std::to_string(frame) + ", " + what + ": ";
    if (what.rfind("tolerance", 0) == 0)
      seen.insert(after.tolerance > before.tolerance ? "+" : "-");
    else if (what.rfind("drag", 0) != 0)
      seen.insert(what);
    if (what == "wireframe on" || what == "wireframe off") {
      expect(after.wire == (what == "wireframe on") && before.wire != after.wire &&
                 after.triangles == before.triangles,
             at + "the line's ' wire' flips, the triangles stay");
    } else if (what.rfind("colour ", 0) == 0) {
      const std::map<std::string, std::string> next = {
          {"shaded", "patch"}, {"patch", "level"}, {"level", "shaded"}};
      expect(next.at(before.colour) == after.colour && what == "colour " + after.colour,
             at + before.colour + " -> " + after.colour);
    } else if (what.rfind("tolerance ", 0) == 0) {
      const bool coarser = after.tolerance == 2 * before.tolerance;
      const bool finer = after.tolerance == 0.5 * before.tolerance;
      expect(coarser ? after.triangles < before.triangles && after.error > before.error
                     : finer && after.triangles > before.triangles && after.error < before.error,
             at + std::to_string(before.triangles) + " -> " + std::to_string(after.triangles) +
                 " triangles, error " + std::to_string(before.error) + " -> " +
                 std::to_string(after.error) + " px");
    } else if (what == "frozen" || what == "unfrozen") {
      expect(after.frozen == (what == "frozen") && before.frozen != after.frozen,
             at + "the line's FROZEN flips");
    } else if (what.rfind("drag", 0) == 0) {
      double dx = 0, dy = 0, wheel = 0;
      std::sscanf(what.c_str(), "drag %lf %lf, wheel %lf", &dx, &dy, &wheel);
      dragX += dx;
      dragY += dy;
      if (dx != 0 || dy != 0) seen.insert("drag");
      const bool frozen = before.frozen && after.frozen;
      if (frozen)
        expect(after.triangles == before.triangles && after.error != before.error,
               at + "frozen: the triangles stay (" + std::to_string(after.triangles) +
                   "), the error moves (" + std::to_string(before.error) + " -> " +
                   std::to_string(after.error) + " px)");
      if (wheel != 0) seen.insert("wheel");
      if (wheel > 0 && frozen)
        expect(after.error > 1.1 * before.error,  // 2 steps: 0.81 the distance, ~1.23 the error
               at + "nearer, frozen: the error grows, " + std::to_string(before.error) +
                   " -> " + std::to_string(after.error) + " px");
      if (wheel != 0 && !frozen)
        expect(wheel > 0 ? after.triangles > before.triangles
                         : after.triangles < before.triangles,
               at + (wheel > 0 ? "nearer: " : "farther: ") + std::to_string(before.triangles) +
                   " -> " + std::to_string(after.triangles) + " triangles");
    } else if (what != "quit") {
      expect(false, at + "an event this check does not know");
    }
  }
  for (const char* needed : {"wireframe on", "wireframe off", "colour patch", "colour level",
                             "colour shaded", "+", "-", "frozen", "unfrozen", "drag", "wheel",
                             "quit"})
    expect(seen.count(needed) == 1, std::string("the log shows '") + needed + "'");
  size_t frozen = 0, frozenKept = 0;
  for (const auto& [frame, f] : log.frames)
    if (frame > 0 && f.frozen && log.frames[frame - 1].frozen) {
      ++frozen;
      frozenKept += f.triangles == log.frames[frame - 1].triangles;
    }
  expect(frozen > 0 && frozenKept == frozen,
         std::to_string(frozenKept) + " of " + std::to_string(frozen) +
             " frames after a frozen one keep its triangles");
}

// What keys_script.txt did, from the log (checkLogRules, and the run ends at Esc in frame 19)
// and the files:
// - the pictures: the wireframe's dark lines; the shaded, patch and level pictures in the
//   colours of their palettes (patch: several colours, level: its own palette); the drag turns
//   the picture although the mesh is frozen;
// - the meshes: frozen, a later frame's mesh equals the earlier one byte for byte, though the
//   camera moved; thawed, a drag gives a new mesh.
int checkKeys(const char* logPath, const std::string& dir) {
  KeysLog log;
  if (!readNonEmptyLog(logPath, log)) return 2;
  Checks expect;
  double dragX = 0, dragY = 0;
  checkLogRules(log, expect, dragX, dragY);
  expect(log.frames.rbegin()->first == 19, "the last frame is Esc's, 19");
  expect(dragX == 0 && dragY == -20, "the drags add up to the script's: 0, -20");
  try {
    int w = 0, h = 0;
    const std::vector<Rgb> filled = meshPixels(dir + "/keys_filled.png", w, h);
    const std::vector<Rgb> wire = meshPixels(dir + "/keys_wire.png", w, h);
    const double darkFilled = darkFraction(filled), darkWire = darkFraction(wire);
    expect(darkFilled < 0.005 && darkWire > 0.05 && filled.size() > 0.03 * w * h,
           "wireframe: dark line pixels " + std::to_string(100 * darkFilled) + "% of the " +
               "mesh filled, " + std::to_string(100 * darkWire) + "% with wires");
    using C = tessera::RenderOptions::Colour;
    const auto porcelain = palette(C::Shaded, 1), patch = palette(C::Patch, 10),
               level = palette(C::Depth, 11);
    // Each picture mostly in its own palette, using at least `used` of its colours, and not
    // in another (the porcelain is within 1 degree of a patch colour, so it is told apart from
    // the level palette).
    struct ColourCase {
      const char* file;
      const std::vector<std::array<uint8_t, 3>>* own;
      int minUsed;
      const std::vector<std::array<uint8_t, 3>>* other;
      const char* otherName;
    };
    const ColourCase cases[] = {{"keys_filled.png", &porcelain, 1, &level, "level"},
                                {"keys_patch.png", &patch, 6, &porcelain, "porcelain"},
                                {"keys_level.png", &level, 2, &patch, "patch"},
                                {"keys_shaded.png", &porcelain, 1, &level, "level"}};
    for (const ColourCase& c : cases) {
      const std::vector<Rgb> pixels = meshPixels(dir + "/" + c.file, w, h);
      const auto [share, used] = paletteMatch(pixels, *c.own);
      const auto [asOther, unused] = paletteMatch(pixels, *c.other);
      expect(share > 0.97 && used >= c.minUsed && asOther < 0.5,
             std::string(c.file) + ": " + std::to_string(100 * share) + "% in its palette, " +
                 std::to_string(used) + " of its colours (need " + std::to_string(c.minUsed) +
                 "), " + std::to_string(100 * asOther) + "% in the " + c.otherName + " palette");
    }
    const std::string before = fileBytes(dir + "/keys_before_drag.png");
    const std::string after = fileBytes(dir + "/keys_after_drag.png");
    const std::vector<Rgb> beforeMesh = meshPixels(dir + "/keys_before_drag.png", w, h);
    const std::vector<Rgb> afterMesh = meshPixels(dir + "/keys_after_drag.png", w, h);
    expect(before != after && beforeMesh.size() != afterMesh.size(),
           "the drag turns the view: " + std::to_string(beforeMesh.size()) + " -> " +
               std::to_string(afterMesh.size()) + " mesh pixels");
    const std::string frozenA = fileBytes(dir + "/keys_frozen_a.glb");
    const std::string frozenB = fileBytes(dir + "/keys_frozen_b.glb");
    const std::string thawedA = fileBytes(dir + "/keys_thawed_a.glb");
    const std::string thawedB = fileBytes(dir + "/keys_thawed_b.glb");
    expect(!frozenA.empty() && frozenA == frozenB,
           "frozen: the mesh after the drag is the mesh before it, byte for byte (" +
               std::to_string(frozenA.size()) + " bytes)");
    expect(thawedA != frozenB, "thawed: the mesh is made again for the turned camera");
    expect(thawedA != thawedB, "thawed: a drag gives a new mesh");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "viewer_check: %s\n", e.what());
    return 2;
  }
  return expect.exitCode();
}

}  // namespace

// The log of real X input (real_input.sh): checkLogRules, and the drags it reports add up to
// the one xdotool made.
int checkRealInput(const char* logPath, double dragX, double dragY) {
  KeysLog log;
  if (!readNonEmptyLog(logPath, log)) return 2;
  Checks expect;
  double x = 0, y = 0;
  checkLogRules(log, expect, x, y);
  expect(x == dragX && y == dragY, "the drags add up to " + std::to_string(x) + ", " +
                                       std::to_string(y) + ": the mouse's " +
                                       std::to_string(dragX) + ", " + std::to_string(dragY));
  return expect.exitCode();
}

int main(int argc, char** argv) {
  if (argc == 5 && std::strcmp(argv[1], "picture") == 0)
    return checkPicture(argv[2], std::atof(argv[3]), size_t(std::atol(argv[4])));
  if (argc == 3 && std::strcmp(argv[1], "mesh") == 0) return checkMesh(argv[2]);
  if (argc == 4 && std::strcmp(argv[1], "keys") == 0) return checkKeys(argv[2], argv[3]);
  if (argc == 5 && std::strcmp(argv[1], "keys-log") == 0)
    return checkRealInput(argv[2], std::atof(argv[3]), std::atof(argv[4]));
  std::fprintf(stderr, "usage: viewer_check picture SHOT.png MIN_MESH_FRACTION MIN_COLOURS\n"
                       "       viewer_check mesh FRAME.glb\n"
                       "       viewer_check keys LOG DIR\n"
                       "       viewer_check keys-log LOG DX DY\n");
  return 2;
}
