// Error messages keep the one-line, located promise on the inputs that broke it: a path that
// cannot be followed is said as such (not as missing, not as a raw filesystem exception), a
// --specs that is not a directory is named, and so on. Each case: exit 2 (4 for diff), one line
// on stderr, and the line says what and where.
#include "hostile.hpp"

#include <cstdio>

using namespace splinefig::hostile;
using splinefig::test::count_lines;

namespace {

const std::string kCanvas = "[canvas]\nwidth = 24\nheight = 24\n";

// A symlink loop: `name` -> `name`.2 -> `name`.
void make_loop(const fs::path& dir, const std::string& name) {
  fs::create_symlink(name + ".2", dir / name);
  fs::create_symlink(name, dir / (name + ".2"));
}

void check_one_line(const Outcome& o, int code, const std::string& line) {
  INFO(o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == code);
  CHECK(count_lines(o.err) == 1);
  CHECK(o.err == line + "\n");
}

}  // namespace

TEST_CASE("a symlink loop named by a spec is 'too many levels of symbolic links', located") {
  const fs::path dir = scratch();
  make_loop(dir, "loop.png");
  make_loop(dir, "loop.csv");
  check_one_line(render_spec(dir, "img", kCanvas + "[[image]]\nfile = \"loop.png\"\nat = [0, 0]\nsize = [4, 4]\n"), 2,
                 "splinefig render: img.toml:5: image[0].file: cannot open the image file \"./loop.png\" (Too many levels "
                 "of symbolic links)");
  check_one_line(render_spec(dir, "pts", kCanvas + "[[polyline]]\npoints_file = \"loop.csv\"\n"), 2,
                 "splinefig render: pts.toml:5: polyline[0].points_file: cannot open the data file \"./loop.csv\" (Too "
                 "many levels of symbolic links)");
  // A missing file is still "no such ... file".
  check_one_line(render_spec(dir, "gone", kCanvas + "[[polyline]]\npoints_file = \"gone.csv\"\n"), 2,
                 "splinefig render: gone.toml:5: polyline[0].points_file: no such data file \"./gone.csv\"");
  fs::remove_all(dir);
}

TEST_CASE("a symlink loop given to a command is 'too many levels of symbolic links'") {
  const fs::path dir = scratch();
  make_loop(dir, "loop");
  check_one_line(run_in(dir, {"diff", "loop", "loop"}), 4,
                 "splinefig diff: cannot read loop: cannot open the file (Too many levels of symbolic links)");
  check_one_line(run_in(dir, {"resample", "loop", "-o", "out.png", "--size", "3x3", "--filter", "tent"}), 2,
                 "splinefig resample: loop: cannot open the file (Too many levels of symbolic links)");
  check_one_line(run_in(dir, {"eval", "loop", "--basis", "catmull-rom"}), 2,
                 "splinefig eval: loop: cannot open it (Too many levels of symbolic links)");
  check_one_line(run_in(dir, {"figures", "--specs", "loop", "--out", "out"}), 2,
                 "splinefig figures: --specs loop: cannot open it (Too many levels of symbolic links)");
  check_one_line(run_in(dir, {"figures", "--out", "loop", "--only", "bias"}), 2,
                 "splinefig figures: --out loop: cannot create the directory (Too many levels of symbolic links)");
  fs::remove_all(dir);
}

