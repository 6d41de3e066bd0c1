// The command line as people use it: typed --help with an example per subcommand, input files
// or stdin with a header line and a choice of delimiter, kernel names and ranges, resample
// sizes that keep the aspect ratio, output bits, a verbose line and a progress line that only
// a terminal sees.
#include "cli/run.hpp"
#include "skip.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::count_lines;
using splinefig::test::run;
using splinefig::test::shell_quote;
using splinefig::test::slurp;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-usage-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

void check_fails(const std::vector<std::string>& args, const std::string& input, const std::string& says) {
  const auto r = run(args, input);
  INFO("splinefig " << args[0] << "\nstderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains(says));
}

// Width, height and bit depth from a PNG's IHDR chunk (bytes 16..24 of the file).
struct PngHeader {
  unsigned width = 0, height = 0, bits = 0;
};
PngHeader png_header(const fs::path& p) {
  const std::string b = slurp(p);
  REQUIRE(b.size() > 25);
  const auto u32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(b[at + i]);
    return v;
  };
  return {u32(16), u32(20), static_cast<unsigned char>(b[24])};
}

// An 800x500 RGBA render (a built-in spec) at `scale` to resample.
fs::path source_png(const fs::path& dir, double scale = 1) {
  const fs::path png = dir / "src.png";
  const auto r = run({"render", std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml", "-o", png.string(),
                      "--scale", std::to_string(scale)});
  REQUIRE(r.code == 0);
  return png;
}

const std::string knots = "0,0\n1,2\n3,1\n4,3\n5,0\n";

}  // namespace

TEST_CASE("help: every subcommand shows typed options with their defaults and an example") {
  const auto top = run({"--help"});
  REQUIRE(top.code == 0);
  for (const char* cmd : {"diff", "eval", "figures", "interp", "kernel", "render", "resample", "version"}) {
    const auto r = run({cmd, "--help"});
    INFO(cmd << " --help:\n" << r.out);
    CHECK(r.code == 0);
    CHECK_THAT(top.out, Catch::Contains(cmd));
    CHECK_THAT(r.out, !Catch::Contains(" TEXT"));
    const auto example = r.out.find("Example: ");
    REQUIRE(example != std::string::npos);
    CHECK_THAT(r.out.substr(example), Catch::Contains("splinefig " + std::string(cmd)));
    CHECK_THAT(r.out, !Catch::Contains("(default"));  // defaults are shown as NAME=VALUE, never in prose
  }
  CHECK_THAT(run({"eval", "--help"}).out, Catch::Contains("--grain INT=16"));
  CHECK_THAT(run({"eval", "--help"}).out, Catch::Contains("INPUT PATH"));
  CHECK_THAT(run({"resample", "--help"}).out, Catch::Contains("--edge NAME=clamp"));
  CHECK_THAT(run({"render", "--help"}).out, Catch::Contains("--threads INT=0"));
  CHECK_THAT(run({"diff", "--help"}).out, Catch::Contains("--mask PATH"));
}

TEST_CASE("input: eval, interp and kernel read a file, - or stdin alike") {
  const fs::path dir = scratch("input");
  write_text(dir / "k.csv", knots);
  for (const std::vector<std::string>& cmd :
       {std::vector<std::string>{"eval", "--basis", "catmull-rom", "--grain", "3"}, {"interp", "--output", "bezier"}}) {
    const auto piped = run(cmd, knots);
    REQUIRE(piped.code == 0);
    auto with = [&](const std::string& arg, const std::string& in) {
      auto a = cmd;
      a.push_back(arg);
      return run(a, in);
    };
    CHECK(with((dir / "k.csv").string(), "").out == piped.out);
    CHECK(with("-", knots).out == piped.out);
  }
  // Catmull-Rom through 0,0 1,2 3,1 4,3 at t = 0 of piece 1 is the knot 1,2 (interpolating).
  CHECK(run({"eval", "--basis", "catmull-rom", "--grain", "1", (dir / "k.csv").string()}).out.starts_with("1,2\n3,1\n"));
  check_fails({"eval", "--basis", "bspline", (dir / "missing.csv").string()}, "", "missing.csv");
  check_fails({"interp", (dir / "missing.csv").string()}, "", "missing.csv");
  // Errors name the file and its line.
  write_text(dir / "bad.csv", "0,0\n1,1\n2,x\n3,3\n");
  check_fails({"eval", "--basis", "bspline", (dir / "bad.csv").string()}, "", "bad.csv line 3, field 2: 'x' is not a number");
  check_fails({"interp", (dir / "bad.csv").string()}, "", "bad.csv line 3, field 2");
}

