// Offscreen rendering (host/render/offscreen.h) and the PNG writer (host/io/png_writer.h). The pictures
// are judged by counting pixels: how much of the frame the teapot covers, how many pixels
// change between tessellations, colourings and the wireframe. Thresholds are loose on purpose
// (what a working renderer gives on any driver), and every test prints what it measured.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

// The decoder, to read the PNGs back (test only; static, so no symbol can clash).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb_image.h>

#include "gpu_test_context.h"
#include "io/bpt_reader.h"
#include "io/png_writer.h"
#include "render/offscreen.h"
#include "mesh/tessellate.h"
#include "scratch_dir.h"

using namespace tessera;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 480, kHeight = 360;

// The teapot at the CLI's default thresholds, tessellated once per method on the GPU.
const Tessellation& teapot(SplitRule rule) {
  static std::map<SplitRule, Tessellation> cache;  // a map: references stay valid
  auto found = cache.find(rule);
  if (found != cache.end()) return found->second;
  static const std::vector<BezierPatch> patches = readBpt(TESSERA_SOURCE_DIR "/data/teapot.bpt");
  Backend backend = makeVulkanBackend(test::gpuContext());
  QuadtreeOptions options;
  options.rule = rule;
  return cache.emplace(rule, tessellate(patches, options, backend)).first->second;
}

RenderOptions smallPicture(RenderOptions::Colour colour, bool wireframe = false) {
  RenderOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.colour = colour;
  options.wireframe = wireframe;
  // One camera for both methods' meshes (their boxes differ in the last bits).
  BoundingBox frame = boundingBox(teapot(SplitRule::Midpoint).mesh);
  frame.add(boundingBox(teapot(SplitRule::TrueMax).mesh));
  options.frame = frame;
  return options;
}

bool isBackground(const std::vector<uint8_t>& rgba, size_t pixel) {
  for (int c = 0; c < 4; ++c)
    if (rgba[4 * pixel + c] != kRenderBackground[c]) return false;
  return true;
}

double coveredFraction(const std::vector<uint8_t>& rgba) {
  size_t covered = 0, pixels = rgba.size() / 4;
  for (size_t p = 0; p < pixels; ++p) covered += !isBackground(rgba, p);
  return double(covered) / double(pixels);
}

double differingFraction(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  REQUIRE(a.size() == b.size());
  size_t differing = 0, pixels = a.size() / 4;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c)
      if (a[4 * p + c] != b[4 * p + c]) {
        ++differing;
        break;
      }
  return double(differing) / double(pixels);
}

std::vector<uint8_t> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

}  // namespace

TEST_CASE("render: the shaded teapot fills part of the frame and touches no edge",
          "[gpu][render]") {
  vk::Context& context = test::gpuContext();
  const Tessellation& t = teapot(SplitRule::Midpoint);
  std::vector<uint8_t> rgba =
      renderMesh(context, t.mesh, {}, smallPicture(RenderOptions::Colour::Shaded));
  REQUIRE(rgba.size() == size_t(kWidth) * kHeight * 4);
  double covered = coveredFraction(rgba);
  WARN("teapot (B, " << t.stats.triangles << " triangles) covers " << covered * 100
                     << "% of a " << kWidth << "x" << kHeight << " picture");
  CHECK(covered > 0.15);
  CHECK(covered < 0.75);
  // The camera fits the whole bounding box with a margin: the border rows and columns stay
  // background, so nothing of the teapot is cut off.
  size_t borderCovered = 0;
  for (int x = 0; x < kWidth; ++x)
    borderCovered += !isBackground(rgba, x) + !isBackground(rgba, size_t(kHeight - 1) * kWidth + x);
  for (int y = 0; y < kHeight; ++y)
    borderCovered += !isBackground(rgba, size_t(y) * kWidth) +
                     !isBackground(rgba, size_t(y) * kWidth + kWidth - 1);
  CHECK(borderCovered == 0);

  // Without multisampling (no resolve attachment): the same silhouette, give or take its
  // anti-aliased edge pixels.
  RenderOptions single = smallPicture(RenderOptions::Colour::Shaded);
  single.samples = 1;
  double coveredSingle = coveredFraction(renderMesh(context, t.mesh, {}, single));
  CHECK(std::abs(coveredSingle - covered) < 0.01);
  test::requireValidationClean();
}

