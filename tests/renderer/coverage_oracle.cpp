// Stroke coverage against the independent union oracle (oracle/union_coverage.hpp): random seeded
// polylines with every cap and join, widths 0.1..20, axis-aligned, diagonal and sub-pixel
// placements, and dense self-crossing paths. Bound: max error 1/255, mean 1e-3.
#include "coverage_helpers.hpp"
#include <oracle/sharp_walks.hpp>
#include <oracle/union_coverage.hpp>

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

namespace sr = splinefig::render;

namespace {

struct Case {
  std::vector<oracle::P2> pts;
  bool closed = false;
  double width = 1;
  int join = 0, cap = 0;
  double miter_limit = 4;
};

std::string describe(const Case& c) {
  std::ostringstream o;
  o.precision(17);
  o << "width " << c.width << " join " << c.join << " cap " << c.cap << " limit " << c.miter_limit
    << (c.closed ? " closed" : " open") << " points";
  for (auto p : c.pts) o << " (" << p.x << "," << p.y << ")";
  return o.str();
}

testutil::ErrorStats check_case(const Case& c, int W, int H) {
  const sr::Join joins[] = {sr::Join::Miter, sr::Join::Round, sr::Join::Bevel};
  const sr::Cap caps[] = {sr::Cap::Butt, sr::Cap::Round, sr::Cap::Square};
  std::vector<sr::Vec2> pts;
  for (auto p : c.pts) pts.push_back({p.x, p.y});
  sr::StrokeStyle st;
  st.width = c.width;
  st.join = joins[c.join];
  st.cap = caps[c.cap];
  st.miter_limit = c.miter_limit;
  auto got = testutil::rendered_coverage(W, H, [&](sr::Scene& s) { s.stroke_polyline(pts, c.closed, st, {1, 1, 1, 1}); });
  auto pieces = oracle::stroke_pieces(c.pts, c.closed, c.width, static_cast<oracle::Join>(c.join), c.miter_limit,
                                      static_cast<oracle::Cap>(c.cap));
  auto want = oracle::union_coverage(pieces, W, H);
  return testutil::compare(got, want);
}

void run_cases(const std::vector<Case>& cases, int W, int H, double max_bound = 1.0 / 255) {
  double worst = 0, mean_sum = 0;
  for (const Case& c : cases) {
    auto e = check_case(c, W, H);
    INFO(describe(c));
    INFO("max error " << e.max << " at pixel (" << e.worst % W << "," << e.worst / W << "), mean " << e.mean);
    // Round joins and caps are arcs drawn as chords within 1e-4 px (geometry.hpp): several of
    // them in one pixel may add up to a few times that.
    REQUIRE(e.max <= (c.join == 1 || c.cap == 1 ? std::max(max_bound, 4e-4) : max_bound));
    REQUIRE(e.mean <= 1e-3);
    worst = std::max(worst, e.max);
    mean_sum += e.mean;
  }
  WARN("worst max error " << worst << ", average mean error " << mean_sum / cases.size());
}

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

}  // namespace

TEST_CASE("stroke coverage equals the exact union area: random polylines, every cap and join") {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Case> cases;
  for (int join = 0; join < 3; ++join)
    for (int cap = 0; cap < 3; ++cap)
      for (int rep = 0; rep < 4; ++rep) {
        Case c;
        c.join = join;
        c.cap = cap;
        c.width = log_uniform(rng, 0.1, 20);
        c.miter_limit = 1 + 5 * u(rng);
        const int n = 2 + static_cast<int>(u(rng) * 4);
        for (int i = 0; i < n; ++i) c.pts.push_back({6 + 28 * u(rng), 6 + 28 * u(rng)});
        c.closed = rep == 3;
        cases.push_back(c);
      }
  run_cases(cases, 40, 40);
}

