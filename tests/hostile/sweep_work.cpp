// A polyline whose outline crosses itself past the sweep's work limit is refused at once, naming
// the spec, the item and the bound, instead of being swept for minutes, when the spec asks for
// the exact sweep everywhere (coverage_tolerance = 0).
#include "hostile.hpp"

#include <cstdio>
#include <random>

using namespace splinefig::hostile;

TEST_CASE("30000 random points on 1024^2 (about 4e8 crossings, minutes of sweeping) are refused at once") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1024);
  std::string spec = "[canvas]\nwidth = 1024\nheight = 1024\ncoverage_tolerance = 0\n[[polyline]]\nwidth = 1\npoints = [";
  char buf[64];
  for (int i = 0; i < 30000; ++i) {
    std::snprintf(buf, sizeof buf, "%s[%.3f, %.3f]", i ? ", " : "", u(rng), u(rng));
    spec += buf;
  }
  spec += "]\n";
  check_refused("dense", spec, "dense.toml: item 1 (stroked polyline): its outline crosses itself at least ");
}

TEST_CASE("figures --specs: a spec past the sweep's work limit, or whose output cannot be written, is named first") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1024);
  std::string dense = "[canvas]\nwidth = 1024\nheight = 1024\ncoverage_tolerance = 0\n[[polyline]]\nwidth = 1\npoints = [";
  char buf[64];
  for (int i = 0; i < 30000; ++i) {
    std::snprintf(buf, sizeof buf, "%s[%.3f, %.3f]", i ? ", " : "", u(rng), u(rng));
    dense += buf;
  }
  dense += "]\n";
  const fs::path dir = scratch();
  fs::create_directories(dir / "specs");
  write_file(dir / "specs" / "dense.toml", dense);
  write_file(dir / "specs" / "blocked.toml", "[canvas]\nwidth = 24\nheight = 24\n");
  write_file(dir / "specs" / "ok.toml", "[canvas]\nwidth = 24\nheight = 24\n");
  fs::create_directories(dir / "out" / "blocked.png");  // a directory where the image goes
  const Outcome o = run_in(dir, {"figures", "--specs", "specs", "--out", "out", "--threads", "2"});
  INFO(o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 2);
  // In spec order (blocked, dense, ok), each failure one line starting with its spec's path.
  const auto first_nl = o.err.find('\n'), second_nl = o.err.find('\n', first_nl + 1);
  REQUIRE(second_nl != std::string::npos);
  CHECK_THAT(o.err.substr(0, first_nl), Catch::StartsWith("splinefig figures: specs/blocked.toml: out/blocked.png: "));
  CHECK_THAT(o.err.substr(first_nl + 1, second_nl - first_nl - 1),
             Catch::StartsWith("splinefig figures: specs/dense.toml: item 1 (stroked polyline): its outline crosses itself at least "));
  CHECK(o.err.substr(second_nl + 1) == "splinefig figures: 2 of 3 figures failed\n");
  CHECK(fs::exists(dir / "out" / "ok.png"));
  CHECK_FALSE(fs::exists(dir / "out" / "dense.png"));
  fs::remove_all(dir);
}

TEST_CASE("under the default coverage tolerance a dense polyline is drawn, and the tolerance is checked where it is read") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 256);
  std::string points = "[[polyline]]\nwidth = 1\npoints = [";
  char buf[64];
  for (int i = 0; i < 3000; ++i) {  // about 4e6 crossings
    std::snprintf(buf, sizeof buf, "%s[%.3f, %.3f]", i ? ", " : "", u(rng), u(rng));
    points += buf;
  }
  points += "]\n";
  const std::string canvas = "[canvas]\nwidth = 256\nheight = 256\n";
  check_renders("pieces", canvas + points);
  for (const char* bad : {"-0.5", "1.5", "nan", "\"fine\""})
    check_refused("bad", canvas + "coverage_tolerance = " + bad + "\n", "bad.toml:4: canvas.coverage_tolerance: ");
}

