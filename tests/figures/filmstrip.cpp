// [[axes.inbetween]] as a filmstrip (steps = N) and the linear in-betweening, and s003-fig15
// built from them (seed 003 section 6, Figure 15). The drawn frames are read back through the
// caption fields count() and item(i) (the points in drawing order) and compared with the
// relaxed spline written out here: for three keyframes at t = 0, 1, 2 it is the natural cubic
// spline with M0 = M2 = 0 and M1 = 6 (S0 - 2 S1 + S2) / 4 (the "1 4 1" system), each
// coordinate on its own.
#include <catch2/catch.hpp>

#include "spec_error_check.hpp"

#include <splinefig/base/limits.hpp>
#include <splinefig/figures/figure.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace splinefig::figures;

namespace {

const std::string kSpecs = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/";

// The leg of s003-fig17: hip, knee, heel, toe at t = 0, 1, 2.
const std::vector<std::vector<Vec2>> kLeg = {{{0, 4}, {0.3, 2}, {0, 0}, {0.8, 0}},
                                             {{2, 4}, {2.8, 2.2}, {2.9, 0.3}, {3.7, 0.1}},
                                             {{4, 4}, {4.3, 2}, {4, 0}, {4.8, 0}}};
const std::string kFrames =
    "frames = [[[0, 4], [0.3, 2], [0, 0], [0.8, 0]], [[2, 4], [2.8, 2.2], [2.9, 0.3], [3.7, 0.1]], "
    "[[4, 4], [4.3, 2], [4, 0], [4.8, 0]]]\n";

// The natural cubic spline through s0, s1, s2 at t = 0, 1, 2.
double natural(double s0, double s1, double s2, double t) {
  const double m1 = 6 * (s0 - 2 * s1 + s2) / 4;
  if (t <= 1) return (1 - t) * s0 + t * s1 + (t * t * t - t) * m1 / 6;
  const double u = t - 1, v = 1 - u;
  return v * s1 + u * s2 + (v * v * v - v) * m1 / 6;
}

std::string fmt(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s == "-0" || s.find_first_not_of("-0.") == std::string::npos) s = std::string(buf).substr(s[0] == '-' ? 1 : 0);
  if (s[0] != '-') return s;
  std::string minus = "\u2212";  // built by appends (GCC 12 -Wrestrict, PR 105329, on "literal" + s)
  return minus.append(s, 1);
}

std::string item(int k) {
  std::string s = "item(";
  s += std::to_string(k);
  s += ')';
  return s;
}

std::string pt(double x, double y, int decimals) {
  std::string s = "(";
  s += fmt(x, decimals);
  s += ", ";
  s += fmt(y, decimals);
  s += ')';
  return s;
}

// The caption "{=v}" of one field on the spec's filmstrip, with `keys` added to the element.
std::string field(const std::string& keys, const std::string& value, int decimals = 9) {
  std::string spec = "caption = \"{=v}\"\n[[caption_field]]\nname = \"v\"\nelement = \"axes.inbetween[0]\"\nvalue = \"";
  spec += value;
  spec += "\"\ndecimals = ";
  spec += std::to_string(decimals);
  spec += "\n[axes]\nx_range = [-1, 30]\ny_range = [-1, 5]\n[[axes.inbetween]]\n";
  spec += kFrames;
  spec += keys;
  return layout_figure(parse_spec(spec, "strip.toml")).caption;
}

}  // namespace

