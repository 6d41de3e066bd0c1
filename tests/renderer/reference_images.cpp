// One small reference picture per drawing feature (tests/reference/renderer/*.png), each looked
// at before it was kept, checked with the suite's one reference check (tests/reference_check.hpp:
// no channel off by more than 2/255; with text, 0.01% of the pixels may be). Regenerate with
// SPLINEFIG_UPDATE_REFERENCES=1 and look at every changed image before committing it.
//
// A reference is the renderer's own earlier output, so each picture is also held, pixel by
// pixel, to values that do not come from the renderer: the items composited in order over the
// background, each with its exact coverage from the oracle (oracle/union_coverage.hpp: the
// union of the item's pieces, built here from the geometry; dashes are cut here by hand), or,
// under the tent and B-spline filters, the convolution of those pieces with the kernel written
// here from its closed form. The same values are asserted on the reference file itself, so a
// reference re-baselined from a wrong picture fails too. Pixels near an item that has no
// independent value (a dashed circle, two marker shapes, glyphs) are left out by a mask.
#include "reference_check.hpp"

#include <oracle/union_coverage.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <sstream>

namespace sr = splinefig::render;

namespace {

constexpr double kPi = 3.14159265358979323846;
const sr::Color kInk{0.02f, 0.02f, 0.05f, 1};

splinefig::Image check_reference(const std::string& name, sr::Scene& scene, bool text = false) {
  splinefig::Image img = sr::rasterize(scene, 2);
  CHECK_THAT(img, splinefig::testing::MatchesReference(reference_check::path("renderer/" + name + ".png"),
                                                       text ? reference_check::figure() : reference_check::drawing()));
  return img;
}

sr::StrokeStyle style(double width, sr::Join j = sr::Join::Miter, sr::Cap c = sr::Cap::Butt) {
  sr::StrokeStyle s;
  s.width = width;
  s.join = j;
  s.cap = c;
  return s;
}

// ---- the independent picture ---------------------------------------------------------------

using oracle::P2;
using oracle::Poly;

// One drawing call: its coverage in every pixel (row-major) and its colour.
struct Layer {
  std::vector<double> coverage;
  sr::Color ink;
};

std::vector<P2> pts(std::initializer_list<P2> p) { return p; }

oracle::Join ojoin(sr::Join j) { return j == sr::Join::Miter ? oracle::Join::Miter : j == sr::Join::Round ? oracle::Join::Round : oracle::Join::Bevel; }
oracle::Cap ocap(sr::Cap c) { return c == sr::Cap::Butt ? oracle::Cap::Butt : c == sr::Cap::Round ? oracle::Cap::Round : oracle::Cap::Square; }

std::vector<Poly> stroke(const std::vector<P2>& p, bool closed, double width, sr::Join j = sr::Join::Miter,
                         sr::Cap c = sr::Cap::Butt, double miter_limit = 4) {
  return oracle::stroke_pieces(p, closed, width, ojoin(j), miter_limit, ocap(c));
}

Poly disk(P2 c, double r) { return oracle::sector(c, r, 0, 2 * oracle::kPi); }

Poly rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Layer layer(const std::vector<Poly>& pieces, sr::Color ink, int w, int h) { return {oracle::union_coverage(pieces, w, h), ink}; }

// The open polyline `p` cut into its dashes (on/off lengths, the pattern started `offset` into
// itself), each a polyline keeping the vertices it runs through: the SVG rule, by hand.
std::vector<std::vector<P2>> dashes_of(const std::vector<P2>& p, const std::vector<double>& pattern, double offset) {
  std::vector<double> at{0};  // arc length at each vertex
  for (std::size_t i = 1; i < p.size(); ++i) at.push_back(at.back() + std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y));
  auto point_at = [&](double s) {
    std::size_t i = 1;
    while (i + 1 < p.size() && at[i] < s) ++i;
    const double t = (s - at[i - 1]) / (at[i] - at[i - 1]);
    return P2{p[i - 1].x + t * (p[i].x - p[i - 1].x), p[i - 1].y + t * (p[i].y - p[i - 1].y)};
  };
  double period = 0;
  for (double d : pattern) period += d;
  std::vector<std::vector<P2>> out;
  double s = -std::fmod(offset, period);
  for (std::size_t k = 0; s < at.back(); k = (k + 1) % pattern.size()) {
    const double a = std::max(s, 0.0), b = std::min(s + pattern[k], at.back());
    if (k % 2 == 0 && b > a) {
      std::vector<P2> d{point_at(a)};
      for (std::size_t i = 1; i + 1 < p.size(); ++i)
        if (at[i] > a && at[i] < b) d.push_back(p[i]);
      d.push_back(point_at(b));
      out.push_back(d);
    }
    s += pattern[k];
  }
  return out;
}

