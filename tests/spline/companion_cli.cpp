// `splinefig interp` per docs/cli.md, and eval's --knot-spacing / --betas, run as a user would:
// stdin in, CSV out, one-line errors with nothing on stdout.
#include <catch2/catch.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/interp.hpp>
#include <splinefig/spline/knot_spacing.hpp>
#include <splinefig/spline/local_beta.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace splinefig;
namespace fs = std::filesystem;

namespace {

struct Run {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One directory per test process, removed when it exits.
fs::path scratch() {
  struct Dir {
    fs::path path = fs::temp_directory_path() / ("splinefig-companion-cli-" + std::to_string(::getpid()));
    Dir() { fs::create_directories(path); }
    ~Dir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path;
}

Run run(const std::string& args, const std::string& input) {
  const fs::path in = scratch() / "in.csv", out = scratch() / "out.txt", err = scratch() / "err.txt";
  std::ofstream(in, std::ios::binary) << input;
  const std::string cmd = std::string("'") + SPLINEFIG_EXE + "' " + args + " < '" + in.string() + "' > '" +
                          out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

std::vector<std::vector<double>> rows(const std::string& text) {
  std::vector<std::vector<double>> r;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) row.push_back(std::strtod(f.c_str(), nullptr));
    r.push_back(row);
  }
  return r;
}

Points parse(const std::string& text) {
  Points p;
  for (const auto& row : rows(text)) p.push_back(row);
  return p;
}

const char* worked = "1,-1\n-1,2\n# comment\n\n1,4\n4,3\n7,5\n";

void expect_error(const std::string& args, const std::string& input, const std::string& words) {
  INFO("splinefig " << args);
  const Run r = run(args, input);
  CHECK(r.code != 0);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains(words));
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

}  // namespace

TEST_CASE("interp --output bspline prints seed 003's control points") {
  const Run r = run("interp --output bspline", worked);
  REQUIRE(r.code == 0);
  const auto b = rows(r.out);
  const double B[5][2] = {{1, -1}, {-2, 2}, {1, 5}, {4, 2}, {7, 5}};
  REQUIRE(b.size() == 5);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t c = 0; c < 2; ++c) CHECK(b[i][c] == Approx(B[i][c]).margin(1e-14));
}

TEST_CASE("interp --output bezier prints one piece of 4 points per line") {
  const Run r = run("interp --output bezier", worked);
  REQUIRE(r.code == 0);
  const auto b = rows(r.out);
  REQUIRE(b.size() == 4);
  const double second[8] = {-1, 2, -1, 3, 0, 4, 1, 4};  // the seed's Bezier #2
  for (std::size_t k = 0; k < 8; ++k) CHECK(b[1][k] == Approx(second[k]).margin(1e-14));
}

TEST_CASE("interp curve: n*grain+1 rows that read back to the library's doubles") {
  for (const char* ends : {"relaxed", "clamped", "periodic"}) {
    const std::string data = std::string(ends) == "periodic" ? "0,0,1\n3,1,2\n2,5,0\n0,0,1\n" : "0,0,1\n3,1,2\n2,5,0\n-1,2,2\n";
    std::string args = std::string("interp --grain 5 --ends ") + ends;
    if (std::string(ends) == "clamped") args += " --start-velocity 1,0,0 --end-velocity=-1,2,0.5";
    const Run r = run(args, data);
    REQUIRE(r.code == 0);
    const Points S = parse(data);
    const std::vector<double> v{1, 0, 0}, w{-1, 2, 0.5};
    const Interpolant s = std::string(ends) == "relaxed"   ? interpolate_relaxed(S)
                          : std::string(ends) == "clamped" ? interpolate_clamped(S, v, w)
                                                           : interpolate_periodic(S);
    const Points expect = sample(s, 5), got = parse(r.out);
    REQUIRE(got.size() == 3 * 5 + 1);
    CHECK(got.coords == expect.coords);  // shortest round-trip output: bit-exact
  }
  // --ends clamped defaults to zero end velocities.
  const Run z = run("interp --ends clamped --output bspline", "0,0\n1,1\n3,0\n");
  REQUIRE(z.code == 0);
  const std::vector<double> zero{0, 0};
  CHECK(parse(z.out).coords == interpolate_clamped(parse("0,0\n1,1\n3,0\n"), zero, zero).control.coords);
}

// Each run of the binary costs a process start (it links the image libraries), so each error
// case below checks something different.
TEST_CASE("interp errors in the data: one line naming it, non-zero exit, nothing on stdout") {
  expect_error("interp", "", "0 data points");
  expect_error("interp", "1,2\n", "needs at least 2");
  expect_error("interp --ends periodic", "1,2\n3,4\n", "needs at least 3");
  expect_error("interp --ends periodic", "1,2\n3,4\n5,6\n", "repeat the first");
  expect_error("interp", "1,2\n3,x\n", "line 2, field 2");
}

