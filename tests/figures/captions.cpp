// The built-in captions state values of their figures' data only through computed fields
// (docs/spec.md, "Caption fields"). For each such figure the values are worked out here again,
// independently of the library (the seeds' formulas by hand, exact where the data allow, or an
// evaluation written here), and the built caption must print them; the field errors are
// checked at the end.
#include <catch2/catch.hpp>

#include "spec_error_check.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/spline/basis.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace splinefig::figures;

namespace {

const std::string kSpecs = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/";

FigureSpec builtin(const std::string& name) { return load_spec(kSpecs + name + ".toml"); }

// The caption as index.json and the gallery get it.
std::string built_caption(const FigureSpec& spec) { return layout_figure(spec).caption; }

// The k-th element of kind T in panel `axes` of the spec.
template <class T>
const T& element(const FigureSpec& spec, std::size_t axes, std::size_t k) {
  std::size_t a = 0;
  for (const auto& item : spec.items)
    if (const auto* ax = std::get_if<AxesSpec>(&item); ax && a++ == axes)
      for (const auto& e : ax->elements)
        if (const auto* x = std::get_if<T>(&e); x && k-- == 0) return *x;
  throw std::runtime_error("no such element");
}

// A number as a caption prints it: fixed decimals, U+2212 for minus.
std::string fmt(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s[0] != '-') return s;
  std::string minus = "\u2212";
  return minus.append(s, 1);
}
std::string fmt(Vec2 p, int decimals) {  // built by appends (GCC 12 -Wrestrict, PR 105329, on "(" + s)
  std::string s = "(";
  s += fmt(p.x, decimals);
  s += ", ";
  s += fmt(p.y, decimals);
  s += ')';
  return s;
}

Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The Lagrange polynomial through (t_i, y_i) at t, as the textbook sum of y_i l_i(t), in long
// double (the library evaluates its own form).
long double lagrange_at(const std::vector<Vec2>& d, long double t) {
  long double sum = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    long double l = 1;
    for (std::size_t j = 0; j < d.size(); ++j)
      if (j != i) l *= (t - d[j].x) / static_cast<long double>(d[i].x - d[j].x);
    sum += d[i].y * l;
  }
  return sum;
}

// Its largest value on [a, b]: a grid of 20000 steps, then ternary search around the best.
std::pair<double, double> lagrange_max(const std::vector<Vec2>& d, double a, double b) {
  constexpr int n = 20000;
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (lagrange_at(d, a + (b - a) * i / n) > lagrange_at(d, a + (b - a) * best / n)) best = i;
  long double lo = a + (b - a) * std::max(best - 1, 0) / n, hi = a + (b - a) * std::min(best + 1, n) / n;
  for (int it = 0; it < 200; ++it) {
    const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    (lagrange_at(d, m1) < lagrange_at(d, m2) ? lo : hi) = lagrange_at(d, m1) < lagrange_at(d, m2) ? m1 : m2;
  }
  const long double t = (lo + hi) / 2;
  return {static_cast<double>(t), static_cast<double>(lagrange_at(d, t))};
}

}  // namespace

TEST_CASE("s003-fig03's caption prints P''(0) = 6(P0 - 2P1 + P2) of its two curves", "[captions]") {
  const FigureSpec spec = builtin("s003-fig03");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  // Seed 003 §2: P''(0) = 6(P0 - 2P1 + P2), from the drawn curves' own control points. The
  // data are halves, so these sums are exact in doubles.
  const auto& left = element<BezierElement>(spec, 0, 0).points;
  const auto& right = element<BezierElement>(spec, 1, 0).points;
  const Vec2 l = 6 * (left[0] - 2 * left[1] + left[2]), r = 6 * (right[0] - 2 * right[1] + right[2]);
  CHECK(contains(caption, "so P''(0) = " + fmt(l, 0) + " and"));
  CHECK(contains(caption, "with P₂ = " + fmt(right[2], 1) + " the midpoint"));
  CHECK(contains(caption, "6(P₀ − 2P₁ + P₂) = " + fmt(r, 0) + "."));
  // By hand: 6((0,0) - 2(1,1) + (2,2)) = (0, 0); 6((0,0) - 2(1,1) + (2.5,1)) = (3, -6).
  CHECK(contains(caption, "P''(0) = (0, 0)"));
  CHECK(contains(caption, "= (3, −6)."));
}

TEST_CASE("s003-fig01's caption prints where the Lagrange polynomial peaks near the ends", "[captions]") {
  const FigureSpec spec = builtin("s003-fig01");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  const auto& data = element<LagrangeElement>(spec, 0, 0).points;
  REQUIRE(data.size() == 11);
  const auto [tl, yl] = lagrange_max(data, 0, 1);
  const auto [tr, yr] = lagrange_max(data, 9, 10);
  CHECK(contains(caption, "swings out to " + fmt(yl, 2) + " (at t = " + fmt(tl, 2) + ") and " + fmt(yr, 2) + " (at t = " +
                              fmt(tr, 2) + ")"));
  // The values the seed's figure shows: peaks of about 3.43 at t = 0.30 and 3.72 at t = 9.70,
  // above the values at the half-integers (P(1/2) = 362017/131072 = 2.76, P(19/2) = 3.17).
  CHECK(contains(caption, "3.43 (at t = 0.30) and 3.72 (at t = 9.70)"));
  CHECK(yl > 362017.0 / 131072);
}

