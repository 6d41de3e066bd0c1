// One small reference picture per drawing feature (tests/reference/renderer/*.png), each looked
// at before it was kept, checked with the suite's one reference check (tests/reference_check.hpp:
// no channel off by more than 2/255; with text, 0.01% of the pixels may be). Regenerate with
// SPLINEFIG_UPDATE_REFERENCES=1 and look at every changed image before committing it.
#include "reference_check.hpp"

#include <splinefig/renderer/renderer.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

namespace sr = splinefig::render;

namespace {

constexpr double kPi = 3.14159265358979323846;
const sr::Color kInk{0.02f, 0.02f, 0.05f, 1};

void check_reference(const std::string& name, sr::Scene& scene, bool text = false) {
  const splinefig::Image img = sr::rasterize(scene, 2);
  CHECK_THAT(img, splinefig::testing::MatchesReference(reference_check::path("renderer/" + name + ".png"),
                                                       text ? reference_check::figure() : reference_check::drawing()));
}

sr::StrokeStyle style(double width, sr::Join j = sr::Join::Miter, sr::Cap c = sr::Cap::Butt) {
  sr::StrokeStyle s;
  s.width = width;
  s.join = j;
  s.cap = c;
  return s;
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
  check_reference("caps", s);
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
  check_reference("joins", s);
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
  check_reference("dashes", s);
}

TEST_CASE("reference: hairlines fade with their width instead of vanishing") {
  sr::Scene s(128, 64);
  for (int i = 0; i < 8; ++i) {
    double w = 0.1 + 0.13 * i;
    double x = 8 + 15 * i;
    s.stroke_polyline(std::vector<sr::Vec2>{{x, 4}, {x + 9.3, 60}}, false, style(w), kInk);
  }
  s.stroke_polyline(std::vector<sr::Vec2>{{2, 31.37}, {126, 33.9}}, false, style(0.25), kInk);
  check_reference("hairlines", s);
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
  check_reference("fills", s);
}

TEST_CASE("reference: markers and disks") {
  sr::Scene s(128, 40);
  const sr::Marker m[] = {sr::Marker::Circle, sr::Marker::Square, sr::Marker::Diamond, sr::Marker::Cross, sr::Marker::Plus};
  for (int i = 0; i < 5; ++i) s.marker(m[i], {14.0 + 25 * i, 14.3}, 15, kInk);
  for (int i = 0; i < 5; ++i) s.fill_circle({14.0 + 25 * i + 0.2 * i, 33}, 0.5 + 1.0 * i, {0.8f, 0.1f, 0.1f, 1});
  check_reference("markers", s);
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
    check_reference(std::string("filter_") + (i == 0 ? "box" : i == 1 ? "tent" : "bspline"), s);
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
  check_reference("text", s, true);
}
