// `splinefig eval` and `splinefig kernel` as docs/cli.md specifies them: counts per end mode,
// numbers that read back to the same double, and one stderr line (nothing on stdout) for
// every kind of bad input.
#include "cli/run.hpp"

#include <catch2/catch.hpp>
#include <splinefig/spline/arclength.hpp>
#include <splinefig/spline/curve.hpp>

#include <charconv>
#include <cmath>

using namespace splinefig;
using splinefig::test::count_lines;
using splinefig::test::run;

namespace {

const std::string knots5 = "0,0\n1,2\n3,3\n4,1\n6,0\n";

// Parses CSV output back into rows of doubles (from_chars: exact round trip).
std::vector<std::vector<double>> parse(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    const char* p = line.data();
    const char* end = line.data() + line.size();
    while (p < end) {
      double v = 0;
      auto [q, ec] = std::from_chars(p, end, v);
      REQUIRE(ec == std::errc());
      row.push_back(v);
      p = q + (q < end && *q == ',' ? 1 : 0);
    }
    rows.push_back(row);
  }
  return rows;
}

// A failed command: non-zero exit, exactly one line on stderr, nothing on stdout.
void check_fails(const std::vector<std::string>& args, const std::string& input, const std::string& says) {
  const auto r = run(args, input);
  INFO("stderr: " << r.err);
  CHECK(r.code != 0);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.back() == '\n');
  CHECK_THAT(r.err, Catch::Contains(says));
}

}  // namespace

