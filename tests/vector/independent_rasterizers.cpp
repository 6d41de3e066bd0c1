// Every built-in figure's SVG rasterized by librsvg (rsvg-convert) and its PDF by poppler, with
// its Splash (pdftoppm) and its cairo (pdftocairo) backends, at the PNG's size, compared with
// splinefig's own PNG of the same scene: the PNG should look like its vector siblings as
// viewers show them. A figure with translucent fills (kTranslucent) joins the built-in ones.
//
// The peers composite sRGB-encoded values, as figures do by default ([canvas] blend = "srgb"),
// so flat colours, translucent fills and the weight of text agree; what stays is antialiasing
// (splinefig's coverage is the exact area, the peers' is their own estimate) on edge pixels,
// and where two antialiased edges share a pixel (splinefig composites coverage as opacity).
// Per figure, on the 8-bit values scaled to [0, 1]:
//   - the mean absolute difference over all pixels and channels: at most kMeanMax;
//   - flat colour: where the PNG's 3 x 3 neighbourhood is one colour (a fill's interior, the
//     background; no edge within a pixel), the largest difference: at most 1/255;
//   - ink: for each text box the layout placed (labels, tick labels, legends), the summed
//     darkness (1 - value) inside it: the PNG's within 3% of the peer's;
//   - outliers: under librsvg at most 0.08% of the pixels more than 0.25 off (a curve half a
//     pixel off or in another colour fails this; single pixels where edges meet differ by up
//     to 0.8); under cairo, whose dashes differ a little more, 0.2%.
// Splash antialiases with its own coverage curve (4 x 4 samples through a gamma of 1.5,
// splashAAGamma): its text carries 8-14% more ink than librsvg's, poppler's cairo backend's
// and the PNG's, and its edges differ more, so its bounds are 20% of ink and 0.4% of the
// pixels over 0.25. The rejection test at the end runs under librsvg.
// Blending in linear light fails all three (text carries 20-41% less ink, a translucent fill
// is lighter by up to 50/255, the mean difference doubles): a test case checks that.
// The rectangles of nearest-sampled raster items (a zone plate shown pixel for pixel) are
// left out: at 1x each peer samples them at its own phase (and librsvg 2.54 ignores
// image-rendering and interpolates them); tests/vector/pdf_images.cpp checks them.
// SPLINEFIG_VECTOR_REPORT=FILE writes each figure's numbers (both blend spaces) to FILE.
#include "figures/support.hpp"
#include "skip.hpp"

#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/vector/vector.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <variant>

namespace fig = splinefig::figures;
using splinefig::Image;

namespace {

bool have(const std::string& tool) { return figtest::run("command -v " + tool).code == 0; }

constexpr double kMeanMax = 0.004;   // mean absolute difference
constexpr double kFlatMax = 1.0 / 255 + 1e-6;

// What a peer may differ by besides the mean and flat colours: the relative ink of a text box,
// and the percentage of the pixels more than 0.25 off.
struct Bounds {
  double ink, over;
};
Bounds bounds(const std::string& tool) {
  if (tool == "pdftoppm") return {0.20, 0.4};
  if (tool == "pdftocairo") return {0.03, 0.2};
  return {0.03, 0.08};
}

// Translucent fills over each other, a curve and the axes' texts: its flat interiors are where
// the blend space shows (the built-in figures have no translucent fill; their legend boxes are
// translucent white over white).
const char* const kTranslucent = R"([canvas]
width = 480
height = 320

[axes]
title = "Translucent fills"
x_label = "$x$"
y_label = "$y$"
x_range = [0, 10]
y_range = [0, 10]
legend = "upper right"

[[axes.fill]]
points = [[1, 1], [7, 1], [7, 7], [1, 7]]
color = "#1f77b480"
label = "blue at 0x80"

[[axes.fill]]
points = [[4, 3], [9, 3], [9, 9], [4, 9]]
color = "#d6272866"
label = "red at 0x66"

[[axes.fill]]
points = [[2, 5], [6, 5], [6, 8.5], [2, 8.5]]
color = "#2ca02c40"

[[axes.series]]
x = [0, 2, 4, 6, 8, 10]
y = [2, 6, 3, 8, 4, 6]
color = "#333333"
label = "series"
)";

struct Outcome {
  double mean = 0;        // mean absolute difference
  double over = 0;        // percentage of the pixels differing by more than 0.25 in a channel
  double max = 0;         // the largest difference
  double flat = 0;        // largest difference where the PNG is flat (3 x 3)
  double ink = 0;         // largest relative ink difference over the text boxes
  std::string ink_box;    // which box
  int boxes = 0;          // text boxes with ink measured
};