TEST_CASE("input: a first line of names is skipped, a line of numbers and names is an error") {
  const auto plain = run({"eval", "--basis", "bspline"}, knots);
  REQUIRE(plain.code == 0);
  CHECK(run({"eval", "--basis", "bspline"}, "x,y\n" + knots).out == plain.out);
  CHECK(run({"eval", "--basis", "bspline"}, "# knots\n\nx , y\n" + knots).out == plain.out);
  CHECK(run({"interp"}, "x,y\n" + knots).out == run({"interp"}, knots).out);
  check_fails({"eval", "--basis", "bspline"}, "x,1\n" + knots, "stdin line 1, field 1: 'x' is not a number");
  check_fails({"eval", "--basis", "bspline"}, knots + "x,y\n", "stdin line 6, field 1: 'x' is not a number");
  check_fails({"eval", "--basis", "bspline"}, "x,y,z\n" + knots, "stdin line 2: 2 coordinates, but the header on line 1 names 3");
}

TEST_CASE("input: --delimiter takes comma, semicolon, tab and space") {
  const auto plain = run({"eval", "--basis", "bspline"}, knots);
  auto with = [&](const std::string& d, char c) {
    std::string text = knots;
    for (auto& ch : text) ch = ch == ',' ? c : ch;
    return run({"eval", "--basis", "bspline", "--delimiter", d}, text);
  };
  CHECK(with("comma", ',').out == plain.out);
  CHECK(with("semicolon", ';').out == plain.out);
  CHECK(with(";", ';').out == plain.out);
  CHECK(with("tab", '\t').out == plain.out);
  CHECK(with("space", ' ').out == plain.out);
  // space: runs of blanks, tabs too, are one separator.
  CHECK(run({"eval", "--basis", "bspline", "--delimiter", "space"}, "0   0\n1\t 2\n  3 1\n4 3\n5 0\n").out == plain.out);
  CHECK(run({"interp", "--delimiter", "tab"}, "x\ty\n0\t0\n1\t1\n").code == 0);
  check_fails({"eval", "--basis", "bspline", "--delimiter", "pipe"}, knots, "--delimiter: 'pipe' is not one of");
  // A tab-separated file read as comma-separated: its first line passes for names, the next
  // is named with its line and field.
  check_fails({"eval", "--basis", "bspline"}, "0\t0\n1\t1\n", "stdin line 2, field 1: '1\\x091' is not a number");
}

TEST_CASE("kernel: box, tent and lanczos3 by name, at the values of an input file") {
  // Exact values: box(0.25) = 1, tent(0.5) = 1/2, lanczos3(0.5) = sinc(1/2) sinc(1/6) = 6/pi^2.
  auto one = [](const std::string& basis, const std::string& x) {
    const auto r = run({"kernel", "--basis", basis, "-"}, "x\n" + x + "\n");
    REQUIRE(r.code == 0);
    REQUIRE(count_lines(r.out) == 1);
    return std::stod(r.out.substr(r.out.find(',') + 1));
  };
  CHECK(one("box", "0.25") == 1.0);
  CHECK(one("tent", "0.5") == 0.5);
  CHECK(one("lanczos3", "0.5") == Approx(6 / (M_PI * M_PI)).epsilon(1e-15));
  CHECK(one("tent", "1.5") == 0.0);
  check_fails({"kernel", "--basis", "tent", "-", "--from", "0"}, "0\n", "cannot be combined with an input file");
  check_fails({"kernel", "--basis", "tent", "-"}, "0,1\n", "stdin: 2 values per line, expected one");
  check_fails({"kernel", "--basis", "tent", "--report", "-"}, "0\n", "--report takes no input file");
  check_fails({"kernel", "--basis", "triangle"}, "", "--basis");
}