TEST_CASE("s003-fig05's caption prints the curvature jump at S, and the pieces bend opposite ways", "[captions]") {
  const FigureSpec spec = builtin("s003-fig05");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  const auto& P = element<BezierElement>(spec, 0, 0).points;
  const auto& Q = element<BezierElement>(spec, 0, 1).points;
  REQUIRE(P.size() == 4);
  REQUIRE(Q.size() == 4);
  const Vec2 S = P[3];
  // First derivatives match: S is the midpoint of P2 Q1.
  CHECK(S.x - P[2].x == Q[1].x - S.x);
  CHECK(S.y - P[2].y == Q[1].y - S.y);
  // Seed 003 §3: at S the derivatives are 3(S - P2), 6(P1 - 2P2 + S) and 3(Q1 - S),
  // 6(S - 2Q1 + Q2); the signed curvature is cross(P', P'') / |P'|^3.
  auto kappa = [](Vec2 d1, Vec2 d2) { return cross(d1, d2) / std::pow(std::hypot(d1.x, d1.y), 3); };
  const double kp = kappa(3 * (S - P[2]), 6 * (P[1] - 2 * P[2] + S));
  const double kq = kappa(3 * (Q[1] - S), 6 * (S - 2 * Q[1] + Q[2]));
  CHECK(contains(caption, "from " + fmt(kp, 2) + " to " + fmt(kq, 2) + ":"));
  CHECK(contains(caption, "from −0.48 to 0.24:"));
  // "bends right all the way to S and the second bends left": the sign of cross(B', B'') along
  // each cubic, B' = 3[(1-u)^2 (B1-B0) + 2u(1-u)(B2-B1) + u^2 (B3-B2)], B'' = 6[(1-u)(B2-2B1+B0) + u(B3-2B2+B1)].
  auto turn = [](const std::vector<Vec2>& B, double u) {
    const Vec2 d1 = 3 * ((1 - u) * (1 - u) * (B[1] - B[0]) + 2 * u * (1 - u) * (B[2] - B[1]) + u * u * (B[3] - B[2]));
    const Vec2 d2 = 6 * ((1 - u) * (B[2] - 2 * B[1] + B[0]) + u * (B[3] - 2 * B[2] + B[1]));
    return cross(d1, d2);
  };
  for (int i = 0; i <= 100; ++i) {
    CHECK(turn(P, i / 100.0) < 0);
    CHECK(turn(Q, i / 100.0) > 0);
  }
}

TEST_CASE("s003-fig12's caption prints B3 of both curves, and S1 and S5 are labelled at the joints", "[captions]") {
  const FigureSpec spec = builtin("s003-fig12");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  const auto& before = element<RelaxedBsplineElement>(spec, 0, 0).points;
  const auto& after = element<RelaxedBsplineElement>(spec, 0, 2).points;
  REQUIRE(before.size() == 7);
  REQUIRE(after.size() == 7);
  CHECK(contains(caption, "with B₃ at " + fmt(before[3], 0) + " (blue) and at " + fmt(after[3], 0) + " (dark red"));
  CHECK(contains(caption, "B₃ at (4, 1) (blue) and at (4, −1) (dark red, dashed)"));
  // Seed 003 §4: the joints are S_i = (B_(i-1) + 4B_i + B_(i+1))/6; S1 and S5 do not involve B3.
  const Vec2 S1 = (1.0 / 6) * (before[0] + 4 * before[1] + before[2]);
  const Vec2 S5 = (1.0 / 6) * (before[4] + 4 * before[5] + before[6]);
  int found = 0;
  for (const auto& e : std::get<AxesSpec>(spec.items.back()).elements)
    if (const auto* t = std::get_if<TextElement>(&e)) {
      const Vec2 want = t->text == "$S_1$" ? S1 : S5;
      if (t->text != "$S_1$" && t->text != "$S_5$") continue;
      ++found;
      CHECK(t->at.x == Approx(want.x).margin(1e-12));
      CHECK(t->at.y == Approx(want.y).margin(1e-12));
    }
  CHECK(found == 2);
}

