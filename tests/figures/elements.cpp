// Each element kind of the spec format, rendered from tests/figures/data/elements.toml and
// checked where its pixels must be: data maps from the figure's own axes info (the same
// numbers index.json holds), expected colours worked out from the spec's values.
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/image/srgb.hpp>

#include <cmath>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

struct Rendered {
  RenderedFigure r;
  // 8-bit sRGB of pixel (x, y) (the image is opaque), in either blend space's encoding.
  std::array<int, 3> srgb(double x, double y) const {
    const float* p = r.image.pixel(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
    const bool linear = r.image.encoding == Encoding::linear;
    std::array<int, 3> out{};
    for (int k = 0; k < 3; ++k) out[k] = static_cast<int>(std::lround(255 * (linear ? splinefig::linear_to_srgb(p[k]) : p[k])));
    return out;
  }
  Vec2 at(size_t axes, double x, double y) const {
    const AxesInfo& a = r.info.axes.at(axes);
    return {a.x_map().to_pixel(x), a.y_map().to_pixel(y)};
  }
};

Rendered render_elements() {
  FigureSpec spec = load_spec(std::string(SPLINEFIG_SOURCE_DIR) + "/tests/figures/data/elements.toml");
  return {render_figure(spec, {1, 2})};
}

int srgb8(double linear) { return static_cast<int>(std::lround(255 * splinefig::linear_to_srgb(static_cast<float>(linear)))); }

bool near(std::array<int, 3> a, std::array<int, 3> b, int tol = 2) {
  return std::abs(a[0] - b[0]) <= tol && std::abs(a[1] - b[1]) <= tol && std::abs(a[2] - b[2]) <= tol;
}

}  // namespace

TEST_CASE("elements: fills blend in sRGB, images land on their extent") {
  Rendered f = render_elements();
  REQUIRE(f.r.info.axes.size() == 4);
  // Fill #2ca02c at alpha 0x80/255 over white, blending the sRGB-encoded values (the default):
  // a * c + (1 - a) * 255 in codes, 0x2c -> 149.1, 0xa0 -> 207.3.
  const double a = 128.0 / 255;
  auto over = [&](int v) { return static_cast<int>(std::lround(a * v + (1 - a) * 255)); };
  std::array<int, 3> expected{over(0x2c), over(0xa0), over(0x2c)};
  Vec2 q = f.at(0, 1.3, 0.7);
  CHECK(near(f.srgb(q.x, q.y), expected));
  // Image [[0, 0.25], [0.5, 1]] (linear grey) on extent x, y in [1, 3]: row 0 at the top.
  Vec2 tl = f.at(3, 1.5, 2.5), tr = f.at(3, 2.5, 2.5), bl = f.at(3, 1.5, 1.5), br = f.at(3, 2.5, 1.5);
  CHECK(near(f.srgb(tl.x, tl.y), {0, 0, 0}, 0));
  CHECK(near(f.srgb(tr.x, tr.y), {srgb8(0.25), srgb8(0.25), srgb8(0.25)}, 1));
  CHECK(near(f.srgb(bl.x, bl.y), {srgb8(0.5), srgb8(0.5), srgb8(0.5)}, 1));
  CHECK(near(f.srgb(br.x, br.y), {255, 255, 255}, 0));
  // Just outside the extent: background.
  Vec2 out = f.at(3, 0.9, 2.5);
  CHECK(near(f.srgb(out.x, out.y), {255, 255, 255}, 0));
}