TEST_CASE("render and figures: --coverage-tolerance replaces the spec's, is checked as a flag, and -v says how the picture was drawn") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 256);
  std::string spec = "[canvas]\nwidth = 256\nheight = 256\n[[polyline]]\nwidth = 1\npoints = [[4, 4], [9, 6]]\n"
                     "[[polyline]]\nwidth = 1\npoints = [";
  char buf[64];
  for (int i = 0; i < 3000; ++i) {  // dense: about 4e6 crossings, most pixels solid
    std::snprintf(buf, sizeof buf, "%s[%.3f, %.3f]", i ? ", " : "", u(rng), u(rng));
    spec += buf;
  }
  spec += "]\n";
  const fs::path dir = scratch();
  write_file(dir / "dense.toml", spec);
  // At the default the second item has bands drawn from its pieces; 256 rows are 16 bands.
  const Outcome dflt = run_in(dir, {"render", "dense.toml", "-o", "default.png", "-v"});
  REQUIRE(dflt.code == 0);
  CHECK_THAT(dflt.err, Catch::StartsWith("splinefig render: dense.toml: item 2: ") &&
                           Catch::Contains(" of 16 bands of 16 rows resolved from its pieces, within the coverage tolerance 1/1024"));
  // --coverage-tolerance 0: every band swept exactly, and the same picture within one 8-bit step
  // (the pieces method is exact up to 1e-9 per pixel; float rounding may still tip a value).
  const Outcome exact = run_in(dir, {"render", "dense.toml", "-o", "exact.png", "-v", "--coverage-tolerance", "0"});
  REQUIRE(exact.code == 0);
  CHECK(exact.err == "splinefig render: dense.toml: exact (no band needed the coverage tolerance, 0)\n");
  CHECK(run_in(dir, {"diff", "exact.png", "default.png", "--fail", "0.0040", "--warn", "0.0040"}).code == 0);
  // The flag replaces the spec's value: a spec asking for 0 is drawn from pieces with 0.01.
  write_file(dir / "zero.toml", "[canvas]\nwidth = 256\nheight = 256\ncoverage_tolerance = 0\n" + spec.substr(spec.find("[[polyline]]")));
  const Outcome over = run_in(dir, {"render", "zero.toml", "-o", "zero.png", "-v", "--coverage-tolerance", "0.01"});
  REQUIRE(over.code == 0);
  CHECK_THAT(over.err, Catch::Contains("item 2: ") && Catch::Contains("within the coverage tolerance 1/100 "));
  // A vector output is not rasterized, and says so.
  const Outcome svg = run_in(dir, {"render", "dense.toml", "-o", "dense.svg", "-v"});
  CHECK(svg.err == "splinefig render: dense.toml: not rasterized (the vector file keeps the exact curves)\n");
  // figures -v: one line per figure.
  fs::create_directories(dir / "specs");
  fs::copy_file(dir / "dense.toml", dir / "specs" / "dense.toml");
  const Outcome all = run_in(dir, {"figures", "--specs", "specs", "--out", "out", "-v", "--coverage-tolerance", "1/1024"});
  CHECK(all.code != 0);  // "1/1024" is not a number
  const Outcome figs = run_in(dir, {"figures", "--specs", "specs", "--out", "out", "-v", "--coverage-tolerance", "0.0009765625"});
  REQUIRE(figs.code == 0);
  CHECK_THAT(figs.err, Catch::StartsWith("splinefig figures: dense: item 2: ") && Catch::Contains("tolerance 1/1024 "));
  // Out of range, NaN: one line naming the flag, nothing written.
  for (const char* bad : {"-0.5", "1.5", "nan", "inf"}) {
    const Outcome o = run_in(dir, {"render", "dense.toml", "-o", "bad.png", "--coverage-tolerance", bad});
    INFO(bad << ": " << o.err);
    CHECK(o.code != 0);
    CHECK_THAT(o.err, Catch::Contains("--coverage-tolerance ") && Catch::Contains(": must be in [0, 1]"));
    CHECK_FALSE(fs::exists(dir / "bad.png"));
  }
  fs::remove_all(dir);
}

