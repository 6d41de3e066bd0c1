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

// 0 inside the scene's nearest-sampled raster items, 1 elsewhere.
struct RasterMask final : splinefig::render::SceneVisitor {
  using Vec2 = splinefig::render::Vec2;
  Image mask;
  explicit RasterMask(int w, int h) : mask(Image::zeros(w, h, 1)) { std::fill(mask.pixels.begin(), mask.pixels.end(), 1.0f); }
  void stroke_polyline(std::span<const Vec2>, bool, const splinefig::render::StrokeStyle&, splinefig::render::Color) override {}
  void fill_polygon(const std::vector<std::vector<Vec2>>&, splinefig::render::FillRule, splinefig::render::Color) override {}
  void fill_path(const splinefig::render::Path&, splinefig::render::FillRule, splinefig::render::Color) override {}
  void stroke_path(const splinefig::render::Path&, const splinefig::render::StrokeStyle&, splinefig::render::Color) override {}
  void fill_circle(Vec2, double, splinefig::render::Color) override {}
  void stroke_circle(Vec2, double, const splinefig::render::StrokeStyle&, splinefig::render::Color) override {}
  void marker(splinefig::render::Marker, Vec2, double, splinefig::render::Color) override {}
  void text(std::string_view, Vec2, const splinefig::render::TextStyle&, const splinefig::render::Path&) override {}
  void image(const Image&, Vec2 p0, Vec2 p1, splinefig::render::Scene::Sampling s) override {
    if (s != splinefig::render::Scene::Sampling::Nearest) return;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(p0.x, p1.x)))) ,
              x1 = std::min(mask.width, static_cast<int>(std::ceil(std::max(p0.x, p1.x))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(p0.y, p1.y)))),
              y1 = std::min(mask.height, static_cast<int>(std::ceil(std::max(p0.y, p1.y))));
    for (int j = y0; j < y1; ++j)
      for (int i = x0; i < x1; ++i) mask.at(i, j, 0) = 0;
  }
};

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
    RasterMask m(f.info.width, f.info.height);
    if (tool == "rsvg-convert") f.scene.visit(m);
    const Outcome r = compare(png, downsampled(peer_png(tool, vec, dir, s.name), f.info.width, f.info.height), &m.mask);
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
struct Altered final : r::SceneVisitor {
  r::Scene out;
  bool drop_text = false;
  double dy = 0;
  std::optional<r::Color> recolour;
  explicit Altered(const r::Scene& s) : out(s.width(), s.height(), s.background(), s.filter()) {}
  void stroke_polyline(std::span<const r::Vec2> p, bool closed, const r::StrokeStyle& st, r::Color c) override {
    out.stroke_polyline(p, closed, st, c);
  }
  void fill_polygon(const std::vector<std::vector<r::Vec2>>& c, r::FillRule rule, r::Color col) override { out.fill_polygon(c, rule, col); }
  void fill_path(const r::Path& p, r::FillRule rule, r::Color c) override { out.fill_path(p, rule, c); }
  void stroke_path(const r::Path& p, const r::StrokeStyle& st, r::Color c) override {
    if (recolour) c = *recolour, recolour.reset();
    out.stroke_path(p.transformed(1, 0, 0, 1, 0, dy), st, c);
  }
  void fill_circle(r::Vec2 c, double rad, r::Color col) override { out.fill_circle(c, rad, col); }
  void stroke_circle(r::Vec2 c, double rad, const r::StrokeStyle& st, r::Color col) override { out.stroke_circle(c, rad, st, col); }
  void marker(r::Marker m, r::Vec2 c, double size, r::Color col) override { out.marker(m, c, size, col); }
  void text(std::string_view t, r::Vec2 a, const r::TextStyle& st, const r::Path&) override {
    if (!drop_text) out.text(t, a, st);
  }
  void image(const Image& im, r::Vec2 p0, r::Vec2 p1, r::Scene::Sampling smp) override {
    out.image(std::make_shared<const Image>(im), p0, p1, smp);
  }
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
    f.scene.visit(a);
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