TEST_CASE("elements: log and dB axes place data by their transfer") {
  Rendered f = render_elements();
  const AxesInfo& log = f.r.info.axes.at(1);
  CHECK(log.y_scale == Scale::Log);
  // 0.1 is two decades above 1e-3 of the four in [1e-3, 10]: half way up.
  const double y = log.pixel_box[3] + 0.5 * (log.pixel_box[1] - log.pixel_box[3]);
  CHECK(log.y_map().to_pixel(0.1) == Approx(y));
  CHECK(near(f.srgb(log.x_map().to_pixel(2), y), {0x1f, 0x77, 0xb4}, 3));  // the marker there
  const AxesInfo& db = f.r.info.axes.at(2);
  CHECK(db.y_scale == Scale::Decibel);
  // Magnitude 0.1 = -20 dB, 1/3 of the way down [-60, 0].
  const double ydb = db.pixel_box[1] + (db.pixel_box[3] - db.pixel_box[1]) / 3;
  CHECK(db.y_map().transfer(0.1) == Approx(-20));
  CHECK(db.y_map().to_pixel(0.1) == Approx(ydb));
  // The orange line (#ff7f0e) runs through it; the grey vline, drawn after it, covers that
  // point, so the line is checked one tenth further on, at -24 dB (straight in dB between the
  // samples at 0.5 and 1: -20 - 40 * 0.1 / 0.5).
  Vec2 p{db.x_map().to_pixel(0.6), db.y_map().to_pixel(std::pow(10.0, -24.0 / 20))};
  auto c = f.srgb(p.x, p.y);
  CHECK(c[0] > 200);
  CHECK(c[2] < 120);
  // The series leaves the range below -60 dB: nothing orange under the box.
  for (int yy = static_cast<int>(db.pixel_box[3]) + 3; yy < static_cast<int>(db.pixel_box[3]) + 12; ++yy)
    for (int xx = static_cast<int>(db.pixel_box[0]); xx < static_cast<int>(db.pixel_box[2]); ++xx) {
      auto px = f.srgb(xx, yy);
      bool orange = px[0] > 200 && px[2] < 150 && px[1] < 200;
      if (orange) FAIL("orange at " << xx << "," << yy);
    }
}

TEST_CASE("elements: pixel-space primitives, even-odd holes and the legend's series") {
  Rendered f = render_elements();
  CHECK(near(f.srgb(175, 468), {255, 255, 255}, 0));   // the hole of the even-odd ring
  CHECK(near(f.srgb(162, 462), {0x7f, 0x7f, 0x7f}, 0));  // the ring
  CHECK(near(f.srgb(35, 470), {0x17, 0xbe, 0xcf}, 1));   // 3 px polyline centred on y = 470
  CHECK(near(f.srgb(90, 468), {0xbc, 0xbd, 0x22}, 1));   // the circle's fill
  CHECK(near(f.srgb(608, 28), {0, 0, 0}, 0));            // image [[1, 0], [0, 1]] at (600, 4), 32 px:
  CHECK(near(f.srgb(624, 28), {255, 255, 255}, 0));      // row 1 is black, then white
  CHECK(near(f.srgb(624, 12), {0, 0, 0}, 0));
  const auto& series = f.r.info.axes.at(0).series;
  REQUIRE(series.size() == 4);
  CHECK(series[0].label == "area");
  CHECK(series[0].color == "#2ca02c");
  CHECK(series[3].label == "limit");
  CHECK(series[3].kind == "rule");
}

TEST_CASE("elements: data far outside the canvas (1e12) is clipped, not a hang or a crash") {
  FigureSpec spec = parse_spec(R"(
[canvas]
width = 200
height = 150
[axes]
x_range = [0, 1]
y_range = [0, 1]
[[axes.curve]]
knots = [[0, 0], [1e12, 1], [0.5, -1e12], [1, 1], [0.2, 0.3]]
label = "far"
label_position = "inline"
[[axes.series]]
points = [[1e12, 1e12], [0.5, 0.5], [-1e12, 3]]
style = "line+markers"
label = "far too"
[[polyline]]
points = [[-1e12, 5], [1e12, 100]]
width = 2
)",
                               "far.toml");
  RenderedFigure r = render_figure(spec, {1, 1});
  CHECK(r.image.width == 200);
  // The pixel-space line from (-1e12, 5) to (1e12, 100) crosses x = 100 at y = 52.5.
  CHECK(r.image.pixel(100, 52)[0] < 0.1f);
}
