// Long strokes, whose outline is built in pieces of 2^15 points (renderer/src/stroke.hpp:
// OutlinePieces): the same bytes for any thread count, and the exact union's coverage where the
// pieces meet, at a sharp turn and at a self-crossing.
#include "coverage_helpers.hpp"
#include <oracle/union_coverage.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace sr = splinefig::render;

namespace {

constexpr std::size_t kPiece = std::size_t{1} << 15;  // points per outline piece (kOutlinePiecePoints)

// Appends `steps` points on the line from pts.back() to `to`, the last one exactly `to`, moved
// off the line by wiggle * sin(...) (a dense, gently turning path).
void line_to(std::vector<oracle::P2>& pts, oracle::P2 to, std::size_t steps, double wiggle = 0) {
  const oracle::P2 from = pts.back();
  const double dx = to.x - from.x, dy = to.y - from.y, len = std::hypot(dx, dy);
  for (std::size_t k = 1; k <= steps; ++k) {
    if (k == steps) {
      pts.push_back(to);
      break;
    }
    const double t = static_cast<double>(k) / static_cast<double>(steps);
    const double off = wiggle * std::sin(0.002 * static_cast<double>(k));
    pts.push_back({from.x + t * dx - off * dy / len, from.y + t * dy + off * dx / len});
  }
}

// A path of 2^16 + 1200 points on a 40 x 40 canvas whose bulk lies outside it: point 2^15 (a
// piece boundary) is a sharp turn T on the canvas, and point 2^16 (the next one) is X, where the
// path crosses its earlier pass through X (a vertex of both passes, at right angles).
std::vector<oracle::P2> crossing_path() {
  const oracle::P2 T{20, 24}, X{24, 16};
  std::vector<oracle::P2> p{{5, 5}, {8, 3}};
  line_to(p, {10, -8}, 4);                    // up, off the canvas
  line_to(p, {36, -8}, kPiece - 7 - p.size(), 0.6);  // dense, above it
  line_to(p, {36, 2}, 4);
  line_to(p, T, 4);                           // down to the turn: point 2^15
  line_to(p, {28, 8}, 8);                     // sharply back up, through X = (24, 16) (step 4)
  line_to(p, {34, 50}, 6);                    // off the canvas, below it
  line_to(p, {6, 50}, 2 * kPiece - 11 - p.size(), 0.6);
  line_to(p, {16, 12}, 10);
  line_to(p, {20, 14}, 1);
  line_to(p, X, 1);                           // point 2^16, across the first pass
  line_to(p, {28, 18}, 1);
  line_to(p, {50, 30}, 6);                    // off the canvas, to the right
  line_to(p, {50, 6}, 1100, 0.6);
  line_to(p, {35, 35}, 6);                    // the end cap on the canvas
  return p;
}

// Coverage of the union of the stroke's pieces, keeping only the pieces that can reach the canvas.
std::vector<double> oracle_coverage(const std::vector<oracle::P2>& pts, double width, oracle::Join join, double limit,
                                    oracle::Cap cap, int W, int H) {
  std::vector<oracle::Poly> near;
  for (auto& piece : oracle::stroke_pieces(pts, false, width, join, limit, cap)) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const auto& q : piece) {
      x0 = std::min(x0, q.x); x1 = std::max(x1, q.x);
      y0 = std::min(y0, q.y); y1 = std::max(y1, q.y);
    }
    if (x1 > 0 && x0 < W && y1 > 0 && y0 < H) near.push_back(std::move(piece));
  }
  return oracle::union_coverage(near, W, H);
}

}  // namespace

