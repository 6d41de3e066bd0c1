// No command prints NaN or infinity as an answer: numbers beyond the range of a double, basis
// parameters whose matrix overflows or whose tangents point backwards, and data that drive a
// curve out of range are one-line errors naming the input, with nothing on stdout.
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using splinefig::test::count_lines;
using splinefig::test::run;

namespace {

const std::string knots = "0,0\n1,2\n3,3\n4,1\n6,0\n";

void check_fails(const std::vector<std::string>& args, const std::string& input, const std::string& says) {
  const auto r = run(args, input);
  INFO("splinefig " << args[0] << " " << (args.size() > 2 ? args[2] : "") << "\nstderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains(says));
}

void check_succeeds(const std::vector<std::string>& args, const std::string& input) {
  const auto r = run(args, input);
  INFO("splinefig " << args[0] << " " << (args.size() > 2 ? args[2] : "") << "\nstderr: " << r.err);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("nan") == std::string::npos);
  CHECK(r.out.find("inf") == std::string::npos);
}

}  // namespace

TEST_CASE("interp on data near +-1e308 is an error naming the data point, in every output form") {
  const std::string big = "0\n1e308\n-1e308\n1\n";
  // B_1 of the relaxed 1-4-1 system is (24e308 + 6e308)/15 = 2e308: beyond the largest double.
  for (const char* output : {"curve", "bspline", "bezier"})
    check_fails({"interp", "--output", output}, big,
                "stdin: the spline overflows the range of a double: data point 2 (a coordinate 1e+308) is too large");
  check_fails({"interp", "--ends", "periodic"}, "0\n1e308\n-1e308\n0\n", "data point 2");
  check_fails({"interp", "--ends", "clamped", "--start-velocity", "1.7e308,0"}, "0,0\n1,1\n2,0\n", "--start-velocity");
  // Large but representable: 1e307 gives B_1 = 2e307.
  const auto r = run({"interp", "--output", "bspline"}, "0\n1e307\n-1e307\n1\n");
  CHECK(r.code == 0);
  CHECK(r.out == "0\n2e+307\n-2e+307\n1\n");
}

TEST_CASE("eval and kernel refuse basis parameters whose matrix overflows or whose tangents reverse") {
  // Each run starts a process; the full range of cases is in tests/spline/basis_matrices.cpp.
  check_fails({"eval", "--basis", "cardinal:a=1e308"}, knots, "--basis: cardinal: a=1e308 is too large");
  check_fails({"eval", "--basis", "tensioned-bspline:a=1e308"}, knots, "tensioned-bspline: a=1e308 is too large");
  check_fails({"kernel", "--basis", "cardinal:a=1e400"}, "", "value of 'a' is out of the range of a double: '1e400'");
  check_fails({"eval", "--basis", "cardinal:a=-1"}, knots, "a=-1 is negative: the tangent at every knot would point backwards");
  check_fails({"kernel", "--basis", "beta:b1=-1,b2=2"}, "", "b1=-1 is negative");
  // a = 1 and a = 0 (the control polygon), as the built-in figures use them, are fine.
  check_succeeds({"eval", "--basis", "cardinal:a=1"}, knots);
  check_succeeds({"kernel", "--basis", "tensioned-bspline:a=0"}, "");
}

TEST_CASE("eval names the knots of the piece where the curve overflows") {
  const std::string big = "0,0\n1,1e308\n2,-1e308\n3,1\n5,5\n";
  // X'' of the B-spline at the start of piece 1 is x0 - 2x1 + x2 = 1e308 + 2e308: infinite.
  check_fails({"eval", "--basis", "bspline", "--derivative", "2", "--grain", "1"}, big,
              "stdin: knots 1..4 with --basis bspline: its second derivative overflows the range of a double at t = 0");
  // Closed: piece 0 wraps to knots 5, 1, 2, 3 (X'' there: -1e308 - 2e308).
  check_fails({"eval", "--basis", "bspline", "--ends", "closed", "--derivative", "2", "--grain", "1"},
              "0,1e308\n1,0\n2,1\n3,0\n4,-1e308\n", "stdin: knots 5, 1, 2, 3 with --basis bspline");
  // A matrix with entries near 1e307 times knots of 100: the curve leaves the range of a double.
  // C_a with a = 1e307 on knots of 1e4: the weight of x1 at u = 1/4, about a u^2 (1 - u), times 1e4.
  check_fails({"eval", "--basis", "cardinal:a=1e307", "--grain", "4"}, "0\n1e4\n-1e4\n0\n",
              "stdin: knots 1..4 with --basis cardinal:a=1e307: the curve overflows the range of a double at t = 0.25");
  // Finite answers from large data are printed: Catmull-Rom at u = 1/2 is (-x0 + 9x1 + 9x2 - x3)/16.
  const auto r = run({"eval", "--basis", "catmull-rom", "--grain", "2"}, "0\n1e308\n-1e308\n3\n");
  CHECK(r.code == 0);
  CHECK(r.out == "1e+308\n-0.1875\n-1e+308\n");
}