TEST_CASE("stroke coverage is exact for axis-aligned paths on and off the pixel grid") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Case> cases;
  for (int k = 0; k < 18; ++k) {
    Case c;
    c.join = k % 3;
    c.cap = (k / 3) % 3;
    // integer, half-integer and arbitrary sub-pixel placements
    const double snap = k % 3 == 0 ? 1.0 : (k % 3 == 1 ? 0.5 : 0.0);
    auto q = [&](double v) { return snap > 0 ? std::round(v / snap) * snap : v; };
    c.width = k % 2 ? q(0.5 + 6 * u(rng)) + (snap > 0 ? 0 : 0) : 0.1 + 4 * u(rng);
    if (c.width <= 0) c.width = 1;
    oracle::P2 p{q(8 + 8 * u(rng)), q(8 + 8 * u(rng))};
    c.pts.push_back(p);
    for (int i = 0; i < 4; ++i) {
      double len = q(4 + 10 * u(rng));
      if (i % 2 == 0) p.x += (u(rng) < 0.5 ? -1 : 1) * len; else p.y += (u(rng) < 0.5 ? -1 : 1) * len;
      p.x = std::clamp(p.x, 4.0, 28.0);
      p.y = std::clamp(p.y, 4.0, 28.0);
      c.pts.push_back(p);
    }
    cases.push_back(c);
  }
  run_cases(cases, 32, 32);
}

TEST_CASE("stroke coverage is exact for diagonal and nearly axis-aligned segments") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Case> cases;
  for (int k = 0; k < 18; ++k) {
    Case c;
    c.join = k % 3;
    c.cap = (k / 3) % 3;
    c.width = log_uniform(rng, 0.1, 12);
    double ang = (k % 2 ? 0.25 * oracle::kPi : 1e-3 * (u(rng) - 0.5)) + (k % 4 >= 2 ? 0.5 * oracle::kPi : 0);
    oracle::P2 a{8 + 4 * u(rng), 8 + 4 * u(rng)};
    double len = 10 + 10 * u(rng);
    oracle::P2 b{a.x + len * std::cos(ang), a.y + len * std::sin(ang)};
    c.pts = {a, b, {b.x + 6 * std::cos(ang + 2.2), b.y + 6 * std::sin(ang + 2.2)}};
    cases.push_back(c);
  }
  run_cases(cases, 40, 40);
}

TEST_CASE("a dense self-crossing polyline is covered once: no double coverage, no beads") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Case> cases;
  for (int k = 0; k < 9; ++k) {
    Case c;
    c.join = k % 3;
    c.cap = (k / 3) % 3;
    c.width = 0.3 + 2.5 * u(rng);
    c.miter_limit = 10;
    // a random scribble, and a densely sampled curve that loops over itself
    if (k % 2 == 0) {
      for (int i = 0; i < 25; ++i) c.pts.push_back({5 + 22 * u(rng), 5 + 22 * u(rng)});
    } else {
      for (int i = 0; i <= 200; ++i) {
        double t = 2 * oracle::kPi * i / 200;
        c.pts.push_back({16 + 10 * std::sin(2 * t + 0.3), 16 + 10 * std::sin(3 * t)});
      }
    }
    cases.push_back(c);
  }
  run_cases(cases, 32, 32);
}

TEST_CASE("hairlines keep their exact area: a 0.1 px line covers 0.1 of each pixel it crosses") {
  // Horizontal line through the middle of row 5: every pixel fully along it gets 0.1 exactly.
  std::vector<sr::Vec2> pts{{2, 5.5}, {18, 5.5}};
  sr::StrokeStyle st;
  st.width = 0.1;
  auto cov = testutil::rendered_coverage(20, 10, [&](sr::Scene& s) { s.stroke_polyline(pts, false, st, {1, 1, 1, 1}); });
  for (int x = 2; x < 18; ++x) CHECK(cov[5 * 20 + x] == Approx(0.1).margin(1e-9));
  double total = 0;
  for (double c : cov) total += c;
  CHECK(total == Approx(1.6).margin(1e-9));
}

