// `tessera render`: tessellate on the GPU, draw the mesh offscreen with Vulkan, write a PNG.
// --side-by-side draws one panel per method with one shared camera, each labelled.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include <stb_easy_font.h>

#include "cli/cad_job.h"
#include "cli/cli_support.h"
#include "cli/commands.h"
#include "cli/outputs.h"
#include "cli/stdio.h"
#include "io/surface_reader.h"
#include "io/errors.h"
#include "render/offscreen.h"
#include "shaders/layout.h"
#include "mesh/screen_tolerance.h"
#include "mesh/tessellate.h"
#include "quadtree/tolerance.h"
#include "vk/context.h"

namespace tessera::cli {
namespace {

struct RenderArgs {
  std::string input;
  std::string output;
  std::string method = "B";
  std::string sideBySide;
  float linearity = 0.1f;
  float flatness = 0.1f;
  uint32_t maxDepth = 12;
  std::string colour = "shaded";
  bool wireframe = false;
  std::string size = "1024x768";
  std::string device;
  bool quiet = false;
  std::string tolerance;  // rule T: model units, a percentage, or pixels for the picture's camera
  bool methodGiven = false;  // -m on the command line (not its default)
};

struct Panel {
  SplitRule rule;
  Tessellation tessellation;
  std::vector<uint8_t> pixels;
};

SplitRule parseMethod(const std::string& name, const char* option) {
  try {
    return parseSplitRule(name);
  } catch (const std::invalid_argument&) {
    throw CLI::ValidationError(option, "unknown method '" + name + "' (expected A, B, C or D)");
  }
}

RenderOptions::Colour parseColour(const std::string& name) {
  if (name == "shaded") return RenderOptions::Colour::Shaded;
  if (name == "depth") return RenderOptions::Colour::Depth;
  if (name == "patch") return RenderOptions::Colour::Patch;
  throw CLI::ValidationError("--colour", "expected shaded, depth or patch, got '" + name + "'");
}

void parseSize(const std::string& text, RenderOptions& options) {
  int w = 0, h = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 ||
      w > kMaxRenderExtent || h > kMaxRenderExtent)
    throw CLI::ValidationError("--size", "expected WxH with each in 1.." +
                                             std::to_string(kMaxRenderExtent) + ", got '" +
                                             text + "'");
  options.width = w;
  options.height = h;
}

// One RGBA8 picture being annotated on the CPU.
struct Canvas {
  std::vector<uint8_t>& rgba;
  int width, height;

  void fill(int x0, int y0, int x1, int y1, std::array<uint8_t, 3> colour) {
    for (int y = std::max(y0, 0); y < std::min(y1, height); ++y)
      for (int x = std::max(x0, 0); x < std::min(x1, width); ++x) {
        uint8_t* p = &rgba[(size_t(y) * width + x) * 4];
        p[0] = colour[0], p[1] = colour[1], p[2] = colour[2], p[3] = 255;
      }
  }

  // `text` from the top-left corner (x, y), in stb_easy_font's quads scaled by `scale`.
  void text(int x, int y, int scale, const std::string& text) {
    std::vector<char> chars(text.begin(), text.end());
    chars.push_back('\0');
    std::vector<char> quads(300 * chars.size());  // stb asks ~270 bytes per character
    int count = stb_easy_font_print(0, 0, chars.data(), nullptr, quads.data(), int(quads.size()));
    struct QuadVertex {
      float x, y, z;
      unsigned char colour[4];
    };
    const auto* v = reinterpret_cast<const QuadVertex*>(quads.data());
    for (int q = 0; q < count; ++q) {
      const QuadVertex* c = v + 4 * q;  // axis-aligned: corners 0 and 2 are opposite
      fill(x + int(std::min(c[0].x, c[2].x) * scale), y + int(std::min(c[0].y, c[2].y) * scale),
           x + int(std::max(c[0].x, c[2].x) * scale), y + int(std::max(c[0].y, c[2].y) * scale),
           {30, 30, 30});
    }
  }