TEST_CASE("eval --spacing arclength and polygon refuse curves whose length overflows (they hung or lied)") {
  const std::string big = "0,0\n1e200,1\n-1e200,0\n3,1\n5,5\n";
  check_fails({"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "5"}, big,
              "stdin: knots 1..4 are too large for --spacing arclength: the curve's length there overflows");
  check_fails({"eval", "--basis", "bspline", "--spacing", "polygon", "--count", "5"},
              "0,0\n1e307,1\n-1e307,0\n3,1\n5,5\n6,6\n", "are too large for --spacing polygon");
  check_succeeds({"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "3"},
                 "0,0\n1e150,1\n-1e150,0\n3,1\n5,5\n");
}

TEST_CASE("kernel --report checks every measure before printing") {
  // Entries near 1e307 keep k finite, but the report's energy (the integral of k^2) overflows.
  check_fails({"kernel", "--basis", "cardinal:a=1e307", "--report"}, "",
              "--basis cardinal:a=1e307: the filter's energy overflows the range of a double");
  check_succeeds({"kernel", "--basis", "cardinal:a=1e300", "--step", "0.25"}, "");
}

TEST_CASE("eval finds an overflow in the middle of a long curve and in the partial block at its end") {
  // 220000 2-D knots at grain 5: 2.2e6 numbers (17.6 MB), sampled with streaming stores, 10
  // outputs a piece (two blocks of 4 and a partial block of 2). X'' of the B-spline on piece i
  // is (1-u) P0 + (3u-2) P1 + (1-3u) P2 + u P3 over its knots P0..P3.
  const std::size_t n = 220000;
  auto curve = [&](std::size_t at, const char* a, std::size_t at2, const char* a2) {
    std::string s;
    s.reserve(n * 8);
    for (std::size_t i = 0; i < n; ++i)
      s += (i == at ? std::string(a) : i == at2 ? std::string(a2) : std::to_string(i % 7) + ".25") + ",0\n";
    return s;
  };
  const std::vector<std::string> args{"eval", "--basis", "bspline", "--derivative", "2", "--grain", "5"};
  // Knot 110001 (from 1) is 1e308: pieces 109997 and 109998 (from 0) weigh it by u and 1-3u,
  // at most 1.4 in size (u <= 0.8), and stay finite; piece 109999 (knots 110000..110003)
  // starts at P0 - 2 P1 + P2 = -2e308.
  check_fails(args, curve(110000, "1e308", n, ""),
              "stdin: knots 110000..110003 with --basis bspline: its second derivative overflows the range of a double at t = 109999");
  // The last two knots -0.9e308 and 1e308: on the last piece (knots 219997..220000, t from
  // 219996) 1.32e308 at u = 0.6, -1.4 x -0.9e308 + 0.8e308 = 2.06e308 at u = 0.8, the last
  // output pair of the piece (the partial block).
  check_fails(args, curve(n - 2, "-0.9e308", n - 1, "1e308"),
              "stdin: knots 219997..220000 with --basis bspline: its second derivative overflows the range of a double at t = 219996.8");
  // Without them the same curve is printed whole, every number finite.
  const auto r = run(args, curve(n, "", n, ""));
  CHECK(r.code == 0);
  CHECK(count_lines(r.out) == (n - 3) * 5 + 1);
  CHECK(r.out.find("inf") == std::string::npos);
  CHECK(r.out.find("nan") == std::string::npos);
}