bool within(const Outcome& r, const std::string& tool) {
  const Bounds b = bounds(tool);
  return r.mean <= kMeanMax && r.flat <= kFlatMax && r.ink <= b.ink && r.over <= b.over;
}

// 0 inside the scene's nearest-sampled raster items, 1 elsewhere.
Image raster_mask(const splinefig::render::Scene& scene) {
  Image mask = Image::zeros(scene.width(), scene.height(), 1);
  std::fill(mask.pixels.begin(), mask.pixels.end(), 1.0f);
  for (const splinefig::render::DrawItem& item : scene.items()) {
    const auto* im = std::get_if<splinefig::render::ImageItem>(&item);
    if (!im || im->sampling != splinefig::render::Sampling::Nearest) continue;
    const auto p0 = im->p0, p1 = im->p1;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(p0.x, p1.x)))),
              x1 = std::min(mask.width, static_cast<int>(std::ceil(std::max(p0.x, p1.x))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(p0.y, p1.y)))),
              y1 = std::min(mask.height, static_cast<int>(std::ceil(std::max(p0.y, p1.y))));
    for (int j = y0; j < y1; ++j)
      for (int i = x0; i < x1; ++i) mask.at(i, j, 0) = 0;
  }
  return mask;
}

// The text boxes of every panel, in pixels (left, top, right, bottom).
std::vector<std::pair<std::string, std::array<double, 4>>> text_boxes(const fig::FigureInfo& info) {
  std::vector<std::pair<std::string, std::array<double, 4>>> out;
  for (const auto& a : info.axes)
    for (const auto& t : a.text_boxes) out.emplace_back(t.what, t.box);
  return out;
}

// The PNG (8-bit sRGB as stored) against the peer's rendering of the same size.
Outcome compare(const std::string& png, const std::string& peer_file, const Image& mask,
                const std::vector<std::pair<std::string, std::array<double, 4>>>& boxes) {
  const Image a = splinefig::read_image(png, splinefig::ReadMode::as_stored);
  const Image b = splinefig::read_image(peer_file, splinefig::ReadMode::as_stored);
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  const int w = a.width, h = a.height;
  auto va = [&](int i, int j, int c) { return static_cast<double>(a.at(i, j, std::min(c, a.channels - 1))); };
  auto vb = [&](int i, int j, int c) { return static_cast<double>(b.at(i, j, std::min(c, b.channels - 1))); };
  Outcome r;
  double sum = 0;
  long n = 0, pixels = 0, over = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (mask.at(i, j, 0) == 0) continue;
      bool flat = i > 0 && j > 0 && i + 1 < w && j + 1 < h;
      for (int dj = -1; flat && dj <= 1; ++dj)
        for (int di = -1; flat && di <= 1; ++di)
          for (int c = 0; c < 3; ++c)
            if (va(i + di, j + dj, c) != va(i, j, c) || mask.at(i + di, j + dj, 0) == 0) flat = false;
      double most = 0;
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(va(i, j, c) - vb(i, j, c));
        sum += d;
        ++n;
        most = std::max(most, d);
        if (flat) r.flat = std::max(r.flat, d);
      }
      ++pixels;
      if (most > 0.25) ++over;
      r.max = std::max(r.max, most);
    }
  r.mean = n ? sum / static_cast<double>(n) : 0;
  r.over = pixels ? 100.0 * static_cast<double>(over) / static_cast<double>(pixels) : 0;
  for (const auto& [what, box] : boxes) {
    // The pixels whose centres lie in the box grown by a pixel (antialiased glyph edges).
    const int x0 = std::max(0, static_cast<int>(std::floor(box[0] - 1))), x1 = std::min(w, static_cast<int>(std::ceil(box[2] + 1)));
    const int y0 = std::max(0, static_cast<int>(std::floor(box[1] - 1))), y1 = std::min(h, static_cast<int>(std::ceil(box[3] + 1)));
    double ink_a = 0, ink_b = 0;
    for (int j = y0; j < y1; ++j)
      for (int i = x0; i < x1; ++i) {
        if (mask.at(i, j, 0) == 0) continue;
        for (int c = 0; c < 3; ++c) ink_a += 1 - va(i, j, c), ink_b += 1 - vb(i, j, c);
      }
    if (std::max(ink_a, ink_b) < 3) continue;  // no ink to speak of (a box over an empty place)
    ++r.boxes;
    const double rel = std::abs(ink_a - ink_b) / std::max(ink_b, 3.0);
    if (rel > r.ink) r.ink = rel, r.ink_box = what;
  }
  return r;
}