TEST_CASE("long strokes: pieces meeting at a sharp turn and at a self-crossing keep the exact union's coverage") {
  const auto pts = crossing_path();
  REQUIRE(pts.size() > 2 * kPiece + 1000);
  REQUIRE((pts[kPiece].x == 20 && pts[kPiece].y == 24));
  REQUIRE((pts[2 * kPiece].x == 24 && pts[2 * kPiece].y == 16));
  REQUIRE((pts[kPiece + 4].x == 24 && pts[kPiece + 4].y == 16));
  std::vector<sr::Vec2> spts;
  for (auto q : pts) spts.push_back({q.x, q.y});
  const sr::Join joins[] = {sr::Join::Miter, sr::Join::Round, sr::Join::Bevel};
  const sr::Cap caps[] = {sr::Cap::Butt, sr::Cap::Round, sr::Cap::Square};
  const int W = 40, H = 40;
  for (double width : {0.7, 2.5, 4.0}) {
    for (int j = 0; j < 3; ++j) {
      const int c = (j + static_cast<int>(width)) % 3;
      sr::StrokeStyle st;
      st.width = width;
      st.join = joins[j];
      st.cap = caps[c];
      st.miter_limit = 10;
      const auto want = oracle_coverage(pts, width, static_cast<oracle::Join>(j), 10, static_cast<oracle::Cap>(c), W, H);
      for (int threads : {1, 2}) {
        auto got = testutil::rendered_coverage(
            W, H, [&](sr::Scene& s) { s.stroke_polyline(spts, false, st, {1, 1, 1, 1}); }, threads);
        auto e = testutil::compare(got, want);
        INFO("width " << width << " join " << j << " cap " << c << " threads " << threads << ": max error " << e.max
                      << " at pixel " << e.worst << ", mean " << e.mean);
        CHECK(e.max <= 1e-4);
        CHECK(e.counted > 100);
      }
    }
  }
}

TEST_CASE("long strokes: byte-identical for any thread count, under the box and the tent filter") {
  // A self-crossing Lissajous of 200,001 points (seven outline pieces), one with repeated points
  // (dropped before the outline is cut), and short items around them.
  std::vector<sr::Vec2> curve, repeats;
  for (int k = 0; k <= 200000; ++k) {
    const double t = 2 * 3.141592653589793 * k / 200000;
    curve.push_back({75 + 70 * std::sin(3 * t + 1.5707963), 65 + 60 * std::sin(4 * t)});
  }
  for (int k = 0; k < 160000; ++k) {
    const double t = 2 * 3.141592653589793 * k / 160000;
    const sr::Vec2 q{75 + 50 * std::cos(5 * t), 65 + 50 * std::sin(7 * t)};
    repeats.push_back(q);
    if (k % 997 == 0) repeats.push_back(q);
  }
  for (const auto& filter : {splinefig::Kernel::box(), splinefig::Kernel::tent()}) {
    sr::Scene s(150, 130, {1, 1, 1, 1}, filter);
    s.fill_circle({40, 40}, 20, {0.9f, 0.7f, 0, 0.5f});
    sr::StrokeStyle st;
    st.width = 1.5;
    st.join = sr::Join::Round;
    st.cap = sr::Cap::Round;
    s.stroke_polyline(curve, false, st, {0.1f, 0.2f, 0.7f, 0.8f});
    st.width = 0.8;
    st.join = sr::Join::Miter;
    s.stroke_polyline(repeats, false, st, {0.8f, 0.1f, 0.1f, 0.6f});
    s.stroke_polyline({{10, 10}, {140, 120}, {20, 110}}, false, st, {0, 0, 0, 1});
    const auto ref = sr::rasterize(s, 1);
    std::size_t drawn = 0;
    for (std::size_t i = 0; i < ref.pixels.size(); i += 4) drawn += ref.pixels[i] < 0.99f || ref.pixels[i + 2] < 0.99f;
    CHECK(drawn > 1000);
    for (int threads : {2, 3, 4}) {
      const auto img = sr::rasterize(s, threads);
      INFO("filter " << filter.name() << ", threads " << threads);
      REQUIRE(img.pixels.size() == ref.pixels.size());
      CHECK(std::memcmp(img.pixels.data(), ref.pixels.data(), ref.pixels.size() * sizeof(float)) == 0);
    }
  }
}