TEST_CASE("caption fields: values, number format and errors", "[captions]") {
  const std::string head = "caption = \"P''(0) = {=d}\"\n";
  const std::string axes =
      "[axes]\nx_range = [0, 3]\ny_range = [0, 3]\n[[axes.bezier]]\npoints = [[0, 0], [1, 1], [2.5, 1], [3, 0]]\n"
      "[[axes.lagrange]]\npoints = [[0, 0], [1, 1], [2, 0]]\n[[axes.bezier]]\npoints = [[1, 1], [2, 3], [4, 3], [5, 1]]\n";
  auto field = [](const std::string& body) { return "[[caption_field]]\nname = \"d\"\n" + body + "\n"; };
  auto caption_of = [&](const std::string& body) {
    return layout_figure(parse_spec(head + field(body) + axes, "c.toml")).caption;
  };
  // By hand: P''(0) = 6((0,0) - 2(1,1) + (2.5,1)) = (3, -6); P''(1) = 6((1,1) - 2(2.5,1) + (3,0)) = (-6, -6);
  // P'(1) = 3((3,0) - (2.5,1)) = (1.5, -3); P(1/2) = ((0,0) + 3(1,1) + 3(2.5,1) + (3,0))/8 = (13.5/8, 6/8).
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"d2(0)\"\ndecimals = 1") == "P''(0) = (3.0, −6.0)");
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"d2(1)\"\ndecimals = 0") == "P''(0) = (−6, −6)");
  // Off the origin: 6((1,1) - 2(2,3) + (4,3)) = (6, -12) at 0; 6((2,3) - 2(4,3) + (5,1)) = (-6, -12) at 1.
  CHECK(caption_of("element = \"axes.bezier[1]\"\nvalue = \"d2(0)\"\ndecimals = 0") == "P''(0) = (6, −12)");
  CHECK(caption_of("element = \"axes.bezier[1]\"\nvalue = \"d2(1)\"\ndecimals = 0") == "P''(0) = (−6, −12)");
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"d1(1)\"") == "P''(0) = (1.50, −3.00)");
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"point(0.5)\"\ndecimals = 4") == "P''(0) = (1.6875, 0.7500)");
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"y(0.5)\"\ndecimals = 3") == "P''(0) = 0.750");
  // Curvature at 0: cross((3,3), (3,-6)) / |(3,3)|^3 = -27 / (18 sqrt 18) = -0.35355...
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"curvature(0)\"\ndecimals = 4") == "P''(0) = −0.3536");
  // The parabola through (0,0), (1,1), (2,0) is 2t - t^2: largest 1 at t = 1, smallest 0 at 0.
  CHECK(caption_of("element = \"axes.lagrange[0]\"\nvalue = \"max_y(0, 2)\"\ndecimals = 6") == "P''(0) = 1.000000");
  CHECK(caption_of("element = \"axes.lagrange[0]\"\nvalue = \"argmax_y(0.5, 2)\"\ndecimals = 6") == "P''(0) = 1.000000");
  CHECK(caption_of("element = \"axes.lagrange[0]\"\nvalue = \"argmin_y(0.5, 2)\"\ndecimals = 6") == "P''(0) = 2.000000");
  CHECK(caption_of("element = \"axes.lagrange[0]\"\nvalue = \"knot(2)\"\ndecimals = 0") == "P''(0) = (2, 0)");
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"points()\"") == "P''(0) = (0, 0), (1, 1), (2.5, 1), (3, 0)");
  // 20 log10 of y = 2t - t^2: 0 dB at t = 1, 20 log10(3/4) = -2.4988 dB at t = 1/2.
  CHECK(caption_of("element = \"axes.lagrange[0]\"\nvalue = \"db(1)\"") == "P''(0) = 0.00");
  CHECK(caption_of("element = \"axes.lagrange[0]\"\nvalue = \"db(0.5)\"\ndecimals = 4") == "P''(0) = −2.4988");
  // No "−0": -1e-9 at two decimals is 0.00.
  CHECK(caption_of("element = \"axes.lagrange[0]\"\nvalue = \"y(2)\"") == "P''(0) = 0.00");

  struct Case {
    std::string text, expect;
  };
  const std::vector<Case> cases = {
      {"caption = \"{=nope}\"\n" + axes, "c.toml:1: caption: {=nope} names no [[caption_field]]"},
      {"caption = \"{=bad name}\"\n" + axes, "c.toml:1: caption: a field is written {=NAME}"},
      {"caption = \"x\"\n" + field("element = \"axes.bezier[0]\"\nvalue = \"d2(0)\"") + axes,
       "c.toml:2: caption_field[0]: \"d\" is declared but the caption never uses {=d}"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"slope(0)\""), "c.toml:5: caption_field[0].value: \"slope\" is not a value function"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"d2(0, 1)\""), "c.toml:5: caption_field[0].value: d2() takes 1 argument, got 2"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"d2(x)\""), "c.toml:5: caption_field[0].value: \"x\" is not a finite number"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"max_y(1, 0)\""), "c.toml:5: caption_field[0].value: max_y(a, b) needs a < b"},
      {head + field("value = \"d2(0)\""), "c.toml:2: caption_field[0].element: needs element"},
      {head + field("element = \"axes.bezier[3]\"\nvalue = \"d2(0)\"") + axes,
       "c.toml:2: caption_field[0]: element: \"axes.bezier[3]\" is no plot element of this spec"},
      {head + field("element = \"axes.lagrange[0]\"\nvalue = \"d2(0)\"") + axes,
       "c.toml:2: caption_field[0]: value: d2() needs a curve made of cubic pieces"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"leakage()\"") + axes,
       "c.toml:2: caption_field[0]: value: leakage() reads a response or filter element; \"axes.bezier[0]\" is neither"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"bias()\"") + axes,
       "c.toml:2: caption_field[0]: value: bias() reads a curve whose basis is a beta or bspline"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"marks()\"") + axes,
       "c.toml:2: caption_field[0]: value: marks() reads a curve with marks; \"axes.bezier[0]\" has none"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"steps()\"") + axes,
       "c.toml:2: caption_field[0]: value: steps() reads an inbetween filmstrip (steps = N); \"axes.bezier[0]\" is not one"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"d2(1.5)\"") + axes,
       "c.toml:2: caption_field[0]: value: d2(): t = 1.500000 is outside the curve's parameter range [0.000000, 1.000000]"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"knot(4)\"") + axes,
       "c.toml:2: caption_field[0]: value: knot(4) of \"axes.bezier[0]\", which has 4 points"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"b1(0)\"") + axes,
       "c.toml:2: caption_field[0]: value: b1() reads the betas of a local_betas element"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"k(0)\"") + axes,
       "c.toml:2: caption_field[0]: value: k() reads a kernel or filter element; \"axes.bezier[0]\" is neither"},
      {head + field("element = \"axes.lagrange[0]\"\nvalue = \"db(0)\"") + axes,
       "c.toml:2: caption_field[0]: value: db(): y is 0 at t = 0.000000"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"points(1)\"") + axes,
       "c.toml:5: caption_field[0].value: points() takes 0 arguments, got 1"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"count()\"") + axes,
       "c.toml:2: caption_field[0]: value: count() reads the points of a point set"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"d2(0)\"\ndecimals = 13") + axes,
       "c.toml:6: caption_field[0].decimals: must be in [0, 12]"},
  };
  figtest::check_spec_errors(cases, "c.toml");
}

