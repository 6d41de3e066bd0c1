// Strokes resolved from their pieces under the coverage tolerance (renderer/src/piece_coverage.hpp):
// dense self-crossing strokes whose bands go past the sweep's per-band limit, checked pixel by
// pixel against the independent union oracle (oracle/union_coverage.hpp) and against the exact
// sweep of the outline (tolerance 0); the report says which bands were resolved so; bytes do not
// depend on the thread count; the tolerance is validated.
#include "coverage_helpers.hpp"
#include <oracle/union_coverage.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

namespace sr = splinefig::render;

namespace {

struct Dense {
  std::vector<oracle::P2> pts;
  double width = 1;
  int join = 0, cap = 0;
  bool closed = false;
};

// n points uniform on [m, size - m]^2 (a dense self-crossing polyline), seeded.
Dense uniform_stroke(unsigned seed, int n, int size, double width, int join, int cap) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-2.0, size + 2.0);
  Dense d;
  for (int i = 0; i < n; ++i) d.pts.push_back({u(rng), u(rng)});
  d.width = width;
  d.join = join;
  d.cap = cap;
  return d;
}

// A random walk with hairpins and sub-width segments: half the turns between 149 and 179
// degrees, the rest uniform; steps of 0.3..1.5 px (three in ten) or 20..60 px.
Dense hairpin_walk(unsigned seed, int n, int size, double width, int join, int cap) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Dense d;
  double x = size / 2.0, y = size / 2.0, a = 0;
  for (int i = 0; i < n; ++i) {
    d.pts.push_back({x, y});
    a += u(rng) < 0.5 ? (u(rng) < 0.5 ? -1 : 1) * (2.6 + 0.52 * u(rng)) : 6.3 * u(rng);
    const double step = u(rng) < 0.3 ? 0.3 + 1.2 * u(rng) : 20 + 40 * u(rng);
    auto reflect = [&](double v) {  // into [1, size - 1]
      const double lo = 1, hi = size - 1.0, p = 2 * (hi - lo);
      v = std::fmod(v - lo, p);
      if (v < 0) v += p;
      return lo + (v > hi - lo ? p - v : v);
    };
    x = reflect(x + step * std::cos(a));
    y = reflect(y + step * std::sin(a));
  }
  d.width = width;
  d.join = join;
  d.cap = cap;
  return d;
}

std::string describe(const Dense& d) {
  std::ostringstream o;
  o << d.pts.size() << " points, width " << d.width << " join " << d.join << " cap " << d.cap;
  return o.str();
}

struct Drawn {
  std::vector<double> cov;
  sr::RasterReport report;
  std::vector<float> pixels;
};

Drawn draw(const Dense& d, int size, double tolerance, int threads) {
  const sr::Join joins[] = {sr::Join::Miter, sr::Join::Round, sr::Join::Bevel};
  const sr::Cap caps[] = {sr::Cap::Butt, sr::Cap::Round, sr::Cap::Square};
  sr::Scene s(size, size, {0, 0, 0, 0});
  s.set_coverage_tolerance(tolerance);
  s.set_max_crossings(INFINITY);
  sr::StrokeStyle st;
  st.width = d.width;
  st.join = joins[d.join];
  st.cap = caps[d.cap];
  std::vector<sr::Vec2> pts;
  for (auto p : d.pts) pts.push_back({p.x, p.y});
  s.stroke_polyline(pts, d.closed, st, {1, 1, 1, 1});
  Drawn out;
  auto img = sr::rasterize(s, threads, &out.report);
  out.pixels.assign(img.pixels.begin(), img.pixels.end());
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) out.cov.push_back(img.pixel(x, y)[3]);
  return out;
}

int piece_bands(const sr::RasterReport& r) {
  int n = 0;
  for (const auto& it : r.items) n += it.piece_bands;
  return n;
}

}  // namespace