TEST_CASE("long strokes: one thread builds the outline band by band, with the bytes and report of the whole outline") {
  // On one thread under the box filter and a coverage tolerance above 0, a long stroke's outline
  // pieces are built as the bands reach them and their memory given back behind them
  // (renderer/src/outline_stream.hpp); with 2 threads, or at tolerance 0, the whole outline is
  // built first. A Lissajous curve of 7 x 9 loops (300,001 points, ten pieces) passes every
  // row many times, so many pieces are built and dropped at each band; its joins are sharp
  // enough at the ends of the loops for the miter tips and square caps to reach past the points.
  std::vector<sr::Vec2> curve;
  for (int k = 0; k <= 300000; ++k) {
    const double t = 2 * 3.141592653589793 * k / 300000;
    curve.push_back({100 + 96 * std::sin(7 * t + 0.3), 90 + 86 * std::sin(9 * t)});
  }
  // A dense walk (many crossings per chain): some of its bands are drawn from its pieces, so the
  // report's bands count the rows of the streamed outline.
  std::vector<sr::Vec2> walk{{100, 90}};
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (int k = 0; k < 200000; ++k) {
    h ^= h << 13;
    h ^= h >> 7;
    h ^= h << 17;
    const double a = static_cast<double>(h >> 11) * 0x1p-53 * 2 * 3.141592653589793;
    sr::Vec2 q{walk.back().x + 0.7 * std::cos(a), walk.back().y + 0.7 * std::sin(a)};
    q.x = std::clamp(q.x, 70.0, 130.0);
    q.y = std::clamp(q.y, 40.0, 150.0);
    walk.push_back(q);
  }
  auto scene = [&](double tolerance, sr::Join join, sr::Cap cap, bool with_walk) {
    sr::Scene s(200, 180, {1, 1, 1, 1});
    s.set_coverage_tolerance(tolerance);
    s.set_max_crossings(INFINITY);
    s.fill_circle({40, 40}, 20, {0.9f, 0.7f, 0, 0.5f});
    sr::StrokeStyle st;
    st.width = 2.5;
    st.join = join;
    st.cap = cap;
    st.miter_limit = 10;
    s.stroke_polyline(curve, false, st, {0.1f, 0.2f, 0.7f, 0.8f});
    st.width = 1;
    if (with_walk) s.stroke_polyline(walk, false, st, {0.8f, 0.1f, 0.1f, 0.6f});
    s.stroke_polyline({{10, 10}, {190, 170}, {20, 160}}, false, st, {0, 0, 0, 1});
    return s;
  };
  for (const auto& [join, cap] : {std::pair{sr::Join::Miter, sr::Cap::Square}, {sr::Join::Round, sr::Cap::Round}}) {
    INFO("join " << static_cast<int>(join) << " cap " << static_cast<int>(cap));
    sr::RasterReport streamed, whole;
    const auto one = sr::rasterize(scene(sr::kDefaultCoverageTolerance, join, cap, true), 1, &streamed);
    const auto two = sr::rasterize(scene(sr::kDefaultCoverageTolerance, join, cap, true), 2, &whole);
    REQUIRE(one.pixels.size() == two.pixels.size());
    CHECK(std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)) == 0);
    // Without the walk nothing is drawn from pieces: the same bytes as at tolerance 0, where the
    // one thread builds the whole outline first.
    const auto curve_only = sr::rasterize(scene(sr::kDefaultCoverageTolerance, join, cap, false), 1);
    const auto exact = sr::rasterize(scene(0, join, cap, false), 1);
    REQUIRE(curve_only.pixels.size() == exact.pixels.size());
    CHECK(std::memcmp(curve_only.pixels.data(), exact.pixels.data(), exact.pixels.size() * sizeof(float)) == 0);
    REQUIRE(whole.items.size() == 1);
    CHECK(whole.items[0].index == 2);
    CHECK(whole.items[0].piece_bands > 0);
    REQUIRE(streamed.items.size() == 1);
    CHECK(streamed.items[0].index == whole.items[0].index);
    CHECK(streamed.items[0].bands == whole.items[0].bands);
    CHECK(streamed.items[0].piece_bands == whole.items[0].piece_bands);
  }
}