// IEC 61966-2-1, written here: the encoding the reference PNG holds.
double srgb_encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

// The layers composited in order over `bg` (linear light, straight colour, as the renderer
// blends), against the rendered picture (within 1e-3 of full scale: the arcs' flattening and
// float32) and against the reference file (8-bit sRGB: within 1.5/255 of the encoded value) at
// every pixel `checked` accepts. At least `min_partial` of them must be partly covered: edges,
// where a wrong picture differs.
void check_independent(const std::string& name, const splinefig::Image& img, const std::vector<Layer>& layers,
                       const std::function<bool(int, int)>& checked = {}, int min_partial = 20,
                       sr::Color bg = {1, 1, 1, 1}) {
  const splinefig::Image ref = splinefig::read_image(reference_check::path("renderer/" + name + ".png"));
  REQUIRE(ref.width == img.width);
  REQUIRE(ref.height == img.height);
  REQUIRE(ref.channels >= 3);
  int compared = 0, partial = 0, bad_img = 0, bad_ref = 0;
  std::ostringstream first;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (checked && !checked(x, y)) continue;
      ++compared;
      double out[3] = {bg.r, bg.g, bg.b};
      bool part = false;
      for (const Layer& l : layers) {
        const double c = l.coverage[std::size_t(y) * std::size_t(img.width) + std::size_t(x)];
        part = part || (c > 0.02 && c < 0.98);
        const double a = l.ink.a * c, ink[3] = {l.ink.r, l.ink.g, l.ink.b};
        for (int k = 0; k < 3; ++k) out[k] = ink[k] * a + out[k] * (1 - a);
      }
      partial += part;
      for (int k = 0; k < 3; ++k) {
        const double got = img.pixel(x, y)[k], stored = ref.pixel(x, y)[k];
        const bool img_off = std::abs(got - out[k]) > 1e-3, ref_off = std::abs(stored - srgb_encode(out[k])) > 1.5 / 255;
        if ((img_off && bad_img == 0) || (ref_off && bad_ref == 0))
          first << "pixel (" << x << ", " << y << ") channel " << k << ": expected " << out[k] << " (sRGB "
                << srgb_encode(out[k]) * 255 << "/255), rendered " << got << ", reference " << stored * 255 << "/255\n";
        bad_img += img_off;
        bad_ref += ref_off;
      }
    }
  INFO(name << ": " << compared << " pixels compared, " << partial << " partly covered\n" << first.str());
  CHECK(bad_img == 0);
  CHECK(bad_ref == 0);
  CHECK(partial >= min_partial);
}

// A filtered pixel value by hand: the pieces' union convolved with k(x) k(y) (unit integral)
// at the pixel centre, as a sum over cells of 1/32 px of the union's exact area in each cell
// times the kernel at the cell's centre.
double filtered(const std::vector<Poly>& pieces, int px, int py, const std::function<double(double)>& k, double radius) {
  const double cx = px + 0.5, cy = py + 0.5, h = 1.0 / 32;
  std::vector<Poly> near;
  for (const Poly& p : pieces) {
    Poly c = oracle::clip_to_box(p, cx - radius, cy - radius, cx + radius, cy + radius);
    if (c.size() >= 3) near.push_back(std::move(c));
  }
  const int n = int(std::lround(2 * radius / h));
  double sum = 0;
  std::vector<Poly> cell;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x0 = cx - radius + i * h, y0 = cy - radius + j * h;
      cell.clear();
      for (const Poly& p : near) {
        Poly c = oracle::clip_to_box(p, x0, y0, x0 + h, y0 + h);
        if (c.size() >= 3) cell.push_back(std::move(c));
      }
      if (cell.empty()) continue;
      sum += oracle::union_area(cell) * k(cx - (x0 + h / 2)) * k(cy - (y0 + h / 2));
    }
  return sum;
}