TEST_CASE("caption fields: along, mirror_x and fractions", "[captions]") {
  const std::string head = "caption = \"c = {=d}\"\n";
  const std::string axes =
      "[axes]\nx_range = [0, 6]\ny_range = [0, 6]\n"
      "[[axes.curve]]\nknots = [[0, 0], [6, 0], [6, 6]]\nbasis = \"bspline\"\nends = \"double\"\n"
      "[[axes.polygon]]\npoints = [[0, 0], [1, 2], [3, 2], [4, 0]]\n"
      "[[axes.polygon]]\npoints = [[0, 0], [1, 2], [3, 1], [4, 0]]\n"
      "[[axes.bezier]]\npoints = [[0, 0], [1, 1], [2.5, 1], [3, 0]]\n";
  auto field = [](const std::string& body) { return "[[caption_field]]\nname = \"d\"\n" + body + "\n"; };
  auto caption_of = [&](const std::string& body) {
    return layout_figure(parse_spec(head + field(body) + axes, "c.toml")).caption;
  };
  // The uniform B-spline with doubled ends K0 K0 K1 K2 K2 starts at (K0 + 4 K0 + K1) / 6 and
  // ends at (K1 + 4 K2 + K2) / 6: a sixth of the first leg from K0, a sixth of the last from K2.
  CHECK(caption_of("element = \"axes.curve[0]\"\nvalue = \"along(0, 0, 1)\"\nfraction = true") == "c = 1/6");
  CHECK(caption_of("element = \"axes.curve[0]\"\nvalue = \"along(2, 2, 1)\"\nfraction = true") == "c = 1/6");
  CHECK(caption_of("element = \"axes.curve[0]\"\nvalue = \"along(2, 1, 2)\"\nfraction = true") == "c = 5/6");
  CHECK(caption_of("element = \"axes.curve[0]\"\nvalue = \"along(0, 0, 1)\"\ndecimals = 4") == "c = 0.1667");
  // At t = 1/2 the weights (1, 23, 23, 1) / 48 of K0 K0 K1 K2 give (24 * 6, 6) / 48 = (3, 1/8).
  CHECK(caption_of("element = \"axes.curve[0]\"\nvalue = \"point(0.5)\"\nfraction = true") == "c = (3, 1/8)");
  // (0,0), (1,2), (3,2), (4,0) mirror under x -> 4 - x.
  CHECK(caption_of("element = \"axes.polygon[0]\"\nvalue = \"mirror_x()\"\ndecimals = 0") == "c = 4");
  // P''(0) = (3, -6) of the Bezier, as whole numbers; a minus is U+2212.
  CHECK(caption_of("element = \"axes.bezier[0]\"\nvalue = \"d2(0)\"\nfraction = true") == "c = (3, \u22126)");
  struct Case {
    std::string text, expect;
  };
  const std::vector<Case> cases = {
      {head + field("element = \"axes.curve[0]\"\nvalue = \"along(1, 0, 1)\"") + axes,
       // (K0 + 4 K1 + K2) / 6 = (5, 1) at t = 1: on neither leg.
       "c.toml:2: caption_field[0]: value: along(): the point at t = 1.000000, (5.000000, 1.000000), is not on the leg from "
       "knot 0 to knot 1"},
      {head + field("element = \"axes.curve[0]\"\nvalue = \"along(0, 0, 3)\"") + axes,
       "c.toml:2: caption_field[0]: value: knot 3 of \"axes.curve[0]\", which has 3 points (0 .. 2)"},
      {head + field("element = \"axes.curve[0]\"\nvalue = \"along(0, 1, 1)\"") + axes,
       "c.toml:5: caption_field[0].value: along(t, i, j) needs two different knots i and j"},
      {head + field("element = \"axes.curve[0]\"\nvalue = \"along(0, 0.5, 1)\"") + axes,
       "c.toml:5: caption_field[0].value: along(t, i, j) takes knot indices 0, 1, 2, ... for i and j, got 0.500000"},
      {head + field("element = \"axes.polygon[1]\"\nvalue = \"mirror_x()\"") + axes,
       "c.toml:2: caption_field[0]: value: mirror_x(): the points of \"axes.polygon[1]\" are not their own mirror image "
       "under x -> 4.000000 - x (point 1 against point 2)"},
      // P(1/2) = (1.6875, 0.75) = (27/16, 3/4); curvature(0) = -1/(2 sqrt 2) is no fraction.
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"curvature(0)\"\nfraction = true") + axes,
       "c.toml:2: caption_field[0]: fraction: \u22120.353553390593 is no fraction p/q with q <= 1000"},
      {head + field("element = \"axes.bezier[0]\"\nvalue = \"points()\"\nfraction = true") + axes,
       "c.toml:6: caption_field[0].fraction: points() prints decimals"},
  };
  figtest::check_spec_errors(cases, "c.toml");
}