TEST_CASE("render -v of an animation: how each frame was drawn, runs of frames alike on one line") {
  // Two keyframes of 1500 random points each, three frames (t = 0, 1/2, 1): every frame a
  // dense self-crossing polyline, drawn in part from its pieces at the default tolerance.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::string frames = "frames = [";
  char buf[64];
  for (int f = 0; f < 2; ++f) {
    frames += f ? "], [" : "[";
    for (int i = 0; i < 1500; ++i) {
      std::snprintf(buf, sizeof buf, "%s[%.4f, %.4f]", i ? ", " : "", u(rng), u(rng));
      frames += buf;
    }
  }
  frames += "]]\n";
  const std::string spec = "[canvas]\nwidth = 256\nheight = 256\n[[axes]]\nx_range = [0, 1]\ny_range = [0, 1]\n"
                           "[[axes.inbetween]]\nsteps = 2\nwidth = 1\n" + frames +
                           "[animation]\nwidth = 256\nheight = 256\n";
  const fs::path dir = scratch();
  write_file(dir / "anim.toml", spec);
  const Outcome dflt = run_in(dir, {"render", "anim.toml", "-o", "anim.webp", "-v"});
  INFO(dflt.err);
  REQUIRE(dflt.code == 0);
  CHECK(fs::exists(dir / "anim.webp"));
  // One line per run of frames described alike, covering frames 1 to 3 in order.
  std::vector<std::string> lines;
  for (std::size_t at = 0, nl; (nl = dflt.err.find('\n', at)) != std::string::npos; at = nl + 1)
    lines.push_back(dflt.err.substr(at, nl - at));
  REQUIRE_FALSE(lines.empty());
  int next = 1;
  for (const std::string& line : lines) {
    CHECK_THAT(line, Catch::StartsWith("splinefig render: anim.toml: frame"));
    const std::string one = "frame " + std::to_string(next) + " of 3: ";
    const std::string run = "frames " + std::to_string(next) + "-";
    REQUIRE((line.find(one) != std::string::npos || line.find(run) != std::string::npos));
    if (line.find(one) != std::string::npos) {
      ++next;
    } else {
      next = std::stoi(line.substr(line.find(run) + run.size())) + 1;
      CHECK(line.find(run + std::to_string(next - 1) + " of 3: ") != std::string::npos);
    }
  }
  CHECK(next == 4);
  CHECK_THAT(dflt.err, Catch::Contains(" bands of 16 rows resolved from their pieces, within the coverage tolerance 1/1024"));
  // --coverage-tolerance 0: every frame exact, said once for the three.
  const Outcome exact = run_in(dir, {"render", "anim.toml", "-o", "exact.webp", "-v", "--coverage-tolerance", "0"});
  REQUIRE(exact.code == 0);
  CHECK(exact.err == "splinefig render: anim.toml: frames 1-3 of 3: exact (no band needed the coverage tolerance, 0)\n");
  // Without -v nothing is said.
  const Outcome quiet = run_in(dir, {"render", "anim.toml", "-o", "quiet.webp"});
  CHECK(quiet.code == 0);
  CHECK(quiet.err.empty());
  // figures -v: after the still figure's line, the same lines for its animation as render's,
  // naming the file.
  fs::create_directories(dir / "specs");
  fs::copy_file(dir / "anim.toml", dir / "specs" / "anim.toml");
  const Outcome figs = run_in(dir, {"figures", "--specs", "specs", "--out", "out", "-v"});
  INFO(figs.err);
  REQUIRE(figs.code == 0);
  CHECK(fs::exists(dir / "out" / "anim.webp"));
  const std::string said = "splinefig render: anim.toml: ";
  std::string expected;
  for (const std::string& line : lines) expected += "splinefig figures: anim.webp: " + line.substr(said.size()) + "\n";
  CHECK_THAT(figs.err, Catch::StartsWith("splinefig figures: anim: ") && Catch::EndsWith(expected));
  const Outcome figs_exact = run_in(dir, {"figures", "--specs", "specs", "--out", "out", "-v", "--coverage-tolerance", "0"});
  REQUIRE(figs_exact.code == 0);
  CHECK_THAT(figs_exact.err,
             Catch::EndsWith("splinefig figures: anim.webp: frames 1-3 of 3: exact (no band needed the coverage tolerance, 0)\n"));
  fs::remove_all(dir);
}