TEST_CASE("kernel: --response honours --from, --to and --step") {
  // The box's response is |sinc f| = |sin(pi f)/(pi f)|: 1 at 0, 2/pi at 1/2.
  const auto r = run({"kernel", "--basis", "box", "--response", "--from", "0", "--to", "0.5", "--step", "0.25"});
  REQUIRE(r.code == 0);
  REQUIRE(count_lines(r.out) == 3);
  CHECK(r.out.starts_with("0,1\n0.25,"));
  CHECK(std::stod(r.out.substr(r.out.rfind("0.5,") + 4)) == Approx(2 / M_PI).epsilon(1e-12));
  const auto d = run({"kernel", "--basis", "box", "--response"});
  CHECK(d.out.starts_with("0,1\n"));
  CHECK(count_lines(d.out) == 513);  // 0 to 2 by 1/256
  check_fails({"kernel", "--basis", "box", "--response", "--from", "1", "--to", "0"}, "", "--to 0 is less than --from 1");
  check_fails({"kernel", "--basis", "box", "--response", "--step", "0"}, "", "--step: 0 must be positive");
}

TEST_CASE("resample: --size Wx and xH keep the aspect ratio, --bits chooses the depth, -v says what it did") {
  const fs::path dir = scratch("resample");
  const fs::path src = source_png(dir);
  REQUIRE(png_header(src).width == 800);
  REQUIRE(png_header(src).height == 500);
  const std::string out = (dir / "out.png").string();
  auto resample = [&](std::vector<std::string> extra) {
    std::vector<std::string> a{"resample", src.string(), "-o", out, "--filter", "catmull-rom"};
    a.insert(a.end(), extra.begin(), extra.end());
    return run(a);
  };
  REQUIRE(resample({"--size", "300x"}).code == 0);
  CHECK(png_header(out).width == 300);
  CHECK(png_header(out).height == 188);  // 500 * 300/800 = 187.5, rounded
  REQUIRE(resample({"--size", "x200"}).code == 0);
  CHECK(png_header(out).width == 320);
  CHECK(png_header(out).height == 200);
  CHECK(png_header(out).bits == 8);
  REQUIRE(resample({"--size", "x200", "--bits", "16"}).code == 0);
  CHECK(png_header(out).bits == 16);
  const auto v = resample({"--size", "40x25", "-v"});
  CHECK(v.code == 0);
  CHECK(count_lines(v.err) == 1);
  CHECK_THAT(v.err, Catch::Contains("800x500 -> " + out + " 40x25 (4 channels, 8-bit, --filter catmull-rom, --edge clamp)"));
  CHECK(resample({"--size", "40x25"}).err.empty());
  fs::remove(out);
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--size", "x"}, "--size: 'x' is not WxH, Wx or xH"},
           {{"--size", "300"}, "is not WxH"},
           {{"--size", "0x"}, "--size width"},
           {{"--size", "x1e3"}, "--size height"},
           {{"--size", "300x", "--bits", "float"}, "--bits float: PNG holds 8 or 16 bits"},
           {{"--size", "300x", "--bits", "12"}, "--bits: '12' is not 8, 16 or float"}}) {
    const auto r = resample(args);
    INFO(args[1] << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(says));
    CHECK(!fs::exists(out));
  }
  const auto exr = run({"resample", src.string(), "-o", (dir / "o.exr").string(), "--filter", "tent", "--size", "x50",
                        "--bits", "16"});
  CHECK(exr.code == 2);
  CHECK_THAT(exr.err, Catch::Contains("--bits 16: .exr is written as float"));
  fs::remove_all(dir);
}

TEST_CASE("progress: resample and diff --perceptual on large images show a line on a terminal only") {
  const fs::path dir = scratch("progress");
  const fs::path src = source_png(dir, 3);  // 2400x1500 RGBA: 14.4 M samples
  const std::string out = (dir / "out.png").string();
  const std::vector<std::string> resample{"resample", src.string(), "-o", out, "--filter", "tent", "--size", "1200x"};
  const std::vector<std::string> diff{"diff", "--perceptual", src.string(), src.string()};
  // Piped (as in this test's run()): nothing on stderr.
  for (const auto& args : {resample, diff}) {
    const auto r = run(args);
    CHECK(r.code == 0);
    CHECK(r.err.empty());
  }
  if (std::system("script --version >/dev/null 2>&1") != 0) {
    splinefig::testing_support::skip("no script(1) to give the command a terminal");
    return;
  }
  // On a terminal (script(1) runs the command on a pseudo-terminal and records what it shows).
  auto on_terminal = [&](const std::vector<std::string>& args) {
    std::string cmd = shell_quote(SPLINEFIG_EXE);
    for (const auto& a : args) cmd += ' ' + shell_quote(a);
    const fs::path typescript = dir / "typescript";
    const std::string line = "script -qec " + shell_quote(cmd + " >/dev/null") + " " + shell_quote(typescript.string()) +
                             " </dev/null >/dev/null 2>&1";
    CHECK(std::system(line.c_str()) == 0);
    return slurp(typescript);
  };
  const std::string shown = on_terminal(resample);
  CHECK_THAT(shown, Catch::Contains("splinefig resample: filtering 2400x1500 to 1200x750..."));
  CHECK_THAT(shown, Catch::Contains("\x1b[K"));  // and erased when done
  CHECK_THAT(on_terminal(diff), Catch::Contains("splinefig diff: comparing 2400x1500 (SSIM, FLIP)..."));
  fs::remove_all(dir);
}