TEST_CASE("render: depth colouring tells methods B and D apart", "[gpu][render]") {
  vk::Context& context = test::gpuContext();
  const Tessellation& b = teapot(SplitRule::Midpoint);
  const Tessellation& d = teapot(SplitRule::TrueMax);
  std::vector<float> levelsB = triangleLevels(b), levelsD = triangleLevels(d);
  // Every triangle lies in a leaf, and the deepest leaves have triangles.
  REQUIRE(levelsB.size() == b.mesh.triangleCount());
  CHECK(*std::max_element(levelsB.begin(), levelsB.end()) == float(b.stats.depth));
  CHECK(*std::max_element(levelsD.begin(), levelsD.end()) == float(d.stats.depth));

  RenderOptions options = smallPicture(RenderOptions::Colour::Depth);
  std::vector<uint8_t> pictureB = renderMesh(context, b.mesh, levelsB, options);
  std::vector<uint8_t> pictureD = renderMesh(context, d.mesh, levelsD, options);
  double coverB = coveredFraction(pictureB), coverD = coveredFraction(pictureD);
  double differing = differingFraction(pictureB, pictureD);
  WARN("depth colouring: B depth " << b.stats.depth << ", D depth " << d.stats.depth
                                   << "; covered " << coverB * 100 << "% and " << coverD * 100
                                   << "%; " << differing * 100 << "% of the pixels differ");
  // One surface, one camera: the silhouettes agree to a sliver of edge pixels ...
  CHECK(std::abs(coverB - coverD) < 0.01);
  // ... while the levels, hence the colours, differ over a good part of the teapot.
  CHECK(differing > 0.05);

  // The depth picture is not the shaded one.
  std::vector<uint8_t> shaded =
      renderMesh(context, b.mesh, {}, smallPicture(RenderOptions::Colour::Shaded));
  CHECK(differingFraction(shaded, pictureB) > 0.5 * coverB);
  test::requireValidationClean();
}

TEST_CASE("render: the wireframe darkens the triangle edges", "[gpu][render]") {
  vk::Context& context = test::gpuContext();
  const Tessellation& t = teapot(SplitRule::Midpoint);
  std::vector<float> patches = trianglePatchIds(t);
  std::vector<uint8_t> plain =
      renderMesh(context, t.mesh, patches, smallPicture(RenderOptions::Colour::Patch));
  std::vector<uint8_t> wired =
      renderMesh(context, t.mesh, patches, smallPicture(RenderOptions::Colour::Patch, true));
  double differing = differingFraction(plain, wired);
  uint64_t sumPlain = 0, sumWired = 0;
  for (size_t i = 0; i < plain.size(); ++i)
    if (i % 4 != 3) sumPlain += plain[i], sumWired += wired[i];
  WARN("wireframe: " << differing * 100 << "% of the pixels change, mean brightness "
                     << sumPlain / (plain.size() * 0.75) << " -> "
                     << sumWired / (wired.size() * 0.75));
  CHECK(differing > 0.03);
  CHECK(sumWired < sumPlain);
  // Lines only on the mesh: the background is untouched.
  CHECK(std::abs(coveredFraction(plain) - coveredFraction(wired)) < 1e-9);
  test::requireValidationClean();
}