TEST_CASE("dense strokes resolved from their pieces match the union oracle", "[renderer][tolerance]") {
  const int size = 128;
  std::vector<Dense> cases;
  unsigned seed = 1;
  // Every join and every cap at least once.
  for (auto [join, cap] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}})
    cases.push_back(uniform_stroke(seed++, 2500, size, 1.0 + 0.7 * join, join, cap));
  // Hairpins and sub-width segments with the sharp joins (miter, bevel).
  cases.push_back(hairpin_walk(seed++, 12000, size, 1.5, 0, 0));
  cases.push_back(hairpin_walk(seed++, 12000, size, 2.5, 2, 2));
  cases.push_back(uniform_stroke(seed++, 5000, size, 0.3, 0, 0));  // hairlines: few solid pixels
  cases.push_back(uniform_stroke(seed++, 1200, size, 6, 1, 1));    // wide: solid interiors
  {
    Dense closed = uniform_stroke(seed++, 2500, size, 2, 2, 0);
    closed.closed = true;
    cases.push_back(closed);
  }
  // The oracle's pixels in two windows of 40 x 40: the middle (mostly solid pixels, the holes
  // between them resolved) and a corner (sparser: more pixels resolved by sweeping pieces).
  const int win = 40;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Dense& d = cases[k];
    INFO(describe(d));
    const Drawn got = draw(d, size, sr::kDefaultCoverageTolerance, 1);
    // The pieces were used (else this compares the exact sweep with the oracle again).
    REQUIRE(piece_bands(got.report) > 0);
    for (const int at : {(size - win) / 2, 0}) {
      auto pieces =
          oracle::stroke_pieces(d.pts, d.closed, d.width, static_cast<oracle::Join>(d.join), 4, static_cast<oracle::Cap>(d.cap));
      for (auto& poly : pieces)
        for (auto& q : poly) q = {q.x - at, q.y - at};
      const auto want = oracle::union_coverage(pieces, win, win);
      std::vector<double> mine;
      for (int y = at; y < at + win; ++y)
        for (int x = at; x < at + win; ++x) mine.push_back(got.cov[static_cast<std::size_t>(y) * size + x]);
      const auto e = testutil::compare(mine, want);
      INFO("window at " << at << ": max error " << e.max << " at pixel (" << at + e.worst % win << "," << at + e.worst / win << ")");
      // The tolerance holds; and the method is exact up to the arcs' flattening (1e-4 px chords,
      // which the oracle draws at 1e-6), as the outline's sweep is.
      CHECK(e.max <= sr::kDefaultCoverageTolerance);
      CHECK(e.max <= (d.join == 1 || d.cap == 1 ? 4e-4 : 1e-5));
    }
    // The outline's exact sweep (tolerance 0) gives the same coverage (whole canvas; three cases).
    if (k % 3 == 0) {
      const Drawn exact = draw(d, size, 0, 1);
      CHECK(piece_bands(exact.report) == 0);
      CHECK(testutil::compare(got.cov, exact.cov).max <= 1e-6);
    }
  }
}

TEST_CASE("bands resolved from pieces give the same bytes on any thread count", "[renderer][tolerance]") {
  const Dense d = uniform_stroke(77, 2000, 200, 1, 0, 0);
  const Drawn one = draw(d, 200, sr::kDefaultCoverageTolerance, 1);
  REQUIRE(piece_bands(one.report) > 0);
  REQUIRE(one.report.items.size() == 1);
  CHECK(one.report.items[0].index == 0);
  CHECK(one.report.items[0].bands == 13);  // rows 0..199
  CHECK(one.report.tolerance == sr::kDefaultCoverageTolerance);
  for (int threads : {2, 3, 5}) {
    const Drawn many = draw(d, 200, sr::kDefaultCoverageTolerance, threads);
    CHECK(many.pixels == one.pixels);
    CHECK(piece_bands(many.report) == piece_bands(one.report));
  }
}

TEST_CASE("the work limit holds under the tolerance, and tolerance 0 refuses by the crossing bound", "[renderer][tolerance]") {
  const Dense d = uniform_stroke(5, 3000, 256, 1, 0, 0);
  std::vector<sr::Vec2> pts;
  for (auto p : d.pts) pts.push_back({p.x, p.y});
  auto scene = [&](double tolerance, double limit) {
    sr::Scene s(256, 256);
    s.set_coverage_tolerance(tolerance);
    s.set_max_crossings(limit);
    s.stroke_polyline(pts, false, sr::StrokeStyle{}, {0, 0, 0, 1});
    return s;
  };
  // About 4e6 crossings: refused before the sweep starts.
  CHECK_THROWS_WITH(sr::rasterize(scene(0, 1e6), 1), Catch::Contains("crosses itself at least"));
  sr::RasterReport report;
  CHECK_NOTHROW(sr::rasterize(scene(sr::kDefaultCoverageTolerance, 1e7), 1, &report));
  CHECK(piece_bands(report) > 0);
  for (int threads : {1, 2})
    CHECK_THROWS_WITH(sr::rasterize(scene(sr::kDefaultCoverageTolerance, 1e4), threads),
                      Catch::Contains("item 1 (stroked polyline)") && Catch::Contains("work limit"));
}

TEST_CASE("the coverage tolerance is checked", "[renderer][tolerance]") {
  sr::Scene s(8, 8);
  CHECK(s.coverage_tolerance() == sr::kDefaultCoverageTolerance);
  s.set_coverage_tolerance(0);
  CHECK(s.coverage_tolerance() == 0);
  for (double bad : {-1e-9, 1.5, double(NAN), double(INFINITY)})
    CHECK_THROWS_WITH(s.set_coverage_tolerance(bad), Catch::Contains("coverage tolerance") && Catch::Contains("[0, 1]"));
}