TEST_CASE("an inbetween filmstrip draws every frame at t = i / steps, moved by i * shift", "[filmstrip]") {
  const int steps = 6;
  const Vec2 shift{1.8, 0.25};
  const std::string keys = "steps = 6\nshift = [1.8, 0.25]\n";
  REQUIRE(field(keys, "count()", 0) == std::to_string((2 * steps + 1) * 4));
  for (int i = 0; i <= 2 * steps; ++i)
    for (int j = 0; j < 4; ++j) {
      const double t = static_cast<double>(i) / steps;
      const double x = natural(kLeg[0][j].x, kLeg[1][j].x, kLeg[2][j].x, t) + i * shift.x;
      const double y = natural(kLeg[0][j].y, kLeg[1][j].y, kLeg[2][j].y, t) + i * shift.y;
      INFO("frame " << i << ", point " << j);
      CHECK(field(keys, item(4 * i + j)) == pt(x, y, 9));
    }
  // The heel of the frame at t = 1/2 is DD-4(d)'s (13 S0 + 22 S1 - 3 S2) / 32 = (1.61875, 0.20625).
  CHECK(field(keys, "item(14)", 5) == pt(1.61875 + 3 * 1.8, 0.20625 + 3 * 0.25, 5));
  CHECK(field(keys, "steps()", 0) == "6");
}

TEST_CASE("linear in-betweening puts a frame on the straight line between the keyframes around it", "[filmstrip]") {
  // t = 1/3: two thirds of the frame at 0 plus one third of the frame at 1 (the notes' example).
  for (int j = 0; j < 4; ++j) {
    const Vec2 a = kLeg[0][j], b = kLeg[1][j];
    CHECK(field("t = 0.3333333333333333\ninterpolation = \"linear\"\n", item(j)) ==
          pt(a.x * 2 / 3 + b.x / 3, a.y * 2 / 3 + b.y / 3, 9));
  }
  // A strip of 3 steps: frame 4 is at t = 4/3, a third of the way from the frame at 1 to that at 2.
  const std::string keys = "steps = 3\nshift = [2, 0]\ninterpolation = \"linear\"\n";
  for (int j = 0; j < 4; ++j) {
    const Vec2 a = kLeg[1][j], b = kLeg[2][j];
    CHECK(field(keys, item(16 + j)) ==
          pt(a.x * 2 / 3 + b.x / 3 + 8, a.y * 2 / 3 + b.y / 3, 9));
  }
  // The keyframes are their data, moved: frame 6 is the keyframe at t = 2.
  CHECK(field(keys, "item(24)") == pt(4 + 12, 4, 9));
}

TEST_CASE("inbetween's filmstrip keys are refused in one line where they do not apply", "[filmstrip]") {
  struct Case {
    std::string text, expect;
  };
  const std::string head = "[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n[[axes.inbetween]]\n";
  // 64 steps over 65 keyframe intervals draw 64 * 65 + 1 = 4161 frames, past the limit.
  std::string many = "frames = [";
  for (int k = 0; k <= 65; ++k) many += std::string(k ? ", " : "") + "[[0, 0]]";
  many += "]\n";
  const std::vector<Case> cases = {
      {head + kFrames + "t = 0.5\nsteps = 6\n", "s.toml:7: axes.inbetween[0].steps: give either t = TIME (one frame) or steps = N"},
      {head + kFrames, "s.toml:4: axes.inbetween[0].t: needs t = TIME (one frame) or steps = N"},
      {head + kFrames + "t = 0.5\nshift = [1, 0]\n", "s.toml:7: axes.inbetween[0].shift: shift is for a filmstrip (steps = N)"},
      {head + kFrames + "t = 0.5\nkey_color = \"#000000\"\n", "s.toml:7: axes.inbetween[0].key_color: key_color is for a filmstrip"},
      {head + kFrames + "steps = 0\n", "s.toml:6: axes.inbetween[0].steps: must be in [1, 64], found 0"},
      {head + kFrames + "steps = 65\n", "s.toml:6: axes.inbetween[0].steps: must be in [1, 64], found 65"},
      {head + kFrames + "steps = 2\ninterpolation = \"cubic\"\n", "s.toml:7: axes.inbetween[0].interpolation: unknown value \"cubic\""},
      {head + many + "steps = 64\n",
       std::string("s.toml:6: axes.inbetween[0].steps: 64 steps over 65 keyframe intervals draw more than ") +
           std::to_string(splinefig::kMaxFilmstripFrames) + " frames"},
  };
  figtest::check_spec_errors(cases, "s.toml");
}