// A peer rendering of the vector file at the PNG's size.
std::string peer_png(const std::string& tool, const std::string& file, const figtest::fs::path& dir, const std::string& stem) {
  const std::string out = (dir / (stem + "." + tool + ".png")).string();
  std::string cmd;
  if (tool == "rsvg-convert") cmd = "rsvg-convert -o " + out + " " + file;
  else cmd = tool + " -png -singlefile -r 96 " + file + " " + out.substr(0, out.size() - 4);
  const auto r = figtest::run(cmd);
  INFO(cmd << "\n" << r.out);
  REQUIRE(r.code == 0);
  return out;
}

const char* tool_format(const std::string& tool) { return tool == "rsvg-convert" ? "svg" : "pdf"; }

// One figure as its spec blends it, or in `blend`: its PNG and vector file, the peer's
// rendering, the comparison.
Outcome measure(const std::string& tool, const fig::SpecFile& s, std::optional<splinefig::render::BlendSpace> blend,
                const figtest::fs::path& dir) {
  fig::FigureSpec spec = fig::load_spec(s.path);
  if (blend) spec.canvas.blend = *blend;
  const fig::FigureScene f = fig::figure_scene(spec, 1);
  std::optional<Image> raster;
  const std::string format = tool_format(tool);
  const std::string png = (dir / (s.name + ".png")).string(), vec = (dir / (s.name + "." + format)).string();
  fig::write_figure_file(f, png, fig::Format::png, {}, raster);
  fig::write_figure_file(f, vec, *fig::format_named(format), {}, raster);
  return compare(png, peer_png(tool, vec, dir, s.name), raster_mask(f.scene), text_boxes(f.info));
}

void report_line(const std::string& tool, const std::string& name, const char* blend, const Outcome& r) {
  const char* path = std::getenv("SPLINEFIG_VECTOR_REPORT");
  if (!path || !*path) return;
  std::ofstream out(path, std::ios::app);
  out << tool << '\t' << name << '\t' << blend << '\t' << r.mean << '\t' << r.flat << '\t' << r.ink << '\t' << r.ink_box << '\t' << r.over << '\t' << r.max << '\n';
}

// The built-in figures and kTranslucent (written into `dir`).
std::vector<fig::SpecFile> figures_compared(const figtest::fs::path& dir) {
  std::vector<fig::SpecFile> out = fig::list_specs(fig::builtin_specs_dir());
  const std::string path = (dir / "translucent.toml").string();
  std::ofstream(path) << kTranslucent;
  out.push_back({"translucent", path});
  return out;
}

void check_every_figure(const std::string& tool) {
  if (!have(tool)) {
    splinefig::testing_support::skip(tool + " is not installed");
    return;
  }
  const auto dir = figtest::scratch("vector-" + tool);
  for (const fig::SpecFile& s : figures_compared(dir)) {
    const Outcome r = measure(tool, s, std::nullopt, dir);  // the default blend
    report_line(tool, s.name, "srgb", r);
    INFO(s.name << " via " << tool << ": mean " << r.mean << ", flat max " << r.flat << " (" << r.flat * 255
                << "/255), ink " << 100 * r.ink << "% (" << r.ink_box << "), " << r.over << "% of the pixels over 0.25, max "
                << r.max);
    CHECK(within(r, tool));
  }
}

}  // namespace

TEST_CASE("every built-in figure's SVG, rasterized by librsvg, looks like its PNG") { check_every_figure("rsvg-convert"); }

TEST_CASE("every built-in figure's PDF, rasterized by poppler (Splash), looks like its PNG") { check_every_figure("pdftoppm"); }

TEST_CASE("every built-in figure's PDF, rasterized by poppler (cairo), looks like its PNG") { check_every_figure("pdftocairo"); }

