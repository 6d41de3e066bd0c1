// Clipping exact paths to a box: the curves are built from polynomials with chosen rational
// roots, so where they cross the box's sides is known beforehand, and every kept piece is
// compared with the original curve evaluated here by its Bernstein form.
#include <catch2/catch.hpp>

#include "figures/src/paint/clip_path.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace sfd = splinefig::figures::detail;
namespace sr = splinefig::render;
using sr::Vec2;

namespace {

// Bernstein coefficients of a0 + a1 t + a2 t^2 + a3 t^3.
std::array<double, 4> from_power(double a0, double a1, double a2, double a3) {
  return {a0, a0 + a1 / 3, a0 + 2 * a1 / 3 + a2 / 3, a0 + a1 + a2 + a3};
}

// k (t - r1)(t - r2)(t - r3) + c in Bernstein form.
std::array<double, 4> with_roots(double k, double r1, double r2, double r3, double c) {
  return from_power(c - k * r1 * r2 * r3, k * (r1 * r2 + r1 * r3 + r2 * r3), -k * (r1 + r2 + r3), k);
}

double bernstein(const std::array<double, 4>& b, double t) {
  const double s = 1 - t;
  return s * s * s * b[0] + 3 * s * s * t * b[1] + 3 * s * t * t * b[2] + t * t * t * b[3];
}

struct Cubic {
  std::array<double, 4> x, y;
  Vec2 at(double t) const { return {bernstein(x, t), bernstein(y, t)}; }
};

// One piece of a clipped path: its start and its control points (a line as its elevation).
struct Piece {
  bool cubic;
  Cubic c;
};

struct Run {
  std::vector<Piece> pieces;
  bool closed = false;
};

// The runs of clip_path's result, piece by piece.
std::vector<Run> runs_of(const std::vector<sr::Path>& paths) {
  std::vector<Run> out;
  for (const sr::Path& p : paths) {
    Run run;
    Vec2 cur{};
    std::size_t k = 0;
    for (sr::Path::Verb v : p.verbs()) {
      const auto& q = p.points();
      if (v == sr::Path::Verb::Move) {
        REQUIRE(k == 0);  // one subpath per run
        cur = q[k++];
      } else if (v == sr::Path::Verb::Line) {
        const Vec2 e = q[k++];
        run.pieces.push_back({false, {{cur.x, (2 * cur.x + e.x) / 3, (cur.x + 2 * e.x) / 3, e.x},
                                      {cur.y, (2 * cur.y + e.y) / 3, (cur.y + 2 * e.y) / 3, e.y}}});
        cur = e;
      } else if (v == sr::Path::Verb::Cubic) {
        run.pieces.push_back({true, {{cur.x, q[k].x, q[k + 1].x, q[k + 2].x}, {cur.y, q[k].y, q[k + 1].y, q[k + 2].y}}});
        cur = q[k + 2];
        k += 3;
      } else {
        run.closed = true;
      }
    }
    out.push_back(run);
  }
  return out;
}

// The piece is the original curve on [a, b]: the same points at matching parameters.
void check_same_curve(const Piece& piece, const Cubic& original, double a, double b) {
  for (int j = 0; j <= 16; ++j) {
    const double s = j / 16.0;
    const Vec2 p = piece.c.at(s), q = original.at(a + s * (b - a));
    INFO("s = " << s << " on [" << a << ", " << b << "]");
    CHECK(std::abs(p.x - q.x) <= 1e-12);
    CHECK(std::abs(p.y - q.y) <= 1e-12);
  }
}

sr::Path path_of(const Cubic& c) {
  sr::Path p;
  p.move_to({c.x[0], c.y[0]});
  p.cubic_to({c.x[1], c.y[1]}, {c.x[2], c.y[2]}, {c.x[3], c.y[3]});
  return p;
}

const sfd::Rect kBox{100, 0, 500, 100};  // left, top, right, bottom

// A line from y = 10 to y = 30 as a cubic.
const std::array<double, 4> kY = from_power(10, 20, 0, 0);

}  // namespace