TEST_CASE("eval counts: open (n-3)*grain+1, double (n-1)*grain+1, closed n*grain+1 with last = first") {
  auto rows = [](std::vector<std::string> args, const std::string& in = knots5) {
    const auto r = run(args, in);
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(r.err.empty());
    return parse(r.out);
  };
  CHECK(rows({"eval", "--basis", "catmull-rom", "--grain", "4"}).size() == (5 - 3) * 4 + 1);
  CHECK(rows({"eval", "--basis", "bspline"}).size() == (5 - 3) * 16 + 1);  // default grain 16
  CHECK(rows({"eval", "--basis", "catmull-rom", "--grain", "3", "--ends", "double"}).size() == (5 + 2 - 3) * 3 + 1);
  const auto closed = rows({"eval", "--basis", "bspline", "--grain", "5", "--ends", "closed"});
  REQUIRE(closed.size() == 5 * 5 + 1);
  CHECK(closed.back() == closed.front());
  CHECK(rows({"eval", "--basis", "uniform-bspline:degree=5", "--grain", "2"}, knots5 + "7,7\n8,1\n").size() ==
        (7 - 5) * 2 + 1);
  for (const char* d : {"1", "2"}) CHECK(rows({"eval", "--basis", "beta:b1=2,b2=1", "--derivative", d}).size() == 33);
  CHECK(rows({"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "40"}).size() == 40);
  CHECK(rows({"eval", "--basis", "catmull-rom", "--spacing", "polygon", "--count", "7"}).size() == 7);
  // Comments, blank lines, CRLF and blanks around fields are fine.
  CHECK(rows({"eval", "--basis", "catmull-rom", "--grain", "1"}, "# knots\n0, 0\r\n\n1 ,2\n  3,3\n4,1\n").size() == 2);
}

TEST_CASE("eval writes numbers that read back to exactly the library's doubles") {
  const std::string in = "0.1,0.2,0.3\n1e-7,2.5,-3\n3.3333333333333335,3,1e10\n4,1,0.7\n6,0.1,-0.0001\n";
  const auto r = run({"eval", "--basis", "beta:b1=1.5,b2=0.25", "--grain", "7", "--ends", "double"}, in);
  REQUIRE(r.code == 0);
  Points k(3);
  for (const auto& row : parse(in)) k.push_back(row);
  const Points expect = sample(make_curve(beta(1.5, 0.25), k, Ends::doubled), 7);
  const auto got = parse(r.out);
  REQUIRE(got.size() == expect.size());
  for (size_t i = 0; i < got.size(); ++i)
    for (int d = 0; d < 3; ++d) CHECK(got[i][d] == expect[i][d]);
  // Catmull-Rom passes through its knots: those rows are the input numbers themselves.
  const auto cr = parse(run({"eval", "--basis", "catmull-rom", "--grain", "7"}, in).out);
  CHECK(cr[0] == std::vector<double>{1e-7, 2.5, -3});
  CHECK(cr[7] == std::vector<double>{3.3333333333333335, 3, 1e10});
}

TEST_CASE("eval --spacing arclength: the first and last point are the curve's ends") {
  const auto r = run({"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "5"}, knots5);
  REQUIRE(r.code == 0);
  const auto rows = parse(r.out);
  REQUIRE(rows.size() == 5);
  CHECK(rows.front() == std::vector<double>{1, 2});
  CHECK(rows.back() == std::vector<double>{4, 1});
}

TEST_CASE("kernel writes x,k(x) from -2 to 2 in steps of 1/64 by default") {
  const auto r = run({"kernel", "--basis", "catmull-rom"});
  REQUIRE(r.code == 0);
  const auto rows = parse(r.out);
  REQUIRE(rows.size() == 257);
  CHECK(rows.front() == std::vector<double>{-2, 0});
  CHECK(rows[128] == std::vector<double>{0, 1});
  CHECK(rows[32] == std::vector<double>{-1.5, -1.0 / 16});
  CHECK(rows.back() == std::vector<double>{2, 0});
  const auto b = parse(run({"kernel", "--basis", "bspline", "--from", "-1", "--to", "1", "--step", "0.5"}).out);
  REQUIRE(b.size() == 5);
  CHECK(b[0][1] == Approx(1.0 / 6).epsilon(1e-15));
  CHECK(b[2][1] == Approx(2.0 / 3).epsilon(1e-15));
  CHECK(b[3][1] == Approx(23.0 / 48).epsilon(1e-15));
  // A step that does not divide the range stops at the last x not beyond --to.
  CHECK(parse(run({"kernel", "--basis", "bspline", "--from", "0", "--to", "1", "--step", "0.3"}).out).size() == 4);
  CHECK(parse(run({"kernel", "--basis", "bspline", "--from", "0", "--to", "0.3", "--step", "0.1"}).out).size() == 4);
}

TEST_CASE("eval rejects bad knots with the stdin line number, one stderr line, nothing on stdout") {
  const std::vector<std::string> cr = {"eval", "--basis", "catmull-rom"};
  check_fails(cr, "0,0\n1,1\n2,0\n", "too few knots: 3 given");
  check_fails(cr, "", "no knots (catmull-rom with open ends needs at least 4)");
  check_fails(cr, "0,0\n1,1\n# note\n\n2,0,5\n3,3\n", "stdin line 5: 3 coordinates, but line 1 has 2");
  check_fails(cr, "0,0\n1,1\nabc,2\n3,3\n", "stdin line 3, field 1: 'abc' is not a number");
  check_fails(cr, "0,0\n1,nan\n2,0\n3,3\n", "stdin line 2, field 2: 'nan' is not a finite number");
  check_fails(cr, "0,0\n1,1\n2,inf\n3,3\n", "stdin line 3, field 2: 'inf' is not a finite number");
  check_fails(cr, "0,0\n1,1e999\n2,0\n3,3\n", "stdin line 2, field 2: '1e999' is out of the range");
  check_fails(cr, "0,0\n1,\n2,0\n3,3\n", "stdin line 2, field 2: empty field");
  check_fails(cr, "0,0\n1,2x\n2,0\n3,3\n", "'2x' is not a number");
  check_fails({"eval", "--basis", "bspline", "--ends", "closed"}, "0,0\n1,1\n", "needs at least 3");
}

TEST_CASE("eval rejects bad flags and specs, naming the flag, key or value") {
  const std::string in = knots5;
  check_fails({"eval", "--basis", "catmull-rom", "--grain", "0"}, in, "--grain: 0 is out of range");
  check_fails({"eval", "--basis", "catmull-rom", "--grain", "-3"}, in, "--grain");
  check_fails({"eval", "--basis", "catmull-rom", "--grain", "2.5"}, in, "--grain: '2.5' is not a whole number");
  check_fails({"eval", "--basis", "catmull-rom", "--grain"}, in, "--grain");
  check_fails({"eval", "--basis"}, in, "--basis");
  check_fails({"eval"}, in, "splinefig eval: missing --basis SPEC; usage: splinefig eval [INPUT] --basis SPEC [options]\n");
  check_fails({"eval", "--basis", "bogus"}, in, "unknown basis 'bogus'");
  check_fails({"eval", "--basis", "cardinal:tension=1"}, in, "unknown parameter 'tension'");
  check_fails({"eval", "--basis", "cardinal:a=nan"}, in, "not finite");
  check_fails({"eval", "--basis", "beta:b1=-1,b2=0"}, in, "denominator");
  check_fails({"eval", "--basis", "catmull-rom", "--ends", "loop"}, in, "--ends: unknown end mode 'loop'");
  check_fails({"eval", "--basis", "catmull-rom", "--derivative", "3"}, in, "--derivative: 3 is out of range");
  check_fails({"eval", "--basis", "catmull-rom", "--spacing", "arclength"}, in, "needs --count");
  check_fails({"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "1"}, in, "--count: 1");
  check_fails({"eval", "--basis", "catmull-rom", "--spacing", "chordal", "--count", "5"}, in, "unknown spacing");
  check_fails({"eval", "--basis", "catmull-rom", "--count", "5"}, in, "--count needs --spacing");
}

TEST_CASE("eval refuses output it cannot hold and reports a failed write") {
  std::string many;
  for (int i = 0; i < 100; ++i) many += std::to_string(i) + "," + std::to_string(i % 7) + "\n";
  check_fails({"eval", "--basis", "catmull-rom", "--grain", "16777216"}, many, "more than");
  check_fails({"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "50000000"}, many,
              "--count 50000000: 50000000 points of dimension 2 would be more than");
  const auto r = run({"eval", "--basis", "catmull-rom"}, knots5, "/dev/full");
  CHECK(r.code != 0);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("cannot write"));
}

TEST_CASE("kernel rejects bad ranges and specs") {
  check_fails({"kernel", "--basis", "catmull-rom", "--step", "0"}, "", "--step: 0 must be positive");
  check_fails({"kernel", "--basis", "catmull-rom", "--step", "-1"}, "", "--step");
  check_fails({"kernel", "--basis", "catmull-rom", "--from", "nan"}, "", "--from: value 'nan' is not a finite number");
  check_fails({"kernel", "--basis", "catmull-rom", "--from", "1", "--to", "0"}, "", "less than --from");
  check_fails({"kernel", "--basis", "catmull-rom", "--step", "1e-12"}, "", "more than 1e8 rows");
  check_fails({"kernel", "--basis", "uniform-bspline:degree=0"}, "", "out of range");
  check_fails({"kernel", "--basis", "catmull-rom", "--step"}, "", "--step");
  check_fails({"kernel", "--basis", "catmull-rom", "--from", "-1.7e308", "--to", "1.7e308", "--step", "1e300"}, "",
              "more than 1e8 rows");
}

TEST_CASE("kernel's rows reach the ends of the doubles where to - from and i * step overflow") {
  // 3 rows, at -1.7e308, 0 and 1.7e308 (the B-spline is 0, 2/3, 0 there); (to - from) / step
  // overflowed to inf and the range was said to be more than 1e8 rows.
  const auto r = run({"kernel", "--basis", "bspline", "--from", "-1.7e308", "--to", "1.7e308", "--step", "1.7e308"});
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(r.out == "-1.7e+308,0\n0,0.6666666666666666\n1.7e+308,0\n");
}

TEST_CASE("An unknown subcommand is one clear line, --help works on every subcommand") {
  check_fails({"bogus"}, "", "unknown command 'bogus'");
  const auto top = run({"--help"});
  REQUIRE(top.code == 0);
  // Every subcommand listed under "Subcommands:" answers --help with its usage.
  std::istringstream in(top.out);
  std::string line;
  bool in_list = false;
  int seen = 0;
  while (std::getline(in, line)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      in_list = true;
      continue;
    }
    if (!in_list || line.empty()) continue;
    std::istringstream words(line);
    std::string name;
    words >> name;
    INFO("splinefig " << name << " --help");
    const auto r = run({name, "--help"});
    CHECK(r.code == 0);
    CHECK_THAT(r.out, Catch::Contains("Usage"));
    ++seen;
  }
  CHECK(seen >= 3);  // eval, kernel, version at least
  CHECK(run({"--version"}).code == 0);
}