TEST_CASE("s003-fig15's caption prints the knee's velocity jump under linear in-betweening", "[filmstrip]") {
  const FigureSpec spec = load_spec(kSpecs + "s003-fig15.toml");
  const std::string caption = layout_figure(spec).caption;
  CAPTURE(caption);
  // The knee's x relative to the hip at t = 0, 1, 2 (the key frames' point 1 minus point 0):
  // 0.3, 0.8, 0.3. Linear: slopes 0.5 and then -0.5 (dt = 1). The natural spline's slope at
  // t = 1 is (S1 - S0) + (2 M1) / 6 = (S2 - S0) / 2 = 0.
  double s[3];
  for (int k = 0; k < 3; ++k) s[k] = kLeg[k][1].x - kLeg[k][0].x;
  auto vel = [](double dx) { return pt(1, dx, 2); };
  CHECK(caption.find("divided into 6 subintervals") != std::string::npos);
  CHECK(caption.find(std::string("from ") + vel(s[1] - s[0]) + " to " + vel(s[2] - s[1])) != std::string::npos);
  CHECK(caption.find(std::string("at ") + vel((s[1] - s[0]) + 2 * (6 * (s[0] - 2 * s[1] + s[2]) / 4) / 6) + ", with no jump") !=
        std::string::npos);
  CHECK(vel(s[1] - s[0]) == "(1.00, 0.50)");
  CHECK(vel((s[2] - s[0]) / 2) == "(1.00, 0.00)");
  // The bottom panel plots those differences: its data are the key frames', not typed apart.
  std::size_t a = 0;
  for (const auto& item : spec.items)
    if (const auto* ax = std::get_if<AxesSpec>(&item); ax && a++ == 2)
      for (const auto& e : ax->elements) {
        if (const auto* b = std::get_if<BezierElement>(&e)) {  // a linear piece, key frame k to k + 1
          REQUIRE(b->points.size() == 2);
          const int k = static_cast<int>(b->points[0].x);
          REQUIRE((k == 0 || k == 1));
          CHECK(b->points[0].y == Approx(s[k]).margin(1e-15));
          CHECK(b->points[1].x == k + 1);
          CHECK(b->points[1].y == Approx(s[k + 1]).margin(1e-15));
          continue;
        }
        const std::vector<Vec2>* pts = nullptr;
        if (const auto* i = std::get_if<InterpElement>(&e)) pts = &i->points;
        if (const auto* r = std::get_if<SeriesElement>(&e)) pts = &r->points;
        if (!pts) continue;
        REQUIRE(pts->size() == 3);
        for (int k = 0; k < 3; ++k) {
          CHECK((*pts)[static_cast<std::size_t>(k)].x == k);
          CHECK((*pts)[static_cast<std::size_t>(k)].y == Approx(s[k]).margin(1e-15));
        }
      }
  // Both strips draw the same keyframes as s003-fig17, and six subintervals of each time unit.
  const FigureSpec fig17 = load_spec(kSpecs + "s003-fig17.toml");
  std::vector<const InbetweenElement*> strips;
  const InbetweenElement* single = nullptr;
  for (const FigureSpec* s : {&spec, &fig17})
    for (const auto& item : s->items)
      if (const auto* ax = std::get_if<AxesSpec>(&item))
        for (const auto& e : ax->elements)
          if (const auto* ib = std::get_if<InbetweenElement>(&e)) (s == &spec ? strips.push_back(ib) : (void)(single = ib));
  REQUIRE(strips.size() == 2);
  REQUIRE(single != nullptr);
  for (const auto* ib : strips) {
    CHECK(ib->steps == 6);
    REQUIRE(ib->frames.size() == single->frames.size());
    for (std::size_t k = 0; k < ib->frames.size(); ++k)
      for (std::size_t j = 0; j < ib->frames[k].size(); ++j) {
        CHECK(ib->frames[k][j].x == single->frames[k][j].x);
        CHECK(ib->frames[k][j].y == single->frames[k][j].y);
      }
  }
  CHECK(strips[0]->interpolation == InbetweenElement::Interpolation::Relaxed);
  CHECK(strips[1]->interpolation == InbetweenElement::Interpolation::Linear);
}