double tent(double x) { return std::max(0.0, 1 - std::abs(x)); }

double cubic_bspline(double x) {
  const double a = std::abs(x);
  return a < 1 ? (4 - 6 * a * a + 3 * a * a * a) / 6 : a < 2 ? (2 - a) * (2 - a) * (2 - a) / 6 : 0;
}

}  // namespace

TEST_CASE("reference: caps (butt, round, square) on thin and wide strokes") {
  sr::Scene s(120, 72);
  const sr::Cap caps[] = {sr::Cap::Butt, sr::Cap::Round, sr::Cap::Square};
  for (int i = 0; i < 3; ++i) {
    s.stroke_polyline(std::vector<sr::Vec2>{{20, 12.0 + 20 * i}, {60, 12.0 + 20 * i}}, false, style(10, sr::Join::Miter, caps[i]), kInk);
    s.stroke_polyline(std::vector<sr::Vec2>{{80.3, 8.0 + 20 * i}, {104.7, 17.0 + 20 * i}}, false, style(4.5, sr::Join::Miter, caps[i]), kInk);
    // the geometric ends, for the eye
    s.stroke_polyline(std::vector<sr::Vec2>{{20, 12.0 + 20 * i}, {60, 12.0 + 20 * i}}, false, style(0.6), {1, 0.2f, 0.2f, 1});
  }
  const auto img = check_reference("caps", s);
  std::vector<Layer> want;
  for (int i = 0; i < 3; ++i) {
    want.push_back(layer(stroke(pts({{20, 12.0 + 20 * i}, {60, 12.0 + 20 * i}}), false, 10, sr::Join::Miter, caps[i]), kInk, 120, 72));
    want.push_back(layer(stroke(pts({{80.3, 8.0 + 20 * i}, {104.7, 17.0 + 20 * i}}), false, 4.5, sr::Join::Miter, caps[i]), kInk, 120, 72));
    want.push_back(layer(stroke(pts({{20, 12.0 + 20 * i}, {60, 12.0 + 20 * i}}), false, 0.6), {1, 0.2f, 0.2f, 1}, 120, 72));
  }
  check_independent("caps", img, want);
}

TEST_CASE("reference: joins (miter, miter past its limit, round, bevel) with translucent ink") {
  sr::Scene s(160, 64);
  const sr::Join joins[] = {sr::Join::Miter, sr::Join::Miter, sr::Join::Round, sr::Join::Bevel};
  const double limits[] = {10, 1.5, 4, 4};
  for (int i = 0; i < 4; ++i) {
    double x = 10 + 38 * i;
    auto st = style(9, joins[i]);
    st.miter_limit = limits[i];
    s.stroke_polyline(std::vector<sr::Vec2>{{x, 54}, {x + 14, 12}, {x + 28, 54}}, false, st, {0.1f, 0.2f, 0.8f, 0.6f});
  }
  const auto img = check_reference("joins", s);
  std::vector<Layer> want;
  for (int i = 0; i < 4; ++i) {
    const double x = 10 + 38 * i;
    want.push_back(layer(stroke(pts({{x, 54}, {x + 14, 12}, {x + 28, 54}}), false, 9, joins[i], sr::Cap::Butt, limits[i]),
                         {0.1f, 0.2f, 0.8f, 0.6f}, 160, 64));
  }
  check_independent("joins", img, want);
}