TEST_CASE("self-overlapping strokes that leave the canvas are covered exactly up to its edges") {
  // Outside the canvas the outline is projected onto the canvas's sides, so pieces of it run
  // along a side together and then leave it: those are changes of order for the scan converter.
  std::mt19937_64 rng(4213);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Case> cases;
  for (int k = 0; k < 48; ++k) {
    Case c;
    c.join = k % 3;
    c.width = 0.5 + 2.5 * u(rng);
    const int side = k % 4;
    oracle::P2 q{side == 0 ? 2.0 : side == 1 ? 30.0 : 16.0, side == 2 ? 2.0 : side == 3 ? 30.0 : 16.0};
    if (side < 2) q.y = 4 + 24 * u(rng); else q.x = 4 + 24 * u(rng);
    for (int i = 0; i < 60; ++i) {
      c.pts.push_back(q);
      const double a = 2 * oracle::kPi * u(rng);
      q = {q.x + 3 * std::cos(a), q.y + 3 * std::sin(a)};
    }
    cases.push_back(c);
  }
  run_cases(cases, 32, 32);
}

// The outline's inner side goes through the offset lines' intersection only where the
// quadrilateral that removes lies in both segments' rectangles (stroke.hpp): these are the turns
// where X lies within both segments but an inner corner does not lie in the other rectangle.
TEST_CASE("sharp turns next to segments shorter than the half-width are covered exactly") {
  std::vector<Case> cases;
  // A 70.5-degree turn (miter, ratio 1.22) into a last segment of 1.17 px at width 3, and a
  // 55-degree bevel into 0.81 px: 0.071 and 0.148 of a pixel were left uncovered. The points are
  // those of 256^2 random walks moved by whole pixels onto this canvas.
  Case miter;
  miter.width = 3;
  miter.pts = {{86.53 - 80, 186.36 - 170}, {98.76 - 80, 184.51 - 170}, {99.31 - 80, 185.54 - 170}};
  cases.push_back(miter);
  Case bevel;
  bevel.width = 3;
  bevel.join = 2;
  bevel.pts = {{52.65 - 40, 121.22 - 100}, {53.24 - 40, 116.38 - 100}, {52.63 - 40, 115.84 - 100}};
  cases.push_back(bevel);
  // Every join and cap, turns from 20 to 180 degrees, the short segment first or last, from a
  // tenth of the half-width to a little over the width.
  for (int join = 0; join < 3; ++join)
    for (int cap = 0; cap < 3; ++cap)
      for (double turn : {20.0, 35.0, 55.0, 70.5, 90.0, 120.0, 150.0, 170.0, 178.0, 180.0})
        for (double rel : {0.1, 0.3, 0.6, 0.9, 1.2, 1.6, 2.5})
          for (bool short_last : {true, false}) {
            Case c;
            c.join = join;
            c.cap = cap;
            c.width = 3;
            const double a = 0.3 + turn * oracle::kPi / 180, len = rel * 1.5;
            const oracle::P2 P{12.37, 11.81}, A{P.x - 8 * std::cos(0.3), P.y - 8 * std::sin(0.3)};
            const oracle::P2 B{P.x + len * std::cos(a), P.y + len * std::sin(a)};
            if (short_last) c.pts = {A, P, B}; else c.pts = {B, P, A};
            cases.push_back(c);
          }
  run_cases(cases, 24, 24, 1e-4);
}

TEST_CASE("random walks of hairpins, near-reversals and sub-width segments are covered exactly") {
  std::mt19937_64 rng(20261202);
  std::vector<Case> cases;
  for (double width : {1.0, 3.0, 4.0, 7.0})
    for (int join = 0; join < 3; ++join)
      for (int cap = 0; cap < 3; ++cap)
        for (int rep = 0; rep < 2; ++rep) {
          Case c;
          c.join = join;
          c.cap = cap;
          c.width = width;
          c.miter_limit = rep ? 10 : 4;
          c.closed = rep == 1 && cap == 0;
          c.pts = oracle::sharp_walk(rng, 40, width, 8, 40);
          cases.push_back(c);
        }
  run_cases(cases, 48, 48, 1e-4);
}