TEST_CASE("clip_path: a cubic's crossings with a value are found to full precision") {
  SECTION("three simple roots") {
    const auto r = sfd::cubic_crossings(with_roots(640, 0.25, 0.5, 0.75, 100), 100);
    REQUIRE(r.size() == 3);
    CHECK(std::abs(r[0] - 0.25) <= 1e-15);
    CHECK(std::abs(r[1] - 0.5) <= 1e-15);
    CHECK(std::abs(r[2] - 0.75) <= 1e-15);
  }
  SECTION("a root near an end, two close together") {
    const auto r = sfd::cubic_crossings(with_roots(1000, 1e-6, 0.5, 0.5 + 1e-6, 3), 3);
    REQUIRE(r.size() == 3);
    CHECK(std::abs(r[0] - 1e-6) <= 1e-15);
    // The coefficients (up to 500) are rounded to doubles, about 1e-13; the slope at the close
    // pair is only 1000 * 0.5 * 1e-6 = 5e-4, so the pair itself moves by up to 1e-13 / 5e-4.
    CHECK(std::abs(r[1] - 0.5) <= 2e-10);
    CHECK(std::abs(r[2] - (0.5 + 1e-6)) <= 2e-10);
    CHECK(r[1] < r[2]);
  }
  SECTION("a quadratic: 16 (t - 1/4)(t - 3/4)") {
    const auto r = sfd::cubic_crossings(from_power(3, -16, 16, 0), 0);
    REQUIRE(r.size() == 2);
    CHECK(std::abs(r[0] - 0.25) <= 1e-15);
    CHECK(std::abs(r[1] - 0.75) <= 1e-15);
  }
  SECTION("a line and a constant") {
    const auto r = sfd::cubic_crossings(from_power(0, 1, 0, 0), 0.3);
    REQUIRE(r.size() == 1);
    CHECK(std::abs(r[0] - 0.3) <= 1e-16);
    CHECK(sfd::cubic_crossings({2, 2, 2, 2}, 2).empty());
    CHECK(sfd::cubic_crossings({2, 2, 2, 2}, 1).empty());
  }
  SECTION("a double root: the cubic touches the value once") {
    // 64 (t - 1/2)^2 (t + 1) = 64 t^3 - 48 t + 16
    const auto r = sfd::cubic_crossings(from_power(16, -48, 0, 64), 0);
    REQUIRE(r.size() == 1);
    CHECK(std::abs(r[0] - 0.5) <= 1e-8);
  }
  SECTION("no crossing: roots outside (0, 1), or only at its ends") {
    CHECK(sfd::cubic_crossings(with_roots(10, -0.5, 1.5, 2, 0), 0).empty());
    CHECK(sfd::cubic_crossings(with_roots(10, 0, 1, 2, 0), 0).empty());
  }
}

TEST_CASE("clip_path: a cubic leaving the box is cut exactly at the side") {
  // x(t) = 100 + 640 (t - 1/4)(t - 1/2)(t - 3/4): outside (x < 100) on (0, 1/4) and (1/2, 3/4).
  const Cubic c{with_roots(640, 0.25, 0.5, 0.75, 100), kY};
  const auto runs = runs_of(sfd::clip_path(path_of(c), kBox));
  REQUIRE(runs.size() == 2);
  const std::array<std::array<double, 2>, 2> kept{{{0.25, 0.5}, {0.75, 1}}};
  for (std::size_t i = 0; i < 2; ++i) {
    REQUIRE(runs[i].pieces.size() == 1);
    CHECK_FALSE(runs[i].closed);
    const Piece& p = runs[i].pieces[0];
    CHECK(p.cubic);
    check_same_curve(p, c, kept[i][0], kept[i][1]);
  }
  // Ends on the left side.
  CHECK(std::abs(runs[0].pieces[0].c.x[0] - 100) <= 1e-12);
  CHECK(std::abs(runs[0].pieces[0].c.x[3] - 100) <= 1e-12);
  CHECK(std::abs(runs[1].pieces[0].c.x[0] - 100) <= 1e-12);
  CHECK(runs[1].pieces[0].c.x[3] == c.x[3]);
  CHECK(runs[1].pieces[0].c.y[3] == c.y[3]);
}

TEST_CASE("clip_path: crossings of the left and right sides, and of the bottom and top") {
  SECTION("x = -100 + 800 t: x = 100 at t = 1/4, x = 500 at t = 3/4") {
    const Cubic c{from_power(-100, 800, 0, 0), from_power(50, 0, 0, 0)};
    const auto runs = runs_of(sfd::clip_path(path_of(c), kBox));
    REQUIRE(runs.size() == 1);
    REQUIRE(runs[0].pieces.size() == 1);
    check_same_curve(runs[0].pieces[0], c, 0.25, 0.75);
    CHECK(std::abs(runs[0].pieces[0].c.x[0] - 100) <= 1e-12);
    CHECK(std::abs(runs[0].pieces[0].c.x[3] - 500) <= 1e-12);
  }
  SECTION("y = 150 - 200 t: y = 100 at t = 1/4, y = 0 at t = 3/4") {
    const Cubic c{from_power(300, 0, 0, 0), from_power(150, -200, 0, 0)};
    const auto runs = runs_of(sfd::clip_path(path_of(c), kBox));
    REQUIRE(runs.size() == 1);
    REQUIRE(runs[0].pieces.size() == 1);
    check_same_curve(runs[0].pieces[0], c, 0.25, 0.75);
    CHECK(std::abs(runs[0].pieces[0].c.y[0] - 100) <= 1e-12);
    CHECK(std::abs(runs[0].pieces[0].c.y[3] - 0) <= 1e-12);
  }
}