TEST_CASE("bias' caption prints where the curves start and stop and the polygon's mirror", "[captions]") {
  const FigureSpec spec = builtin("bias");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  // The polygon (0,0), (1,2), ..., (6,0): point k mirrors point 6 - k under x -> x0 + x6 - x.
  const auto& poly = element<SeriesElement>(spec, 0, 0).points;
  REQUIRE(poly.size() == 7);
  for (std::size_t k = 0; k < 7; ++k) {
    CHECK(poly[k].x + poly[6 - k].x == poly[0].x + poly[6].x);
    CHECK(poly[k].y == poly[6 - k].y);
  }
  CHECK(contains(caption, "mirror image under x → " + fmt(poly[0].x + poly[6].x, 0) + " − x"));
  CHECK(contains(caption, "x → 6 − x"));
  // The memo's B-spline matrix, last row (1 4 1 0) / 6, with doubled ends K0 K0 K1 ...: the
  // curve starts at (K0 + 4 K0 + K1) / 6, a sixth of the way from K0 to K1, and ends a sixth of
  // the way from K6 back to K5.
  CHECK(contains(caption, "the B-spline (blue, dashed) starts 1/6 of the way along the first leg and stops 1/6 of the "
                          "last leg short of the last knot"));
  // A polygon that is no longer symmetric cannot be captioned as one.
  FigureSpec moved = spec;
  std::get<SeriesElement>(std::get<AxesSpec>(moved.items.at(0)).elements.at(0)).points[1].x = 1.25;
  try {
    built_caption(moved);
    FAIL("a polygon without its mirror was captioned");
  } catch (const std::exception& e) {
    CHECK(contains(e.what(), "mirror_x(): the points of \"axes.polygon[0]\" are not their own mirror image"));
  }
  // Where b1 = 5 starts and ends: the next test case.
}

TEST_CASE("s002-fig474's caption prints the point counts 3 + 2^k, and (b) is the tree of groups", "[captions]") {
  const FigureSpec spec = builtin("s002-fig474");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  // Seed 002: step k has 3 + 2^k distinct points: 5 after one step, 7 after two.
  CHECK(element<SubdivisionElement>(spec, 0, 0).steps == 1);
  CHECK(element<SubdivisionElement>(spec, 0, 1).steps == 2);
  CHECK(contains(caption, "the " + std::to_string(3 + (1 << 1)) + " points of the first step and the " +
                              std::to_string(3 + (1 << 2)) + " of the second"));
  // (b): the groups after three steps. Group j of step k is P^k_j .. P^k_(j+3); it makes groups
  // 2j and 2j + 1 of step k + 1 (P^1_0123 -> P^2_0123, P^2_1234; P^1_1234 -> P^2_2345, P^2_3456).
  std::vector<std::string> want;
  for (int k = 0; k <= 3; ++k)
    for (int j = 0; j < (1 << k); ++j) {
      std::string idx;
      for (int i = j; i < j + 4; ++i) {
        if (j + 3 >= 10 && i > j) idx += ' ';
        idx += std::to_string(i);
      }
      want.push_back("$P^" + std::to_string(k) + "_{" + idx + "}$");
    }
  std::vector<std::string> got;
  std::size_t edges = 0;
  std::size_t a = 0;
  for (const auto& item : spec.items)
    if (const auto* ax = std::get_if<AxesSpec>(&item); ax && a++ == 1)
      for (const auto& e : ax->elements) {
        if (const auto* t = std::get_if<TextElement>(&e)) got.push_back(t->text);
        if (std::holds_alternative<SeriesElement>(e)) ++edges;
      }
  CHECK(got == want);
  CHECK(edges == 2 + 4 + 8);  // two children for each of the 1 + 2 + 4 groups above the last row
}