TEST_CASE("resample: JPEG by the output's extension, alpha composited over white") {
  const fs::path dir = scratch("formats");
  // The same square drawn on transparency and on white: over white, the first is the second.
  const std::string square = "[[polygon]]\npoints = [[20, 20], [100, 20], [100, 60], [20, 60]]\ncolor = \"#204080\"\n";
  write_text(dir / "clear.toml", "[canvas]\nwidth = 120\nheight = 80\nbackground = \"#00000000\"\n" + square);
  write_text(dir / "white.toml", "[canvas]\nwidth = 120\nheight = 80\nbackground = \"#ffffff\"\n" + square);
  for (const char* name : {"clear", "white"})
    REQUIRE(run({"render", (dir / (std::string(name) + ".toml")).string(), "-o", (dir / (std::string(name) + ".png")).string()}).code == 0);
  auto resample = [&](const std::string& in, const std::string& out, std::vector<std::string> extra = {}) {
    std::vector<std::string> a{"resample", (dir / in).string(), "-o", (dir / out).string(), "--filter", "tent", "--size", "60x"};
    a.insert(a.end(), extra.begin(), extra.end());
    return run(a);
  };
  REQUIRE(resample("clear.png", "clear.jpg").code == 0);
  REQUIRE(resample("white.png", "white-small.png").code == 0);
  const std::string jpg = slurp(dir / "clear.jpg");
  REQUIRE(jpg.size() > 3);
  CHECK(jpg.substr(0, 3) == "\xff\xd8\xff");  // a JPEG file
  // JPEG is lossy: within 6% of the white-background picture in every value (its edges), where
  // transparency left black or dropped would be off by 1.
  const auto same = run({"diff", (dir / "white-small.png").string(), (dir / "clear.jpg").string(), "--ignore-alpha",
                         "--fail", "0.06"});
  INFO(same.out << same.err);
  CHECK(same.code == 0);
  for (const auto& [out, bits, says] : std::vector<std::array<std::string, 3>>{
           {"x.jpg", "16", "--bits 16: JPEG holds 8 bits"},
           {"x.exr", "8", "--bits 8: .exr is written as float"}}) {
    const auto r = resample("white.png", out, {"--bits", bits});
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(says));
    CHECK(!fs::exists(dir / out));
  }
  const auto bmp = resample("white.png", "x.bmp");
  CHECK(bmp.code == 2);
  CHECK_THAT(bmp.err, Catch::Contains("unsupported output format '.bmp' (use .png, .jpg, .tif or .exr)"));
  // TIFF: by default as the input is stored (8 bits from an 8-bit PNG, float from an EXR).
  REQUIRE(resample("white.png", "white.exr").code == 0);
  for (const auto& [in, out, bits, says] : std::vector<std::array<std::string, 4>>{
           {"white.png", "a.tif", "", "8-bit"},
           {"white.png", "b.tiff", "16", "16-bit"},
           {"white.exr", "c.tif", "", "float"},
           {"white.png", "d.tif", "float", "float"}}) {
    std::vector<std::string> extra{"-v"};
    if (!bits.empty()) extra.insert(extra.end(), {"--bits", bits});
    const auto r = resample(in, out, extra);
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK_THAT(r.err, Catch::Contains("60x40 (4 channels, " + says + ","));
    CHECK(slurp(dir / out).substr(0, 4) == std::string("II*\0", 4));
  }
  fs::remove_all(dir);
}