  // A row of swatches with their level under them, bottom left.
  void depthLegend(int deepest, int scale) {
    const int box = 10 * scale, step = 14 * scale, margin = 6 * scale;
    int y = height - margin - box - 10 * scale;
    text(margin, y - 10 * scale, scale, "quad-tree level");
    for (int level = 0; level <= deepest && level < gpu::kDepthPaletteSize; ++level) {
      int x = margin + level * step;
      fill(x - 1, y - 1, x + box + 1, y + box + 1, {30, 30, 30});
      fill(x, y, x + box, y + box, paletteColour(RenderOptions::Colour::Depth, level));
      bool last = level == gpu::kDepthPaletteSize - 1 && deepest > level;
      text(x, y + box + 2 * scale, scale, std::to_string(level) + (last ? "+" : ""));
    }
  }
};

std::string panelLabel(const Panel& panel) {
  const TessellationStats& s = panel.tessellation.stats;
  std::ostringstream label;
  label << "method " << splitRuleLetter(panel.rule) << ": " << s.leaves << " leaves, "
        << s.triangles << " triangles, depth " << s.depth;
  return label.str();
}

// A CAD model (issue 17, cad_job.h): the options that do not apply are a bad command line
// here; the model is meshed and drawn by renderCadModel.
int renderCad(const RenderArgs& a, RenderOptions options) {
  ToleranceSpec spec;
  checkCommandLine([&] {
    if (!a.sideBySide.empty())
      throw std::invalid_argument("--side-by-side: a CAD model is meshed one way (to a tolerance)");
    if (a.methodGiven && a.method != "T" && a.method != "t")
      throw std::invalid_argument("-m " + a.method +
                                  ": a CAD model is meshed to a tolerance (rule T); leave out -m");
    if (options.colour == RenderOptions::Colour::Depth)
      throw std::invalid_argument("--colour depth: a CAD model's faces have no single quad-tree "
                                  "level; use shaded or patch (by face)");
    if (!a.tolerance.empty()) spec = parseTolerance(a.tolerance);
    if (spec.pixels)
      throw std::invalid_argument("--tolerance '" + a.tolerance +
                                  "': a CAD model takes a distance or a percentage, not pixels");
  });
  CadRenderCommand c;
  c.input = a.input;
  c.output = a.output;
  c.device = a.device;
  c.tolerance = spec;
  c.options = options;
  c.quiet = a.quiet;
  return renderCadModel(c);
}

int run(const RenderArgs& a) {
  RenderOptions options;
  options.colour = parseColour(a.colour);
  options.wireframe = a.wireframe;
  parseSize(a.size, options);
  if (isCadInput(a.input)) return renderCad(a, options);
  std::vector<SplitRule> rules;
  if (a.sideBySide.empty()) {
    rules.push_back(parseMethod(a.method, "--method"));
  } else {
    std::stringstream list(a.sideBySide);
    for (std::string item; std::getline(list, item, ',');)
      rules.push_back(parseMethod(item, "--side-by-side"));
    if (rules.size() < 2)
      throw CLI::ValidationError("--side-by-side", "expected two or more methods, e.g. B,D");
  }

  // --tolerance: rule T, one panel. In pixels it is for the picture's own camera, framed on
  // the control points' box (the surface lies in their hull) before tessellating.
  std::optional<ToleranceSpec> tolerance;
  checkCommandLine([&] {
    if (a.tolerance.empty()) return;
    if (!a.sideBySide.empty())
      throw std::invalid_argument("--tolerance makes one picture; it does not go with "
                                  "--side-by-side");
    if (a.methodGiven && rules.front() != SplitRule::Tolerance)
      throw std::invalid_argument("--tolerance sets the δ of rule T; it does not go with -m " +
                                  a.method + " (leave out -m, or give -m T)");
    tolerance = parseTolerance(a.tolerance);
    rules = {SplitRule::Tolerance};
  });

  std::vector<QuadtreeOptions> panelOptions;
  for (SplitRule rule : rules) {
    // δ is resolved once the input is read (a percentage needs the model's size).
    QuadtreeOptions q = tolerance ? toleranceOptions(1.0) : QuadtreeOptions{};
    q.rule = rule;
    q.linearity = a.linearity;
    q.flatness = a.flatness;
    if (!tolerance) q.maxDepth = a.maxDepth;
    checkCommandLine([&] { validateQuadtreeOptions(q); });  // exit 1 before any work
    panelOptions.push_back(q);
  }

  checkOutputs({{"input", a.input}}, {{"-o", a.output}});
  std::vector<BezierPatch> patches = readSurfaceFile(a.input);

  vk::ContextOptions vkOptions;
  vkOptions.device = a.device;
  vk::Context context(vkOptions);
  if (!context.queueSupportsGraphics())
    throw vk::VulkanUnavailable("device '" + context.info().name +
                                "' cannot draw (no graphics queue); choose another with --device");
  Backend backend = makeVulkanBackend(context);

  std::vector<Panel> panels;
  BoundingBox frame;
  if (tolerance && tolerance->pixels) {
    for (const BezierPatch& p : patches)
      for (size_t k = 0; k < p.cp.size(); ++k)
        if (p.weights.empty() || p.weights[k] > 0.0) frame.add(glm::vec3(p.cp[k]));
    ScreenView view;
    view.camera.viewProjection = glm::dmat4(frameViewProjection(frame, options));
    view.camera.width = options.width;
    view.camera.height = options.height;
    panels.push_back(
        {SplitRule::Tolerance,
         tessellateScreenTolerance(patches, toleranceOptions(tolerance->value), view, backend),
         {}});
  } else {
    for (QuadtreeOptions q : panelOptions) {
      if (tolerance) q.tolerance = resolveTolerance(*tolerance, patches);
      panels.push_back({q.rule, tessellate(patches, q, backend), {}});
      frame.add(boundingBox(panels.back().tessellation.mesh));
    }
  }
  if (!frame.empty()) options.frame = frame;  // one camera for every panel

  for (Panel& panel : panels) {
    const Tessellation& t = panel.tessellation;
    std::vector<float> values;
    if (options.colour == RenderOptions::Colour::Depth)
      values = triangleLevels(t);
    else if (options.colour == RenderOptions::Colour::Patch)
      values = trianglePatchIds(t);
    panel.pixels = renderMesh(context, t.mesh, values, options);
  }

  // Panels left to right, a 2-pixel rule between them.
  const int gap = panels.size() > 1 ? 2 : 0;
  const int width = int(panels.size()) * options.width + (int(panels.size()) - 1) * gap;
  const int height = options.height;
  std::vector<uint8_t> picture(size_t(width) * height * 4, 200);
  const int scale = std::max(1, (options.height + 120) / 240);  // 2 at 480 rows, 3 at 600
  uint32_t deepest = 0;
  for (const Panel& panel : panels) deepest = std::max(deepest, panel.tessellation.stats.depth);
  for (size_t k = 0; k < panels.size(); ++k) {
    int x0 = int(k) * (options.width + gap);
    Canvas canvas{panels[k].pixels, options.width, height};
    if (panels.size() > 1) canvas.text(6 * scale, 6 * scale, scale, panelLabel(panels[k]));
    if (options.colour == RenderOptions::Colour::Depth) canvas.depthLegend(int(deepest), scale);
    for (int y = 0; y < height; ++y)
      std::copy_n(&panels[k].pixels[size_t(y) * options.width * 4], size_t(options.width) * 4,
                  &picture[(size_t(y) * width + x0) * 4]);
  }
  const bool toStdout = a.output == kStdioPath;
  writePicture(a.output, picture, width, height);

  if (!a.quiet) {
    FILE* const to = toStdout ? stderr : stdout;  // never into the picture
    if (tolerance)
      std::fprintf(to, "%s: %zu patches, tolerance %s, on %s\n", a.input.c_str(), patches.size(),
                   a.tolerance.c_str(), context.info().name.c_str());
    else
      std::fprintf(to, "%s: %zu patches, linearity %g, flatness %g, on %s\n", a.input.c_str(),
                   patches.size(), a.linearity, a.flatness, context.info().name.c_str());
    for (const Panel& panel : panels) std::fprintf(to, "%s\n", panelLabel(panel).c_str());
    std::fprintf(to, "wrote %s (%dx%d)\n", toStdout ? kStdoutName : a.output.c_str(), width,
                 height);
  }
  return kExitOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
  static RenderArgs args;
  CLI::App* cmd = app.add_subcommand(
      "render", "Tessellate a surface file on the GPU and draw it offscreen to a PNG (needs Vulkan)");
  cmd->add_option("input", args.input,
                  "input surface file (.bpt, .grid or .json), or a CAD model (.step/.stp, "
                  ".iges/.igs, .brep)")
      ->required();
  cmd->add_option("-o,--output", args.output, "output picture (.png); - writes it to standard output")->required();
  CLI::Option* method = cmd->add_option("-m,--method", args.method,
                  "split rule: A uniform grid, B midpoint, C sampled κ max, D true κ max")
      ->capture_default_str();
  cmd->add_option("--side-by-side", args.sideBySide,
                  "methods to draw next to each other with one camera, e.g. B,D (overrides --method)");
  cmd->add_option("--linearity", args.linearity, "edge linearity threshold (1 - Ti·Tj)")
      ->capture_default_str();
  cmd->add_option("--flatness", args.flatness, "flatness threshold (1 - Ni·Nj)")
      ->capture_default_str();
  cmd->add_option("--max-depth", args.maxDepth, "maximum quad-tree depth")->capture_default_str();
  cmd->add_option("--colour", args.colour,
                  "shaded, depth (quad-tree level of each triangle's leaf) or patch")
      ->capture_default_str();
  cmd->add_flag("--wireframe", args.wireframe, "draw the triangle edges");
  cmd->add_option("--size", args.size, "picture size WxH (per panel with --side-by-side)")
      ->capture_default_str();
  cmd->add_option("--device", args.device, "Vulkan device index or part of its name");
  cmd->add_flag("-q,--quiet", args.quiet, "print nothing on success");
  cmd->add_option("--tolerance", args.tolerance,
                  "rule T instead of -m: in model units (0.01), a percentage of the size (0.1%), "
                  "or in pixels of this picture (1px: the tree is made for its camera)");
  cmd->callback([&exitCode, method] {
    args.methodGiven = method->count() > 0;
    exitCode = runReportingErrors([] { return run(args); }, {args.output, kStdoutName},
                                  "render needs a Vulkan device that draws");
  });
}

}  // namespace tessera::cli