TEST_CASE("local-betas' caption prints the changed shape values and the joints where the change ends", "[captions]") {
  const FigureSpec spec = builtin("local-betas");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  const auto& a = element<LocalBetasElement>(spec, 0, 0);
  const auto& b = element<LocalBetasElement>(spec, 0, 1);
  const auto& c = element<LocalBetasElement>(spec, 1, 0);
  const auto& d = element<LocalBetasElement>(spec, 1, 1);
  // Only the 4th vertex differs from the B-spline's (1, 0), in b1 on top and b2 below.
  for (const auto* e : {&a, &b, &c, &d})
    for (std::size_t i = 0; i < e->betas.size(); ++i)
      if (i != 3) CHECK(e->betas[i] == std::array<double, 2>{1, 0});
  CHECK(contains(caption, "bias b₁ = " + fmt(a.betas[3][0], 1) + " and " + fmt(b.betas[3][0], 0) + " (top), tension b₂ = " +
                              fmt(c.betas[3][1], 0) + " and " + fmt(d.betas[3][1], 0) + " (bottom)"));
  CHECK(contains(caption, "bias b₁ = 0.5 and 2 (top), tension b₂ = 5 and 20 (bottom)"));
  // The joints under vertices 3 and 5 keep their B-spline places (B_(i-1) + 4B_i + B_(i+1))/6,
  // their own vertices' values being (1, 0): ((1,2) + 4(2,0) + (3,2))/6 = (2, 2/3) and
  // ((3,2) + 4(4,0) + (5,2))/6 = (4, 2/3).
  const auto& B = a.knots;
  const Vec2 j3 = (1.0 / 6) * (B[1] + 4 * B[2] + B[3]), j5 = (1.0 / 6) * (B[3] + 4 * B[4] + B[5]);
  CHECK(contains(caption, "at the joint " + fmt(j3, 2) + " under vertex 3 and rejoin it at the joint " + fmt(j5, 2) +
                              " under vertex 5"));
  CHECK(contains(caption, "(2.00, 0.67) under vertex 3"));
}

TEST_CASE("s003-fig14's caption prints the control points that solve the seed's system", "[captions]") {
  const FigureSpec spec = builtin("s003-fig14");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  const auto& S = element<InterpElement>(spec, 0, 0).points;
  REQUIRE(S.size() == 5);
  // Seed 003 §5: B0 = S0, B4 = S4 and B_(i-1) + 4B_i + B_(i+1) = 6S_i for i = 1, 2, 3; for
  // S = (1,-1), (-1,2), (1,4), (4,3), (7,5) the solution is B1 = (-2,2), B2 = (1,5), B3 = (4,2).
  const std::vector<Vec2> B{S[0], {-2, 2}, {1, 5}, {4, 2}, S[4]};
  for (int i = 1; i <= 3; ++i) {
    const Vec2 lhs = B[i - 1] + 4 * B[i] + B[i + 1], rhs = 6 * S[i];
    CHECK(lhs.x == rhs.x);
    CHECK(lhs.y == rhs.y);
  }
  CHECK(contains(caption, "B₁ = " + fmt(B[1], 0) + ", B₂ = " + fmt(B[2], 0) + ", B₃ = " + fmt(B[3], 0) + ", B₄ = S₄"));
  // The first piece's Bezier points: S0, (2B0 + B1)/3, (B0 + 2B1)/3, S1 = (1,-1), (0,0), (-1,1), (-1,2).
  const Vec2 z1 = (1.0 / 3) * (2 * B[0] + B[1]), z2 = (1.0 / 3) * (B[0] + 2 * B[1]);
  CHECK(contains(caption, "e.g. " + fmt(S[0], 0) + ", " + fmt(z1, 0) + ", " + fmt(z2, 0) + ", " + fmt(S[1], 0) + " for the first"));
  CHECK(contains(caption, "e.g. (1, −1), (0, 0), (−1, 1), (−1, 2) for the first"));
}

TEST_CASE("s003-fig17's caption prints the in-between heel (13 S0 + 22 S1 - 3 S2)/32", "[captions]") {
  const FigureSpec spec = builtin("s003-fig17");
  const std::string caption = built_caption(spec);
  CAPTURE(caption);
  const auto& e = element<InbetweenElement>(spec, 0, 0);
  REQUIRE(e.frames.size() == 3);
  REQUIRE(e.t == 0.5);
  // DD-4(d): the relaxed spline through three keyframes at t = 1/2 is (13 S0 + 22 S1 - 3 S2)/32.
  const Vec2 heel = (1.0 / 32) * (13 * e.frames[0][2] + 22 * e.frames[1][2] + (-3) * e.frames[2][2]);
  CHECK(contains(caption, "= " + fmt(heel, 5) + "."));
  CHECK(contains(caption, "(13 S₀ + 22 S₁ − 3 S₂)/32 = (1.61875, 0.20625)."));
}

namespace {

// Keys' cardinal cubic with parameter a (a = 0.5: Catmull-Rom), written out.
double cardinal(double a, double s) {
  s = std::abs(s);
  if (s < 1) return (2 - a) * s * s * s + (a - 3) * s * s + 1;
  if (s < 2) return -a * s * s * s + 5 * a * s * s - 8 * a * s + 4 * a;
  return 0;
}

// The samples 0,0,0,0,1,1,1,1 (clamped at the ends) reconstructed by the cardinal kernel, whose
// weights sum to 1: its largest value, on a grid of 1e-5 over [3.5, 5.5].
double cardinal_step_peak(double a) {
  const double v[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  double best = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double t = 3.5 + i * 1e-5;
    double x = 0;
    for (int j = static_cast<int>(std::floor(t)) - 1; j <= static_cast<int>(std::floor(t)) + 2; ++j)
      x += cardinal(a, t - j) * v[std::clamp(j, 0, 7)];
    best = std::max(best, x);
  }
  return best;
}

// |K(f)| of a kernel on [-2, 2] by Simpson's rule on 4000 intervals (the kernels are even).
template <class K>
double response_at(K k, double f) {
  const int n = 4000;
  const double h = 4.0 / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double s = -2 + i * h;
    sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * k(s) * std::cos(2 * M_PI * f * s);
  }
  return std::abs(sum * h / 3);
}

}  // namespace