TEST_CASE("render: an empty mesh gives the background; bad options are refused",
          "[gpu][render]") {
  vk::Context& context = test::gpuContext();
  RenderOptions options;
  options.width = 64;
  options.height = 32;
  std::vector<uint8_t> rgba = renderMesh(context, TriangleMesh{}, {}, options);
  REQUIRE(rgba.size() == 64 * 32 * 4);
  CHECK(coveredFraction(rgba) == 0.0);

  const TriangleMesh& mesh = teapot(SplitRule::Midpoint).mesh;
  RenderOptions bad = options;
  bad.width = 0;
  CHECK_THROWS_AS(renderMesh(context, mesh, {}, bad), std::invalid_argument);
  bad = options;
  bad.samples = 3;
  CHECK_THROWS_AS(renderMesh(context, mesh, {}, bad), std::invalid_argument);
  bad = options;
  bad.colour = RenderOptions::Colour::Depth;  // needs levels
  CHECK_THROWS_AS(renderMesh(context, mesh, {}, bad), std::invalid_argument);
  CHECK_THROWS_AS(renderMesh(context, mesh, {1.0f, 2.0f}, options), std::invalid_argument);
  test::requireValidationClean();
}

TEST_CASE("render: a rendered teapot written as PNG reads back pixel for pixel",
          "[gpu][render]") {
  vk::Context& context = test::gpuContext();
  const Tessellation& t = teapot(SplitRule::TrueMax);
  std::vector<uint8_t> rgba = renderMesh(context, t.mesh, triangleLevels(t),
                                         smallPicture(RenderOptions::Colour::Depth, true));
  test::ScratchDir dir("render");
  fs::path path = dir.path / "teapot.png";
  writePngFile(path.string(), rgba, kWidth, kHeight);
  std::vector<uint8_t> file = readBytes(path);
  WARN("PNG of " << kWidth << "x" << kHeight << ": " << file.size() << " bytes");
  REQUIRE(file.size() > sizeof kPngSignature);
  CHECK(std::equal(std::begin(kPngSignature), std::end(kPngSignature), file.begin()));
  // Compressed (a flat background), yet more than a blank picture would take.
  CHECK(file.size() > 5000);
  CHECK(file.size() < rgba.size() / 2);

  int w = 0, h = 0, channels = 0;
  stbi_uc* decoded = stbi_load_from_memory(file.data(), int(file.size()), &w, &h, &channels, 4);
  REQUIRE(decoded != nullptr);
  std::vector<uint8_t> back(decoded, decoded + size_t(w) * h * 4);
  stbi_image_free(decoded);
  CHECK(w == kWidth);
  CHECK(h == kHeight);
  CHECK(back == rgba);
  test::requireValidationClean();
}

TEST_CASE("png: signature, round trip, and refused extents", "[render][png]") {
  const int w = 7, h = 5;
  std::vector<uint8_t> rgba(w * h * 4);
  for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t(i * 37);
  test::ScratchDir dir("render");
  fs::path path = dir.path / "tiny.png";
  writePngFile(path.string(), rgba, w, h);
  std::vector<uint8_t> file = readBytes(path);
  REQUIRE(file.size() > 8 + 25 + 12);  // signature, IHDR chunk, IEND chunk
  CHECK(std::equal(std::begin(kPngSignature), std::end(kPngSignature), file.begin()));
  int dw = 0, dh = 0, channels = 0;
  stbi_uc* decoded = stbi_load_from_memory(file.data(), int(file.size()), &dw, &dh, &channels, 4);
  REQUIRE(decoded != nullptr);
  CHECK(std::vector<uint8_t>(decoded, decoded + w * h * 4) == rgba);
  stbi_image_free(decoded);

  CHECK_THROWS_AS(writePngFile((dir.path / "bad.png").string(), rgba, w + 1, h),
                  std::invalid_argument);
  CHECK_THROWS_AS(writePngFile((dir.path / "bad.png").string(), rgba, 0, h),
                  std::invalid_argument);
  CHECK_FALSE(fs::exists(dir.path / "bad.png"));
}