TEST_CASE("reference: dashes continue across joints, with offset and round caps") {
  sr::Scene s(128, 80);
  auto st = style(4, sr::Join::Round, sr::Cap::Round);
  st.dashes = {12, 6};
  st.dash_offset = 3;
  s.stroke_polyline(std::vector<sr::Vec2>{{10, 10}, {118, 10}, {118, 40}, {10, 70}}, false, st, kInk);
  auto st2 = style(2, sr::Join::Miter, sr::Cap::Butt);
  st2.dashes = {1, 2, 6, 2};
  s.stroke_circle({40, 42}, 18, st2, {0.8f, 0.1f, 0.1f, 1});
  const auto img = check_reference("dashes", s);
  // The polyline's dashes, cut here; the dashed circle has no independent value: its ring is
  // left out.
  std::vector<Poly> pieces;
  for (const auto& d : dashes_of(pts({{10, 10}, {118, 10}, {118, 40}, {10, 70}}), {12, 6}, 3))
    for (Poly& p : stroke(d, false, 4, sr::Join::Round, sr::Cap::Round)) pieces.push_back(std::move(p));
  const auto off_ring = [](int x, int y) {
    const double r = std::hypot(x + 0.5 - 40, y + 0.5 - 42);
    return r < 15.5 || r > 20.5;
  };
  check_independent("dashes", img, {layer(pieces, kInk, 128, 80)}, off_ring);
}

TEST_CASE("reference: hairlines fade with their width instead of vanishing") {
  sr::Scene s(128, 64);
  for (int i = 0; i < 8; ++i) {
    double w = 0.1 + 0.13 * i;
    double x = 8 + 15 * i;
    s.stroke_polyline(std::vector<sr::Vec2>{{x, 4}, {x + 9.3, 60}}, false, style(w), kInk);
  }
  s.stroke_polyline(std::vector<sr::Vec2>{{2, 31.37}, {126, 33.9}}, false, style(0.25), kInk);
  const auto img = check_reference("hairlines", s);
  std::vector<Layer> want;
  for (int i = 0; i < 8; ++i) {
    const double w = 0.1 + 0.13 * i, x = 8 + 15 * i;
    want.push_back(layer(stroke(pts({{x, 4}, {x + 9.3, 60}}), false, w), kInk, 128, 64));
  }
  want.push_back(layer(stroke(pts({{2, 31.37}, {126, 33.9}}), false, 0.25), kInk, 128, 64));
  check_independent("hairlines", img, want);
}

TEST_CASE("reference: fills, nonzero and even-odd, and one path never blends with itself") {
  sr::Scene s(160, 80);
  auto star = [](double cx, double cy) {
    std::vector<sr::Vec2> p;
    for (int k = 0; k < 5; ++k) {
      double a = -kPi / 2 + k * 4 * kPi / 5;
      p.push_back({cx + 34 * std::cos(a), cy + 34 * std::sin(a)});
    }
    return p;
  };
  s.fill_polygon({star(40, 42)}, sr::FillRule::NonZero, {0.1f, 0.5f, 0.2f, 1});
  s.fill_polygon({star(120, 42)}, sr::FillRule::EvenOdd, {0.1f, 0.5f, 0.2f, 1});
  // a translucent self-crossing curve: uniform tone, no darker crossings or beads
  std::vector<sr::Vec2> curve;
  for (int k = 0; k <= 400; ++k) {
    double t = 2 * kPi * k / 400;
    curve.push_back({80 + 70 * std::sin(3 * t), 40 + 30 * std::sin(2 * t)});
  }
  s.stroke_polyline(curve, true, style(3, sr::Join::Round), {0.8f, 0.1f, 0.1f, 0.5f});
  const auto img = check_reference("fills", s);
  // Each edge of the star turns 144 degrees on about its centre, all the same way: the winding
  // number of a point is the number of the fan triangles (centre, p_k, p_k+1) that hold it. So
  // nonzero is their union, and even-odd (winding 1 only) is 2 * union - the sum of the five.
  auto fan = [&](double cx, double cy) {
    const auto p = star(cx, cy);
    std::vector<Poly> t;
    for (std::size_t k = 0; k < 5; ++k) t.push_back({{cx, cy}, {p[k].x, p[k].y}, {p[(k + 1) % 5].x, p[(k + 1) % 5].y}});
    return t;
  };
  const sr::Color green{0.1f, 0.5f, 0.2f, 1};
  Layer even_odd = layer(fan(120, 42), green, 160, 80);
  for (const Poly& t : fan(120, 42)) {
    const auto one = oracle::union_coverage({t}, 160, 80);
    for (std::size_t i = 0; i < one.size(); ++i) even_odd.coverage[i] -= one[i] / 2;
  }
  for (double& c : even_odd.coverage) c *= 2;
  std::vector<P2> ocurve;
  for (const auto& q : curve) ocurve.push_back({q.x, q.y});
  check_independent("fills", img,
                    {layer(fan(40, 42), green, 160, 80), even_odd,
                     layer(stroke(ocurve, true, 3, sr::Join::Round), {0.8f, 0.1f, 0.1f, 0.5f}, 160, 80)});
}

