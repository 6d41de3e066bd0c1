// Every built-in figure's SVG rasterized by librsvg (rsvg-convert) and its PDF by poppler
// (pdftoppm), compared with splinefig's own PNG of the same scene.
//
// The peers antialias differently: they blend edge coverage in sRGB, splinefig in linear light
// with exact areas, so a 1x comparison differs by up to 0.3 on every edge pixel. The peers
// therefore rasterize at 4x, and their pixels are averaged 4 x 4 in linear light: that is a
// supersampled estimate of exact-area coverage, whose error lies only on the 4x edge pixels
// (a quarter of an edge's width). What stays is
//   - the sRGB blending of those 4x edge pixels: at most ~0.08 on a 1x edge pixel;
//   - where two antialiased edges share a pixel (curves crossing, a marker on a line),
//     splinefig composites coverage as opacity (no geometry between items is known), the
//     supersampled peers see the true overlap: up to ~0.35 on those few pixels.
// librsvg 2.54 ignores image-rendering and always interpolates raster items, so its check
// leaves out the rectangles of nearest-sampled raster items (a zone plate shown pixel for
// pixel); poppler honours the PDF's /Interpolate false and its check covers them.
// So the tolerance: at most 0.6% of the pixels may differ by more than 0.1 (26/255), no pixel by
// more than 0.6, and the mean difference stays below 0.003. A figure without its text, a curve
// moved by half a pixel or a wrong colour of one series fails it (the negative checks below).
#include "figures/support.hpp"
#include "skip.hpp"

#include <splinefig/compare/compare.hpp>
#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/vector/vector.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

namespace fig = splinefig::figures;
using splinefig::Image;

namespace {

bool have(const std::string& tool) { return figtest::run("command -v " + tool).code == 0; }

constexpr int kZoom = 4;

// The peer's 4x image averaged kZoom x kZoom in linear light, sRGB-encoded again: what the PNG
// holds, as float.
Image downsampled(const std::string& path, int w, int h) {
  const Image hi = splinefig::read_image(path, splinefig::ReadMode::linear);
  REQUIRE(hi.width >= w * kZoom);
  REQUIRE(hi.height >= h * kZoom);
  Image out(w, h, 3, splinefig::Encoding::srgb);
  const int nc = hi.channels;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int y = 0; y < kZoom; ++y)
          for (int x = 0; x < kZoom; ++x) sum += hi.pixel(i * kZoom + x, j * kZoom + y)[std::min(c, nc - 1)];
        out.at(i, j, c) = splinefig::linear_to_srgb(static_cast<float>(sum / (kZoom * kZoom)));
      }
  return out;
}

struct Outcome {
  double over_percent, max, mean;
};

// 0 inside the scene's nearest-sampled raster items (with `images`), 1 elsewhere.
Image raster_mask(const splinefig::render::Scene& scene, bool images) {
  Image mask = Image::zeros(scene.width(), scene.height(), 1);
  std::fill(mask.pixels.begin(), mask.pixels.end(), 1.0f);
  if (!images) return mask;
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

Outcome compare(const std::string& png, const Image& peer, const Image* mask) {
  const Image ours = splinefig::read_image(png, splinefig::ReadMode::as_stored);
  splinefig::compare::Options o;
  o.ignore_alpha = true;
  o.thresholds.fail = 0.1f;
  o.thresholds.warn = 0.1f;
  const auto c = splinefig::compare::compare_images(ours, peer, o, mask);
  REQUIRE_FALSE(c.sizes_differ);
  return {100.0 * static_cast<double>(c.metrics.nfail) / static_cast<double>(c.metrics.npels), c.metrics.max_error,
          c.metrics.mean_error};
}

bool within(const Outcome& r) { return r.over_percent <= 0.6 && r.max <= 0.6 && r.mean <= 0.003; }

// A peer rendering of the vector file at kZoom times the PNG's size.
std::string peer_png(const std::string& tool, const std::string& file, const figtest::fs::path& dir, const std::string& stem) {
  const std::string out = (dir / (stem + "." + tool + ".png")).string();
  std::string cmd;
  if (tool == "rsvg-convert") cmd = "rsvg-convert -z " + std::to_string(kZoom) + " -o " + out + " " + file;
  else cmd = "pdftoppm -png -singlefile -r " + std::to_string(96 * kZoom) + " " + file + " " + out.substr(0, out.size() - 4);
  const auto r = figtest::run(cmd);
  INFO(cmd << "\n" << r.out);
  REQUIRE(r.code == 0);
  return out;
}

void check_every_figure(const std::string& tool, const std::string& format) {
  if (!have(tool)) {
    splinefig::testing_support::skip(tool + " is not installed");
    return;
  }
  const auto dir = figtest::scratch("vector-" + format);
  for (const fig::SpecFile& s : fig::list_specs(fig::builtin_specs_dir())) {
    const fig::FigureSpec spec = fig::load_spec(s.path);
    const fig::FigureScene f = fig::figure_scene(spec, 1);
    std::optional<Image> raster;
    const std::string png = (dir / (s.name + ".png")).string(), vec = (dir / (s.name + "." + format)).string();
    fig::write_figure_file(f, png, fig::Format::png, {}, raster);
    fig::write_figure_file(f, vec, *fig::format_named(format), {}, raster);
    // librsvg's nearest sampling of an image is left out of the comparison; poppler's is not.
    const Image mask = raster_mask(f.scene, tool == "rsvg-convert");
    const Outcome r = compare(png, downsampled(peer_png(tool, vec, dir, s.name), f.info.width, f.info.height), &mask);
    INFO(s.name << " via " << tool << ": " << r.over_percent << "% of the pixels over 0.1, max " << r.max << ", mean "
                << r.mean);
    CHECK(within(r));
  }
}

}  // namespace

TEST_CASE("every built-in figure's SVG, rasterized by librsvg, matches its PNG") { check_every_figure("rsvg-convert", "svg"); }

TEST_CASE("every built-in figure's PDF, rasterized by poppler, matches its PNG") { check_every_figure("pdftoppm", "pdf"); }

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
  if (!have("rsvg-convert")) {
    splinefig::testing_support::skip("rsvg-convert is not installed");
    return;
  }
  const auto dir = figtest::scratch("vector-negative");
  const fig::FigureSpec spec = fig::load_spec(fig::builtin_specs_dir() + "/cbasis.toml");
  const fig::FigureScene f = fig::figure_scene(spec, 1);
  std::optional<Image> raster;
  const std::string png = (dir / "cbasis.png").string();
  fig::write_figure_file(f, png, fig::Format::png, {}, raster);
  auto outcome = [&](Altered& a, const std::string& stem) {
    for (const r::DrawItem& item : f.scene.items()) std::visit(a, item);
    const std::string svg = (dir / (stem + ".svg")).string();
    splinefig::vector::write_vector(svg, a.out);
    return compare(png, downsampled(peer_png("rsvg-convert", svg, dir, stem), f.info.width, f.info.height), nullptr);
  };
  Altered same(f.scene);
  CHECK(within(outcome(same, "same")));
  Altered no_text(f.scene);
  no_text.drop_text = true;
  CHECK_FALSE(within(outcome(no_text, "no-text")));
  Altered moved(f.scene);
  moved.dy = 0.5;
  CHECK_FALSE(within(outcome(moved, "moved")));
  Altered red(f.scene);
  red.recolour = *r::parse_hex_color("#c03030");
  CHECK_FALSE(within(outcome(red, "red")));
}