TEST_CASE("interp errors in the flags: one line naming the flag") {
  expect_error("interp --ends sideways", worked, "--ends");
  expect_error("interp --grain 0", worked, "--grain");
  expect_error("interp --ends clamped --start-velocity 1", worked, "--start-velocity");
  expect_error("interp --end-velocity 1,2", worked, "only to --ends clamped");
}

TEST_CASE("eval --knot-spacing and --betas use the spaced and locally shaped curves") {
  const std::string knots = "0,0\n1,2\n2,0\n3,2\n4,0\n5,2\n6,0\n";
  const Points K = parse(knots);
  const Run c = run("eval --basis catmull-rom --knot-spacing centripetal --grain 4 --ends double", knots);
  REQUIRE(c.code == 0);
  CHECK(parse(c.out).coords == sample_spaced(make_curve(catmull_rom(), K, Ends::doubled), 0.5, 4).coords);

  const fs::path betas = scratch() / "betas.csv";
  std::ofstream(betas) << "1,0\n1,0\n5,0\n10,0\n1,0\n1,0\n1,0\n";
  const Run b = run("eval --basis beta --grain 4 --betas '" + betas.string() + "'", knots);
  REQUIRE(b.code == 0);
  std::vector<ShapeParameters> s(7);
  s[2].b1 = 5, s[3].b1 = 10;
  CHECK(parse(b.out).coords == sample_local_betas(make_curve(beta(1, 0), K, Ends::open), s, 4).coords);
}

TEST_CASE("eval --knot-spacing and --betas errors name the flag or the file") {
  const std::string knots = "0,0\n1,2\n2,0\n3,2\n4,0\n5,2\n6,0\n";
  const fs::path betas = scratch() / "betas.csv";
  std::ofstream(betas) << "1,0\n1,0\n5,0\n10,0\n1,0\n1,0\n1,0\n";
  expect_error("eval --basis bspline --knot-spacing chordal", knots, "Catmull-Rom");
  expect_error("eval --basis bspline --betas '" + betas.string() + "'", knots, "--basis beta");
  expect_error("eval --basis beta --betas /nonexistent/betas.csv", knots, "cannot open");
  std::ofstream(betas) << "1,0\n1,0\n";
  expect_error("eval --basis beta --betas '" + betas.string() + "'", knots, "2 (b1, b2) pairs for 7 knots");
}

TEST_CASE("eval --knot-spacing on knots whose squared distances overflow: the curve scales with its knots") {
  // Spaced Catmull-Rom is invariant under scaling (its parameters scale with the knots), and
  // powers of 2 scale exactly: at 2^600 |d|^2 overflows, at 2^-600 it underflows; |d| does not.
  const std::string small = "0,0\n1,2\n3,3\n4,1\n6,0\n";
  for (const int e : {600, -600}) {
    std::string scaled;
    for (const auto& row : rows(small)) {
      char line[128];
      std::snprintf(line, sizeof line, "%.17g,%.17g\n", std::ldexp(row[0], e), std::ldexp(row[1], e));
      scaled += line;
    }
    for (const char* spacing : {"chordal", "centripetal"}) {
      INFO(spacing << " at 2^" << e);
      const Run a = run(std::string("eval --basis catmull-rom --grain 4 --knot-spacing ") + spacing, small);
      const Run b = run(std::string("eval --basis catmull-rom --grain 4 --knot-spacing ") + spacing, scaled);
      REQUIRE(a.code == 0);
      REQUIRE(b.code == 0);
      const auto ra = rows(a.out), rb = rows(b.out);
      REQUIRE(ra.size() == rb.size());
      for (std::size_t i = 0; i < ra.size(); ++i)
        for (std::size_t c = 0; c < 2; ++c) CHECK(std::ldexp(rb[i][c], -e) == Approx(ra[i][c]).margin(1e-12));
    }
  }
  // Knots 2e308 apart: the distance itself is beyond a double.
  expect_error("eval --basis catmull-rom --knot-spacing chordal", "0,0\n1e308,1\n-1e308,0\n3,1\n5,5\n",
               "the knot parameters overflow at knot 3");
}

TEST_CASE("eval --betas: shape parameters that overflow the denominator or reverse the curve are refused") {
  const std::string knots = "0,0\n1,2\n2,0\n3,2\n4,0\n5,2\n6,0\n";
  const fs::path betas = scratch() / "betas-range.csv";
  std::ofstream(betas) << "1,0\n1,0\n1e103,0\n1,0\n1,0\n1,0\n1,0\n";  // b1^3 = 1e309
  expect_error("eval --basis beta --betas '" + betas.string() + "'", knots, "between knots 1 and 2 b1 or b2 is too large");
  std::ofstream(betas) << "1,0\n1,0\n-0.5,0\n1,0\n1,0\n1,0\n1,0\n";
  expect_error("eval --basis beta --betas '" + betas.string() + "'", knots, "knot 2 has a negative b1");
  // b1 = 0 (the velocity after a joint stops) and negative tension with d > 0 are allowed.
  std::ofstream(betas) << "1,0\n0,0\n1,0\n1,-5\n1,0\n1,0\n1,0\n";
  const Run r = run("eval --basis beta --betas '" + betas.string() + "'", knots);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
}