TEST_CASE("reference: markers and disks") {
  sr::Scene s(128, 40);
  const sr::Marker m[] = {sr::Marker::Circle, sr::Marker::Square, sr::Marker::Diamond, sr::Marker::Cross, sr::Marker::Plus};
  for (int i = 0; i < 5; ++i) s.marker(m[i], {14.0 + 25 * i, 14.3}, 15, kInk);
  for (int i = 0; i < 5; ++i) s.fill_circle({14.0 + 25 * i + 0.2 * i, 33}, 0.5 + 1.0 * i, {0.8f, 0.1f, 0.1f, 1});
  const auto img = check_reference("markers", s);
  // By the documented sizes: a circle of diameter 15, a square of side 15, a plus of arm span 15
  // with arms 15/4 thick; the diamond and cross are left out.
  const double cy = 14.3, r = 7.5, t = 15.0 / 8;
  std::vector<Layer> want{layer({disk({14, cy}, r)}, kInk, 128, 40), layer({rect(39 - r, cy - r, 39 + r, cy + r)}, kInk, 128, 40),
                          layer({rect(114 - r, cy - t, 114 + r, cy + t), rect(114 - t, cy - r, 114 + t, cy + r)}, kInk, 128, 40)};
  for (int i = 0; i < 5; ++i) want.push_back(layer({disk({14.0 + 25 * i + 0.2 * i, 33}, 0.5 + 1.0 * i)}, {0.8f, 0.1f, 0.1f, 1}, 128, 40));
  const auto not_diamond_or_cross = [](int x, int y) { return y > 24 || x < 53 || x > 101; };
  check_independent("markers", img, want, not_diamond_or_cross);
}