TEST_CASE("clip_path: a curve touching a side from inside is whole, from outside gone") {
  // y(t) = 64 (t - 1/2)^2 (t + 1) >= 0 touches the top (y = 0) at t = 1/2.
  const std::array<double, 4> touch = from_power(16, -48, 0, 64);
  const std::array<double, 4> x = from_power(200, 100, 0, 0);
  SECTION("inside") {
    const Cubic c{x, touch};
    const auto runs = runs_of(sfd::clip_path(path_of(c), kBox));
    REQUIRE(runs.size() == 1);
    const auto& ps = runs[0].pieces;
    REQUIRE((ps.size() == 1 || ps.size() == 2));
    if (ps.size() == 1) check_same_curve(ps[0], c, 0, 1);
    else check_same_curve(ps[0], c, 0, 0.5), check_same_curve(ps[1], c, 0.5, 1);
  }
  SECTION("outside") {
    const Cubic c{x, {-touch[0], -touch[1], -touch[2], -touch[3]}};
    CHECK(sfd::clip_path(path_of(c), kBox).empty());
  }
}

TEST_CASE("clip_path: a curve wholly outside, though its control points are not") {
  // Around the box's top-left corner (100, 0): control points inside the box, the curve not.
  // x(t) = 390 t (1 - t) <= 97.5 < 100, while (130, 30) is a control point inside.
  const Cubic c{{0, 130, 130, 0}, {-60, 30, 30, -60}};
  CHECK(sfd::clip_path(path_of(c), kBox).empty());
}

TEST_CASE("clip_path: a path inside is kept whole, a piece on a side included") {
  sr::Path p;
  p.move_to({100, 0});  // along the top side, then down the left side
  p.line_to({300, 0});
  p.cubic_to({300, 50}, {200, 50}, {100, 100});
  p.close();
  const auto runs = runs_of(sfd::clip_path(p, kBox));
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].closed);
  REQUIRE(runs[0].pieces.size() == 3);  // the closing line is a piece
  CHECK_FALSE(runs[0].pieces[0].cubic);
  CHECK(runs[0].pieces[1].cubic);
  CHECK_FALSE(runs[0].pieces[2].cubic);
  CHECK(runs[0].pieces[2].c.x[3] == 100);
  CHECK(runs[0].pieces[2].c.y[3] == 0);
}

TEST_CASE("clip_path: a closed path that starts inside joins its last part to its first") {
  // x(t) = 100 - 640 (t - 1/4)(t - 1/2)(t - 3/4): inside on (0, 1/4) and (1/2, 3/4), from
  // (160, 10) to (40, 30); the closing line back to (160, 10) meets x = 100 half way, at (100, 20).
  const Cubic c{with_roots(-640, 0.25, 0.5, 0.75, 100), kY};
  REQUIRE(c.at(0).x == 160);
  REQUIRE(c.at(1).x == 40);
  sr::Path p = path_of(c);
  p.close();
  const auto runs = runs_of(sfd::clip_path(p, kBox));
  REQUIRE(runs.size() == 2);
  // In order along the path: the middle part, then the closing line's half joined to the start.
  REQUIRE(runs[0].pieces.size() == 1);
  check_same_curve(runs[0].pieces[0], c, 0.5, 0.75);
  REQUIRE(runs[1].pieces.size() == 2);
  CHECK_FALSE(runs[1].closed);
  const Piece& line = runs[1].pieces[0];
  CHECK_FALSE(line.cubic);
  CHECK(std::abs(line.c.x[0] - 100) <= 1e-12);
  CHECK(std::abs(line.c.y[0] - 20) <= 1e-12);
  CHECK(line.c.x[3] == 160);
  CHECK(line.c.y[3] == 10);
  check_same_curve(runs[1].pieces[1], c, 0, 0.25);
  CHECK(std::abs(runs[1].pieces[1].c.x[3] - 100) <= 1e-12);
}