TEST_CASE("blended in linear light, no built-in figure's PNG looks like its SVG and PDF") {
  // The same comparison with [canvas] blend = "linear" fails on every figure with text or a
  // translucent fill (the zone plates have neither in their panels' text boxes): its text is
  // lighter, its translucent fills too. Its mean difference is at least twice the sRGB
  // blend's, over all figures and figure by figure (under Splash, whose own coverage curve
  // differs from either blend on every edge, at least 1 / 0.6 times).
  for (const std::string tool : {"rsvg-convert", "pdftoppm", "pdftocairo"}) {
    if (!have(tool)) {
      splinefig::testing_support::skip(tool + " is not installed");
      continue;
    }
    const auto dir = figtest::scratch("vector-linear-" + tool);
    const double ratio = tool == "pdftoppm" ? 0.6 : 0.5;
    double sum_lin = 0, sum_srgb = 0;
    for (const fig::SpecFile& s : figures_compared(dir)) {
      const Outcome lin = measure(tool, s, splinefig::render::BlendSpace::linear, dir);
      const Outcome srgb = measure(tool, s, splinefig::render::BlendSpace::srgb, dir);
      report_line(tool, s.name, "linear", lin);
      INFO(s.name << " via " << tool << ": linear mean " << lin.mean << ", flat " << lin.flat * 255 << "/255, ink "
                  << 100 * lin.ink << "% over " << lin.boxes << " boxes; srgb mean " << srgb.mean);
      if (lin.boxes > 0 || s.name == "translucent") CHECK_FALSE(within(lin, tool));
      CHECK(srgb.mean <= ratio * lin.mean);
      sum_lin += lin.mean;
      sum_srgb += srgb.mean;
    }
    INFO(tool << ": mean over the figures, linear " << sum_lin << ", srgb " << sum_srgb << " (sums)");
    CHECK(sum_srgb <= sum_lin / 2);
  }
}

namespace {

namespace r = splinefig::render;

// The scene recorded again with one change: text left out, every exact curve moved down by
// `dy`, or the first exact curve drawn in `recolour`.
struct Altered {
  r::Scene out;
  bool drop_text = false;
  double dy = 0;
  std::optional<r::Color> recolour;
  explicit Altered(const r::Scene& s) : out(s.width(), s.height(), s.background(), s.filter()) {}
  void operator()(const r::StrokeItem& it) { out.stroke_polyline(it.points, it.closed, it.style, it.color); }
  void operator()(const r::FillItem& it) { out.fill_polygon(it.contours, it.rule, it.color); }
  void operator()(const r::PathFillItem& it) { out.fill_path(*it.path, it.rule, it.color); }
  void operator()(const r::PathStrokeItem& it) {
    r::Color c = it.color;
    if (recolour) c = *recolour, recolour.reset();
    out.stroke_path(it.path->transformed(1, 0, 0, 1, 0, dy), it.style, c);
  }
  void operator()(const r::DiskItem& it) { out.fill_circle(it.centre, it.radius, it.color); }
  void operator()(const r::RingItem& it) { out.stroke_circle(it.centre, it.radius, it.style, it.color); }
  void operator()(const r::MarkerItem& it) { out.marker(it.shape, it.centre, it.size, it.color); }
  void operator()(const r::TextItem& it) {
    if (!drop_text) out.text(it.text, it.anchor, it.style);
  }
  void operator()(const r::ImageItem& it) { out.image(it.image, it.p0, it.p1, it.sampling); }
};

}  // namespace

TEST_CASE("the tolerance rejects a figure without text, a curve half a pixel off, a curve in another red") {
  const fig::FigureSpec spec = fig::load_spec(fig::builtin_specs_dir() + "/cbasis.toml");
  const fig::FigureScene f = fig::figure_scene(spec, 1);
  for (const std::string tool : {"rsvg-convert"}) {
    if (!have(tool)) {
      splinefig::testing_support::skip(tool + " is not installed");
      continue;
    }
    const auto dir = figtest::scratch("vector-negative-" + tool);
    std::optional<Image> raster;
    const std::string png = (dir / "cbasis.png").string();
    fig::write_figure_file(f, png, fig::Format::png, {}, raster);
    const Image none = raster_mask(f.scene);  // no raster items: all ones
    auto outcome = [&](Altered& a, const std::string& stem) {
      for (const r::DrawItem& item : f.scene.items()) std::visit(a, item);
      const std::string vec = (dir / (stem + "." + tool_format(tool))).string();
      splinefig::vector::write_vector(vec, a.out);
      const Outcome r = compare(png, peer_png(tool, vec, dir, stem), none, text_boxes(f.info));
      INFO(stem << " via " << tool << ": mean " << r.mean << ", flat " << r.flat * 255 << "/255, ink " << 100 * r.ink
                << "%, " << r.over << "% of the pixels over 0.25, max " << r.max);
      report_line(tool, "cbasis-" + stem, "srgb", r);
      return within(r, tool);
    };
    Altered same(f.scene);
    CHECK(outcome(same, "same"));
    Altered no_text(f.scene);
    no_text.drop_text = true;
    CHECK_FALSE(outcome(no_text, "no-text"));
    Altered moved(f.scene);
    moved.dy = 0.5;
    CHECK_FALSE(outcome(moved, "moved"));
    Altered red(f.scene);
    red.recolour = *r::parse_hex_color("#c03030");
    CHECK_FALSE(outcome(red, "red"));
  }
}