TEST_CASE("reference: the same shapes under box, tent and cubic B-spline pixel filters") {
  const auto bspline = splinefig::Kernel::piecewise(
      "bspline", -2, {{0, 0, 0, 1.0 / 6}, {1.0 / 6, 0.5, 0.5, -0.5}, {4.0 / 6, 0, -1, 0.5}, {1.0 / 6, -0.5, 0.5, -1.0 / 6}});
  int i = 0;
  for (const auto& f : {splinefig::Kernel::box(), splinefig::Kernel::tent(), bspline}) {
    sr::Scene s(64, 64, {1, 1, 1, 1}, f);
    s.stroke_polyline(std::vector<sr::Vec2>{{8, 56}, {20, 8}, {32, 56}, {56, 20}}, false, style(2.5, sr::Join::Round), kInk);
    s.fill_circle({44, 46}, 8, {0.8f, 0.1f, 0.1f, 1});
    s.stroke_polyline(std::vector<sr::Vec2>{{4, 4}, {60, 6}}, false, style(0.5), kInk);
    const std::string name = std::string("filter_") + (i == 0 ? "box" : i == 1 ? "tent" : "bspline");
    const auto img = check_reference(name, s);
    const std::vector<Layer> items{
        layer(stroke(pts({{8, 56}, {20, 8}, {32, 56}, {56, 20}}), false, 2.5, sr::Join::Round), kInk, 64, 64),
        layer({disk({44, 46}, 8)}, {0.8f, 0.1f, 0.1f, 1}, 64, 64), layer(stroke(pts({{4, 4}, {60, 6}}), false, 0.5), kInk, 64, 64)};
    if (i == 0) {
      check_independent(name, img, items);
    } else {
      // Chosen pixels under the tent (support 2 px) and the B-spline (4 px): each item's value
      // convolved by hand, at pixels only that item reaches: across the thin line, across the
      // polyline's first segment, across the disk's edge, inside it, and far from everything.
      const std::function<double(double)> k = i == 1 ? std::function<double(double)>(tent) : cubic_bspline;
      const double reach = i == 1 ? 1 : 2;
      const auto line = stroke(pts({{4, 4}, {60, 6}}), false, 0.5);
      const auto poly = stroke(pts({{8, 56}, {20, 8}, {32, 56}, {56, 20}}), false, 2.5, sr::Join::Round);
      const std::vector<Poly> round{disk({44, 46}, 8)};
      struct Probe {
        int x, y, item;
      };
      const Probe probes[] = {{44, 3, 0},  {44, 4, 0},  {44, 5, 0},  {11, 40, 1}, {12, 40, 1}, {13, 40, 1},
                              {51, 46, 2}, {52, 46, 2}, {44, 53, 2}, {44, 46, 2}, {2, 30, 1}};
      std::vector<Layer> want(3);
      for (int j = 0; j < 3; ++j) want[std::size_t(j)] = {std::vector<double>(64 * 64, 0.0), items[std::size_t(j)].ink};
      want[0].ink = kInk;
      for (const Probe& p : probes) {
        const auto& pieces = p.item == 0 ? line : p.item == 1 ? poly : round;
        const int layer_of = p.item == 0 ? 2 : p.item == 1 ? 0 : 1;
        want[std::size_t(layer_of)].coverage[std::size_t(p.y * 64 + p.x)] = filtered(pieces, p.x, p.y, k, reach);
      }
      const auto probed = [&](int x, int y) {
        for (const Probe& p : probes)
          if (p.x == x && p.y == y) return true;
        return false;
      };
      check_independent(name, img, want, probed, 3);
    }
    ++i;
  }
}

TEST_CASE("reference: text anchored left/centre/right at baseline/middle/top") {
  sr::Scene s(160, 72);
  s.stroke_polyline(std::vector<sr::Vec2>{{80, 0}, {80, 72}}, false, style(0.5), {1, 0.2f, 0.2f, 1});
  for (double y : {18.0, 40.0, 58.0})
    s.stroke_polyline(std::vector<sr::Vec2>{{0, y}, {160, y}}, false, style(0.5), {1, 0.2f, 0.2f, 1});
  sr::TextStyle t;
  t.size = 14;
  t.color = kInk;
  t.halign = sr::HAlign::Left;
  s.text("Left base", {80, 18}, t);
  t.halign = sr::HAlign::Center;
  t.valign = sr::VAlign::Middle;
  s.text("Centre middle", {80, 40}, t);
  t.halign = sr::HAlign::Right;
  t.valign = sr::VAlign::Top;
  s.text("Right top", {80, 58}, t);
  const auto img = check_reference("text", s, true);
  // The guide lines, where no glyph reaches: the rows above the text and the columns left of it.
  const sr::Color red{1, 0.2f, 0.2f, 1};
  std::vector<Layer> want{layer(stroke(pts({{80, 0}, {80, 72}}), false, 0.5), red, 160, 72)};
  for (double y : {18.0, 40.0, 58.0}) want.push_back(layer(stroke(pts({{0, y}, {160, y}}), false, 0.5), red, 160, 72));
  check_independent("text", img, want, [](int x, int y) { return y < 6 || x < 8; }, 6);
}