TEST_CASE("bbasis' caption prints the B-spline kernel's k(0) = 2/3 and k(1) = 1/6", "[captions]") {
  const std::string caption = built_caption(builtin("bbasis"));
  INFO(caption);
  // The uniform cubic B-spline: (4 - 6s^2 + 3|s|^3)/6 on |s| < 1.
  CHECK(contains(caption, "k(0) = " + fmt(4.0 / 6, 4) + ","));
  CHECK(contains(caption, "k(±1) = " + fmt((4.0 - 6 + 3) / 6, 4) + ","));
}

TEST_CASE("filter-step's caption prints the overshoots 1 + 2/27 and 1 + 4/27", "[captions]") {
  const std::string caption = built_caption(builtin("filter-step"));
  INFO(caption);
  const double cr = cardinal_step_peak(0.5), c1 = cardinal_step_peak(1);
  CHECK(cr == Approx(1 + 2.0 / 27).epsilon(1e-7));  // the classic overshoot, by the grid
  CHECK(c1 == Approx(1 + 4.0 / 27).epsilon(1e-7));
  CHECK(contains(caption, "peaking at " + fmt(cr, 3) + " and " + fmt(c1, 3) + ";"));
}

TEST_CASE("filter-response's caption prints |K(0.25)| in dB of the B-spline and of Catmull-Rom", "[captions]") {
  const std::string caption = built_caption(builtin("filter-response"));
  INFO(caption);
  // The B-spline is the box convolved four times: |K(f)| = sinc(f)^4.
  const double sinc = std::sin(M_PI * 0.25) / (M_PI * 0.25);
  const double bspline = 80 * std::log10(sinc);
  CHECK(bspline == Approx(20 * std::log10(response_at([](double s) {
          s = std::abs(s);
          return s < 1 ? (4 - 6 * s * s + 3 * s * s * s) / 6 : s < 2 ? (2 - s) * (2 - s) * (2 - s) / 6 : 0.0;
        }, 0.25))).margin(1e-6));
  const double cr = 20 * std::log10(response_at([](double s) { return cardinal(0.5, s); }, 0.25));
  CHECK(contains(caption, "B-spline (sinc⁴) is at " + fmt(bspline, 1) + " dB at f = 0.25"));
  CHECK(contains(caption, "Catmull-Rom is at " + fmt(cr, 1) + " dB there"));
}

TEST_CASE("filter-response's caption prints the energy each filter keeps above Nyquist", "[captions]") {
  const std::string caption = built_caption(builtin("filter-response"));
  INFO(caption);
  // Parseval: the fraction above |f| = 1/2 is 1 - 2 int_0^(1/2) |K(f)|^2 df / int k^2 ds, both by
  // Simpson's rule here (K(f) itself by Simpson over the kernel, response_at).
  auto simpson = [](auto g, double a, double b, int n) {
    const double h = (b - a) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * g(a + i * h);
    return sum * h / 3;
  };
  auto leak = [&](auto k) {
    const double energy = simpson([&](double s) { return k(s) * k(s); }, -2, 2, 4000);
    return 100 * (1 - 2 * simpson([&](double f) { const double r = response_at(k, f); return r * r; }, 0, 0.5, 200) / energy);
  };
  const double bs = leak([](double s) {
    s = std::abs(s);
    return s < 1 ? (4 - 6 * s * s + 3 * s * s * s) / 6 : s < 2 ? (2 - s) * (2 - s) * (2 - s) / 6 : 0.0;
  });
  const double cr = leak([](double s) { return cardinal(0.5, s); });
  // The box's K is sinc: 1 - 2 int_0^(1/2) sinc^2 (its energy is 1).
  const double box = 100 * (1 - 2 * simpson([](double f) {
                                  if (f == 0) return 1.0;
                                  const double x = M_PI * f;
                                  return std::sin(x) * std::sin(x) / (x * x);
                                }, 0, 0.5, 2000));
  CHECK(bs == Approx(0.606).margin(5e-4));  // SciPy's quad gives 0.6060, 4.6958 and 22.6305
  CHECK(cr == Approx(4.696).margin(5e-4));
  CHECK(box == Approx(22.63).margin(5e-3));
  CHECK(contains(caption, "keeps only " + fmt(bs, 1) + "% of its energy above Nyquist"));
  CHECK(contains(caption, "and leaks " + fmt(cr, 1) + "%; box (sinc) leaks " + fmt(box, 0) + "%."));
}