TEST_CASE("a spec in --specs that is a symlink loop fails as that figure, not the whole listing") {
  const fs::path dir = scratch();
  fs::create_directories(dir / "specs");
  make_loop(dir / "specs", "a.toml");
  const Outcome o = run_in(dir, {"figures", "--specs", "specs", "--out", "out", "--format", "svg"});
  INFO(o.err);
  CHECK(o.code == 2);
  CHECK_THAT(o.err, Catch::StartsWith("splinefig figures: specs/a.toml: cannot read the spec file (Too many levels of "
                                      "symbolic links)\n"));
  CHECK(o.err.find("filesystem error") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("figures --specs names the path it was given when that is no directory") {
  const fs::path dir = scratch();
  write_file(dir / "one.toml", kCanvas);
  check_one_line(run_in(dir, {"figures", "--specs", "one.toml", "--out", "out"}), 2,
                 "splinefig figures: --specs one.toml: not a directory (give the directory of the specs)");
  check_one_line(run_in(dir, {"figures", "--specs", "none", "--out", "out"}), 2,
                 "splinefig figures: --specs none: no such directory");
  fs::remove_all(dir);
}

TEST_CASE("a parameter given to a fixed kernel is a parameter error, not an unknown filter") {
  const fs::path dir = scratch();
  check_one_line(run_in(dir, {"kernel", "--basis", "lanczos3:a=2"}), 2,
                 "splinefig kernel: --basis: lanczos3: unknown parameter 'a' (it takes none; its a is 3)");
  check_one_line(run_in(dir, {"kernel", "--basis", "box:x=1"}), 2,
                 "splinefig kernel: --basis: box: unknown parameter 'x' (it takes none)");
  check_one_line(run_in(dir, {"kernel", "--basis", "tent:"}), 2,
                 "splinefig kernel: --basis: tent: empty parameter list after ':'");
  write_file(dir / "flt.toml", kCanvas + "filter = \"lanczos3:a=2\"\n");
  check_one_line(run_in(dir, {"render", "flt.toml", "-o", "flt.png"}), 2,
                 "splinefig render: flt.toml:4: canvas.filter: lanczos3: unknown parameter 'a' (it takes none; its a is 3)");
  fs::remove_all(dir);
}

TEST_CASE("a number out of range is said back in its shortest form") {
  const fs::path dir = scratch();
  write_file(dir / "s.toml", kCanvas);
  check_one_line(run_in(dir, {"render", "s.toml", "-o", "s.png", "--scale", "1e308"}), 2,
                 "splinefig render: --scale 1e+308: must be in (0, 64]");
  check_one_line(run_in(dir, {"render", "s.toml", "-o", "s.png", "--scale", "-1e-300"}), 2,
                 "splinefig render: --scale -1e-300: must be in (0, 64]");
  check_one_line(run_in(dir, {"figures", "--scale", "64.0001", "--out", "out"}), 2,
                 "splinefig figures: --scale 64.0001: must be in (0, 64]");
  check_one_line(run_in(dir, {"render", "s.toml", "-o", "s.png", "--dpi", "1e-308"}), 2,
                 "splinefig render: --dpi 1e-308: must be in [1, 10000]");
  check_one_line(run_in(dir, {"figures", "--dpi", "10000.0001", "--out", "out"}), 2,
                 "splinefig figures: --dpi 10000.0001: must be in [1, 10000]");
  // Beyond a double: as typed, not the "inf" it was read as.
  check_one_line(run_in(dir, {"render", "s.toml", "-o", "s.png", "--scale", "1e400"}), 2,
                 "splinefig render: --scale 1e400: must be in (0, 64]");
  check_one_line(run_in(dir, {"figures", "--dpi", "-1e400", "--out", "out"}), 2,
                 "splinefig figures: --dpi -1e400: must be in [1, 10000]");
  check_one_line(run_in(dir, {"diff", "a.png", "b.png", "--fail", "-0.5"}), 2,
                 "splinefig diff: --fail -0.5: must be a number in [0, 3.4028235e+38] (a float)");
  fs::remove_all(dir);
}

TEST_CASE("a markup error quotes a short escaped excerpt of the label, not all of it") {
  const fs::path dir = scratch();
  const std::string big = "$" + std::string(100000, 'A') + "^";
  check_one_line(render_spec(dir, "big", kCanvas + "[[text]]\ntext = \"" + big + "\"\nat = [1, 1]\n"), 2,
                 "splinefig render: big.toml:5: text[0].text: \"$" + std::string(39, 'A') +
                     "...\" (100002 bytes): a dangling ^ at the end");
  check_one_line(render_spec(dir, "title", "title = \"" + big + "\"\n" + kCanvas), 2,
                 "splinefig render: title.toml:1: title: \"$" + std::string(39, 'A') +
                     "...\" (100002 bytes): a dangling ^ at the end");
  // A cut never splits a character; control characters are escaped.
  check_one_line(render_spec(dir, "utf8", kCanvas + "[[text]]\ntext = \"" + std::string(39, 'a') + "\u00e9$x^\"\nat = [1, 1]\n"), 2,
                 "splinefig render: utf8.toml:5: text[0].text: \"" + std::string(39, 'a') +
                     "...\" (44 bytes): a dangling ^ at the end");
  check_one_line(render_spec(dir, "esc", kCanvas + "[[text]]\ntext = \"a\\u001b[2J $x^\"\nat = [1, 1]\n"), 2,
                 "splinefig render: esc.toml:5: text[0].text: \"a\\x1b[2J $x^\": a dangling ^ at the end");
  fs::remove_all(dir);
}

TEST_CASE("a value, a file name or a data name the spec repeats in an error keeps the error on one line") {
  const fs::path dir = scratch();
  // TOML's \n and \u001b escapes put a newline and an ESC into the strings.
  check_one_line(render_spec(dir, "legend", "[axes]\nx_range = [0, 1]\ny_range = [0, 1]\nlegend = \"upper\\nleft\"\n"), 2,
                 "splinefig render: legend.toml:4: axes.legend: unknown value \"upper\\x0aleft\" (expected auto | none | upper left | "
                 "upper right | lower left | lower right | upper center | lower center | outside right | outside-right)");
  check_one_line(render_spec(dir, "file", "[axes]\n[[axes.series]]\npoints_file = \"no\\nsuch\\u001b.csv\"\n"), 2,
                 "splinefig render: file.toml:3: axes.series[0].points_file: no such data file \"./no\\x0asuch\\x1b.csv\"");
  check_one_line(render_spec(dir, "named", "[axes]\n[[axes.series]]\npoints = \"a\\r\\nb\"\n"), 2,
                 "splinefig render: named.toml:3: axes.series[0].points: no data named \"a\\x0d\\x0ab\" (the spec has no [data] table)");
  fs::remove_all(dir);
}

TEST_CASE("a basis spec's parameters are quoted at most 40 bytes long, in flags and in specs") {
  const fs::path dir = scratch();
  const std::string ones(10000, '1');
  // A value, a parameter that is not key=value, an unknown name, a fixed kernel's parameter:
  // 40 bytes of each, "...", and its size, wherever the user typed 10000.
  check_one_line(run_in(dir, {"kernel", "--basis", "mitchell-netravali:b=x" + ones}), 2,
                 "splinefig kernel: --basis: mitchell-netravali: value of 'b' is not a number: 'x" + std::string(39, '1') +
                     "...' (10001 bytes)");
  check_one_line(run_in(dir, {"kernel", "--basis", "mitchell-netravali:b=" + ones}), 2,
                 "splinefig kernel: --basis: mitchell-netravali: value of 'b' is out of the range of a double: '" +
                     std::string(40, '1') + "...' (10000 bytes)");
  check_one_line(run_in(dir, {"resample", "in.png", "-o", "out.png", "--scale", "2", "--filter", "mitchell-netravali:" + ones}), 2,
                 "splinefig resample: --filter: mitchell-netravali: parameter '" + std::string(40, '1') +
                     "...' (10000 bytes) is not key=value");
  check_one_line(run_in(dir, {"eval", "--basis", "z" + ones + ":b=1"}), 2,
                 "splinefig eval: --basis: unknown basis 'z" + std::string(39, '1') +
                     "...' (10001 bytes) (known: catmull-rom, cardinal, bspline, tensioned-bspline, beta, uniform-bspline, "
                     "mitchell-netravali)");
  check_one_line(run_in(dir, {"kernel", "--basis", "box:" + ones + "=1"}), 2,
                 "splinefig kernel: --basis: box: unknown parameter '" + std::string(40, '1') + "...' (10000 bytes) (it takes none)");
  // A valid number of 10000 digits, said back in a message about its sign.
  check_one_line(run_in(dir, {"kernel", "--basis", "cardinal:a=-0." + ones}), 2,
                 "splinefig kernel: --basis: cardinal: a='-0." + std::string(37, '1') +
                     "...' (10003 bytes) is negative: the tangent at every knot would point backwards (a >= 0; a = 0 is the "
                     "control polygon, 0.5 Catmull-Rom)");
  // A spec that parses, said again when its filter's energy (a^2) overflows.
  check_one_line(run_in(dir, {"kernel", "--report", "--basis", "cardinal:a=1" + std::string(200, '0')}), 2,
                 "splinefig kernel: --basis \"cardinal:a=1" + std::string(28, '0') +
                     "...\" (212 bytes): the filter's energy overflows the range of a double");
  // In a spec: the canvas filter, and a curve's basis (whose message also quotes the spec).
  check_one_line(render_spec(dir, "filter", kCanvas + "filter = \"mitchell-netravali:c=x" + ones + "\"\n"), 2,
                 "splinefig render: filter.toml:4: canvas.filter: mitchell-netravali: value of 'c' is not a number: 'x" +
                     std::string(39, '1') + "...' (10001 bytes)");
  check_one_line(render_spec(dir, "curve", kCanvas + "[axes]\n[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\n"
                                                     "basis = \"beta:b1=" + ones + "\"\n"),
                 2,
                 "splinefig render: curve.toml:7: axes.curve[0].basis: basis \"beta:b1=" + std::string(32, '1') +
                     "...\" (10008 bytes): beta: value of 'b1' is out of the range of a double: '" + std::string(40, '1') +
                     "...' (10000 bytes)");
  fs::remove_all(dir);
}

TEST_CASE("diff refuses a negative, NaN or out-of-range threshold, saying the flag and the value as typed") {
  const fs::path dir = scratch();
  const std::string fl = ": must be a number in [0, 3.4028235e+38] (a float)";  // FLT_MAX, 2^128 - 2^104
  auto diff = [&](const std::string& flag, const std::string& value) {
    return run_in(dir, {"diff", "a.png", "b.png", flag, value});
  };
  // -1e300 is a double but no float (it was read as -inf); 1e400 is no double either; 1e39 became
  // inf, which --hardfail took for no limit.
  check_one_line(diff("--fail", "-1e300"), 2, "splinefig diff: --fail -1e+300" + fl);
  check_one_line(diff("--fail", "1e400"), 2, "splinefig diff: --fail 1e400" + fl);
  check_one_line(diff("--warn", "1e39"), 2, "splinefig diff: --warn 1e+39" + fl);
  check_one_line(diff("--warn", "nan"), 2, "splinefig diff: --warn nan" + fl);
  check_one_line(diff("--fail", "inf"), 2, "splinefig diff: --fail inf" + fl);
  check_one_line(diff("--hardfail", "-1e300"), 2, "splinefig diff: --hardfail -1e+300" + fl + ", or inf for none");
  check_one_line(diff("--hardfail", "1e39"), 2, "splinefig diff: --hardfail 1e+39" + fl + ", or inf for none");
  check_one_line(diff("--hardwarn", "1e400"), 2, "splinefig diff: --hardwarn 1e400" + fl + ", or inf for none");
  check_one_line(diff("--failpercent", "-1e300"), 2, "splinefig diff: --failpercent -1e+300: must be a percentage in [0, 100]");
  check_one_line(diff("--warnpercent", "1e400"), 2, "splinefig diff: --warnpercent 1e400: must be a percentage in [0, 100]");
  check_one_line(diff("--ssim", "-1e300"), 2, "splinefig diff: --ssim -1e+300: must be in [-1, 1]");
  check_one_line(diff("--flip", "1e400"), 2, "splinefig diff: --flip 1e400: must be in [0, 1]");
  check_one_line(run_in(dir, {"diff", "a.png", "b.png", "--diff-image", "d.png", "--scale", "1e-50"}), 2,
                 "splinefig diff: --scale 1e-50: must be a number in (0, 3.4028235e+38] (a float)");
  check_one_line(diff("--allowfailures", "-5"), 2, "splinefig diff: --allowfailures -5: must be >= 0");
  // A long value is quoted at most 40 bytes long.
  check_one_line(diff("--fail", "1" + std::string(500, '0')), 2,
                 "splinefig diff: --fail \"1" + std::string(39, '0') + "...\" (501 bytes)" + fl);
  // The largest float and inf for no hard limit are thresholds; -0 is 0. With no images to read,
  // the command gets past the flags to the reading (exit 4).
  for (const auto& [flag, value] : {std::pair{"--fail", "3.4028235e+38"}, std::pair{"--hardfail", "inf"}, std::pair{"--warn", "-0"}}) {
    const Outcome o = diff(flag, value);
    INFO(flag << " " << value << ": " << o.err);
    CHECK(o.code == 4);
  }
  fs::remove_all(dir);
}