TEST_CASE("the point lists of s003-fig09, s003-fig13, ends, arclength and multiplicity are the drawn points", "[captions]") {
  // Each list as the figure's source gives it (the seeds' B_i and S_i, the memo's knots), and it
  // is the element's own data: a knot moved in the spec moves in the caption.
  const std::pair<const char*, const char*> lists[] = {
      {"s003-fig09", "B₀..B₆ = (0, 0), (1, 3), (3, 3.5), (4, 1), (6, 0.5), (7, 3), (9, 3.5)."},
      {"s003-fig13", "S₀..S₄ = (1, −1), (−1, 2), (1, 4), (4, 3), (7, 5)."},
      {"ends", "Knots (0, 0), (1, 2), (3, 2.5), (4, 0.5), (6, 1), (7, 3) splined"},
      {"arclength", "through (0, 0), (1, 3), (2, 3.2), (6, 0), (7, 1) with"},
      {"multiplicity", "Knots (0, 0), (1, 2), (2, 0), (3, 2), (4, 0) with the middle knot (2, 0) given"}};
  for (auto [name, text] : lists) {
    const std::string caption = built_caption(builtin(name));
    INFO(name << ": " << caption);
    CHECK(contains(caption, text));
  }
  // arclength's mark counts are the curves' own.
  const FigureSpec arc = builtin("arclength");
  CHECK(contains(built_caption(arc), "with " + std::to_string(element<CurveElement>(arc, 0, 0).marks) +
                                         " points evenly spaced in the parameter t (left), which bunch where the curve "
                                         "moves slowly, and " +
                                         std::to_string(element<CurveElement>(arc, 1, 0).marks) + " points evenly spaced"));
  CHECK(element<CurveElement>(arc, 0, 0).marks == 40);
  FigureSpec moved = builtin("s003-fig13");
  for (auto& item : moved.items)
    if (auto* ax = std::get_if<AxesSpec>(&item))
      for (auto& e : ax->elements)
        if (auto* s = std::get_if<SeriesElement>(&e); s && !s->points.empty()) s->points[1] = {-1.25, 2};
  CHECK(contains(built_caption(moved), "(1, −1), (−1.25, 2), (1, 4)"));
}

TEST_CASE("bias' caption prints where the b1 = 5 curve starts and ends on the end legs", "[captions]") {
  const std::string caption = built_caption(builtin("bias"));
  INFO(caption);
  // The memo's B_{b1,b2} with doubled end knots: the curve starts at ((d - 2) B0 + 2 B1) / d and
  // ends at (2 b1^3 B5 + (d - 2 b1^3) B6) / d, d = b2 + 2 b1^3 + 4 b1^2 + 4 b1 + 2 (372 for b1 = 5).
  const double b1 = 5, b2 = 0, d = b2 + 2 * b1 * b1 * b1 + 4 * b1 * b1 + 4 * b1 + 2;
  const Vec2 B0{0, 0}, B1{1, 2}, B5{5, 2}, B6{6, 0};
  const Vec2 start = (1 / d) * ((d - 2) * B0 + 2 * B1), end = (1 / d) * (2 * b1 * b1 * b1 * B5 + (d - 2 * b1 * b1 * b1) * B6);
  CHECK(d == 372);
  // The end lies 2 b1^3 / d = 250/372 of the way from B6 to B5.
  CHECK(contains(caption, "(b₁ = 5: it starts at " + fmt(start, 2) + " and ends at " + fmt(end, 2) + ", " +
                              fmt(2 * b1 * b1 * b1 / d, 2) + " of the way from (6, 0) to (5, 2))"));
}

TEST_CASE("bias' caption prints the curves' own bias and tension values", "[captions]") {
  const FigureSpec spec = builtin("bias");
  const std::string caption = built_caption(spec);
  INFO(caption);
  // Each curve's b1 and b2 as its spec writes them ("beta:b1=V,b2=V"), read here with sscanf.
  std::vector<double> b1s;
  for (std::size_t k = 0; k < 5; ++k) {
    double b1 = 0, b2 = -1;
    REQUIRE(std::sscanf(element<CurveElement>(spec, 0, k).basis_spec.c_str(), "beta:b1=%lf,b2=%lf", &b1, &b2) == 2);
    CHECK(b2 == 0);
    b1s.push_back(b1);
  }
  std::sort(b1s.begin(), b1s.end());
  CHECK(b1s == std::vector<double>{0.2, 0.5, 1, 2, 5});
  CHECK(contains(caption, "for tension b₂ = 0 and bias b₁ = 0.2, 0.5, 1, 2, 5. b₁ = 1 is the B-spline"));
  CHECK(contains(caption, "the curves for b₁ = 2 and 0.5 are mirror images"));
  // Moved in the spec, moved in the caption.
  FigureSpec moved = spec;
  std::size_t a = 0;
  for (auto& item : moved.items)
    if (auto* ax = std::get_if<AxesSpec>(&item); ax && a++ == 0)
      for (auto& e : ax->elements)
        if (auto* c = std::get_if<CurveElement>(&e); c && c->basis_spec == "beta:b1=2,b2=0") {
          c->basis_spec = "beta:b1=3,b2=0";
          c->basis = splinefig::beta(3, 0);
        }
  CHECK(contains(built_caption(moved), "bias b₁ = 0.2, 0.5, 1, 3, 5."));
}
