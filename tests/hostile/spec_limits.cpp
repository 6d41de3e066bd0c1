// Spec limits and ranges: every quantity that drives a loop or an allocation is refused with a
// one-line "FILE:LINE: KEY: ..." before any work, and data that cannot be mapped to pixels are
// errors naming their element, never undefined behaviour or a silently missing element.
#include "hostile.hpp"

using namespace splinefig::hostile;

namespace {
const std::string kBox = "[axes]\nx_range = [0, 10]\ny_range = [0, 10]\n";

// The wait status of `splinefig ARGS REDIRECT 2> err.txt` in `dir`, after the shell command
// `setup` (a ulimit), under the suite's time limit; ARGS and REDIRECT are shell text.
int run_shell(const fs::path& dir, const std::string& setup, const std::string& args, const std::string& redirect = "") {
  const std::string cmd = "cd " + splinefig::test::shell_quote(dir.string()) + (setup.empty() ? "" : " && " + setup) +
                          " && timeout -s KILL " + std::to_string(kTimeLimit) + " " +
                          splinefig::test::shell_quote(SPLINEFIG_EXE) + " " + args + " " + redirect + " 2> err.txt";
  return std::system(cmd.c_str());
}
}

TEST_CASE("text and title sizes over 4096 px are refused by the loader, and after --scale") {
  check_refused("big_text", "[[text]]\nat = [10, 10]\ntext = \"hi\"\nsize = 1e6\n",
                "big_text.toml:4: text[0].size: font size 1e+06 is over the limit of 4096 px");
  check_refused("big_title", "title = \"hi\"\ntitle_size = 70000\n",
                "big_title.toml:2: title_size: font size 70000 is over the limit of 4096 px");
  check_refused("scaled_title", "title = \"hi\"\ntitle_size = 2000\n", "scaled_title.toml:2: title_size: text: font size",
                {"--scale", "4"});
  check_refused("scaled_text", "[canvas]\nwidth = 100\nheight = 100\n[[text]]\nat = [10, 10]\ntext = \"hi\"\nsize = 3000\n",
                "scaled_text.toml:4: text[0]: text: font size", {"--scale", "2"});
}

TEST_CASE("axis ranges of +-1e308, denormal and too narrow ranges are refused naming the key") {
  check_refused("wide", "[axes]\nx_range = [-1e308, 1e308]\ny_range = [0, 1]\n",
                "wide.toml:2: axes.x_range: the range [-1e+308, 1e+308] is wider than the largest number");
  check_refused("denormal", "[axes]\nx_range = [0, 1]\ny_range = [0, 1e-310]\n", "denormal.toml:3: axes.y_range: the range");
  check_refused("narrow", "[axes]\nx_range = [1, 1.0000000000000002]\ny_range = [0, 1]\n",
                "narrow.toml:2: axes.x_range: the range [1, 1.0000000000000002] is too narrow");
  check_refused("data_wide", "[axes]\n[[axes.series]]\npoints = [[-1e308, 0], [1e308, 1]]\n",
                "data_wide.toml:1: axes.x_range: the range [-inf, inf] is not finite (from the data)");
}

TEST_CASE("a tick step giving more than 1000 ticks is refused, with a given range or one from the data") {
  check_refused("step", "[axes]\nx_range = [0, 1]\nx_tick_step = 1e-300\n",
                "step.toml:3: axes.x_tick_step: gives more than 1000 ticks over the x_range");
  check_refused("step_data", "[axes]\ny_tick_step = 1e-300\n[[axes.series]]\npoints = [[0, 1e20], [1, 1e21]]\n",
                "step_data.toml:1: axes.y_tick_step: a tick step of 1e-300 gives more than 1000 ticks");
}

TEST_CASE("a log axis with non-positive points is an error naming the element") {
  check_refused("log_series", "[axes]\ny_scale = \"log\"\n[[axes.series]]\npoints = [[0, 1], [1, 0]]\n",
                "log_series.toml:3: axes.series: a log y axis needs positive y data");
  check_refused("log_curve", "[axes]\nx_scale = \"log\"\n[[axes.curve]]\nknots = [[1, 1], [2, 2], [-3, 1], [4, 2]]\n",
                "log_curve.toml:3: axes.curve[0]: a log x axis needs positive x data");
  check_refused("log_text", "[axes]\nx_scale = \"log\"\nx_range = [1, 10]\n[[axes.text]]\nat = [0, 1]\ntext = \"t\"\n",
                "log_text.toml:4: axes.text[0]: a log x axis needs positive x data");
}

TEST_CASE("data mapping beyond the pixel range are errors naming the element") {
  check_refused("far_point", kBox + "[[axes.series]]\npoints = [[0, 0], [1e308, 5]]\n",
                "far_point.toml:4: axes.series[0]: ");
}

TEST_CASE("arc-length marks on a curve spanning 1e155 end in bounded time with an error naming the curve") {
  check_refused("arc", kBox + "[[axes.curve]]\nknots = [[0, 0], [1e155, 1], [0, 0], [0, 0]]\nmarks = 10\n"
                              "mark_spacing = \"arclength\"\n",
                "arc.toml:4: axes.curve[0]: arc length: the curve's length is beyond the range of a double");
  const fs::path dir = scratch();
  write_file(dir / "knots.csv", "0\n1e155\n0\n0\n");
  const Outcome o = run_in(dir, {"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "5"}, kTimeLimit,
                           (dir / "knots.csv").string());
  INFO(o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 2);
  CHECK(o.out.empty());
  CHECK_THAT(o.err, Catch::Contains("overflows the range of a double"));
  fs::remove_all(dir);
}

TEST_CASE("a Bezier curve of more than 128 control points is refused, while 128 points and the largest relaxed basis finish") {
  std::string points;
  for (int i = 0; i < 129; ++i) points += (i ? ", [" : "[") + std::to_string(i % 10) + ", " + std::to_string(i % 7) + "]";
  check_refused("bezier", kBox + "[[axes.bezier]]\npoints = [" + points + "]\n",
                "bezier.toml:5: axes.bezier[0].points: 129 control points (limit 128)");
  check_refused("relaxed", kBox + "[[axes.relaxed_basis]]\nn = 1001\n", "relaxed.toml:5: axes.relaxed_basis[0].n:");
  const fs::path dir = scratch();
  points = points.substr(0, points.rfind(", ["));  // 128 points
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"bezier128", kBox + "[[axes.bezier]]\npoints = [" + points + "]\n"},
           {"relaxed1000", kBox + "[[axes.relaxed_basis]]\nn = 1000\nk = 500\n"}}) {
    const Outcome o = render_spec(dir, name, text);
    INFO(name << ": " << o.err);
    CHECK_FALSE(o.killed);
    CHECK(o.code == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("dotted keys and table headers deeper than 64 parts are refused before the TOML parser sees them") {
  auto chain = [](int n, const std::string& part) {
    std::string s = part;
    for (int i = 1; i < n; ++i) s += "." + part;
    return s;
  };
  const std::string says = ": a dotted key of more than 64 parts (the limit of key and table-header depth)";
  check_refused("deep_key", "title = \"t\"\n" + chain(50000, "a") + " = 1\n", "deep_key.toml:2" + says);
  check_refused("deep_header", "title = \"t\"\n\n[" + chain(1000, "a") + "]\nb = 1\n", "deep_header.toml:3" + says);
  check_refused("deep_array_header", "[[" + chain(1000, "a") + "]]\n", "deep_array_header.toml:1" + says);
  check_refused("deep_quoted", "# a.b.c\ns = \"a.b.c\"\n" + chain(65, "\"a\"") + " = 1\n", "deep_quoted.toml:3" + says);
  check_refused("deep_inline", "x = { " + chain(2000, "'k'") + " = 1 }\n", "deep_inline.toml:1" + says);
  check_refused("deep_after_string", "s = \"\"\"\nline\nline\"\"\"\n" + chain(100, "a") + " = 1\n",
                "deep_after_string.toml:4" + says);
  // 64 parts pass the pre-scan and reach the parser and the spec reader, which name the key.
  check_refused("key64", chain(64, "a") + " = 1\n", "key64.toml:1: a: unknown key");
  // Strings and comments full of dots are no keys.
  check_refused("dots_in_strings", "title = \"" + chain(1000, "a") + "\"\n# " + chain(1000, "b") + "\nz = 1\n",
                "dots_in_strings.toml:3: z: unknown key");
}

TEST_CASE("a 1000-part table header is refused cleanly on a 256 KiB stack") {
  const fs::path dir = scratch();
  std::string h = "a";
  for (int i = 1; i < 1000; ++i) h += ".a";
  write_file(dir / "deep.toml", "[" + h + "]\nb = 1\n");
  const int status = run_shell(dir, "ulimit -s 256", "render deep.toml -o deep.png");
  INFO(splinefig::test::slurp(dir / "err.txt"));
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(splinefig::test::slurp(dir / "err.txt") ==
        "splinefig render: deep.toml:1: a dotted key of more than 64 parts (the limit of key and table-header depth)\n");
  CHECK_FALSE(fs::exists(dir / "deep.png"));
}

// The parser recurses into every array and inline table too, a few KiB of stack a level: under
// a 256 KiB stack 150 nested inline tables or 250 nested arrays (toml++ allows 256) died by
// SIGSEGV with nothing said. The scan refuses more than 16 levels; 16 parse on that stack.
TEST_CASE("arrays and inline tables nested more than 16 deep are refused by the scan, on a 256 KiB stack too") {
  const fs::path dir = scratch();
  auto nested = [](int n, const std::string& open, const std::string& inner, const std::string& close) {
    std::string s;
    for (int i = 0; i < n; ++i) s += open;
    s += inner;
    for (int i = 0; i < n; ++i) s += close;
    return s;
  };
  const std::string says = ": arrays and inline tables nested more than 16 deep (the limit of value nesting)";
  struct Case {
    std::string name, text, err;
  };
  const std::vector<Case> cases{
      {"arrays", "title = \"t\"\na = " + nested(250, "[", "", "]") + "\n", "arrays.toml:2" + says},
      {"tables", "a = " + nested(150, "{b = ", "1", "}") + "\n", "tables.toml:1" + says},
      {"mixed", "a = " + nested(9, "[{b = ", "1", "}]") + "\n", "mixed.toml:1" + says},
      {"lines", "a = [\n" + nested(17, "[\n", "", "]\n") + "]\n", "lines.toml:17" + says},
      {"huge", "a = " + nested(100000, "[", "", "]") + "\n", "huge.toml:1" + says},
      // 16 levels reach the parser and the spec reader, which names the key.
      {"arrays16", "a = " + nested(16, "[", "", "]") + "\n", "arrays16.toml:1: a: unknown key"},
      {"tables16", "a = " + nested(16, "{b = ", "1", "}") + "\n", "tables16.toml:1: a: unknown key"},
      // Brackets in strings and comments are no nesting.
      {"quoted", "title = \"" + nested(40, "[", "", "]") + "\"\n# " + nested(40, "{", "", "}") + "\nz = 1\n",
       "quoted.toml:3: z: unknown key"},
  };
#if defined(__SANITIZE_ADDRESS__)
  const std::string stack = "";  // the sanitizer's frames are several times larger
#else
  const std::string stack = "ulimit -s 256";
#endif
  for (const Case& c : cases) {
    write_file(dir / (c.name + ".toml"), c.text);
    const int status = run_shell(dir, stack, "render " + c.name + ".toml -o out.png");
    const std::string err = splinefig::test::slurp(dir / "err.txt");
    INFO(c.name << ": " << err);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    CHECK(err == "splinefig render: " + c.err + "\n");
    CHECK_FALSE(fs::exists(dir / "out.png"));
  }
  fs::remove_all(dir);
}

TEST_CASE("a pixel filter the renderer refuses is an error at load, with the spec's file, line and key") {
  check_refused("wide_filter", "[canvas]\nwidth = 20\nheight = 20\nfilter = \"uniform-bspline:degree=12\"\n",
                "wide_filter.toml:4: canvas.filter: pixel filter 'uniform-bspline:degree=12': support wider than 8 px");
}

TEST_CASE("a spec string holding a NUL is refused: no path is cut short at it") {
  const std::string says = ": a string holding a NUL character (\\u0000)";
  check_refused("nul_points", "[axes]\n[[axes.series]]\npoints_file = \"a\\u0000b\"\n", "nul_points.toml:3: axes.series[0].points_file" + says);
  check_refused("nul_image", "[[image]]\nfile = \"img.png\\u0000.exr\"\n", "nul_image.toml:2: image[0].file" + says);
  check_refused("nul_title", "title = \"a\\u0000b\"\n", "nul_title.toml:1: title" + says);
}

TEST_CASE("a write over the file-size limit (ulimit -f) is a one-line error and leaves no temporary") {
  const fs::path dir = scratch();
  write_file(dir / "big.toml", "[canvas]\nwidth = 400\nheight = 400\n[[circle]]\ncenter = [200, 200]\nradius = 150\n");
  const int status = run_shell(dir, "ulimit -f 2", "render big.toml -o keep.png");
  INFO(splinefig::test::slurp(dir / "err.txt"));
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(splinefig::test::slurp(dir / "err.txt") == "splinefig render: keep.png: write failed (File too large)\n");
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  CHECK(left == std::vector<std::string>{"big.toml", "err.txt"});
}

// The other writers: every output format, figures, resample and diff's images.
TEST_CASE("every command's file write over the file-size limit is a one-line error and leaves no temporary") {
  const fs::path dir = scratch();
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml";
  const std::string png = std::string(SPLINEFIG_SOURCE_DIR) + "/tests/reference/renderer/fills.png";
  struct Case {
    std::string args, err;
    int code;
  };
  const std::string specs = " --specs " + std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs";
  for (const Case& c :
       {Case{"render " + spec + " -o keep.svg", "splinefig render: keep.svg: write failed (File too large)\n", 2},
        {"render " + spec + " -o keep.pdf", "splinefig render: keep.pdf: write failed (File too large)\n", 2},
        {"render " + spec + " -o keep.exr", "splinefig render: keep.exr: write failed (File too large)\n", 2},
        {"figures --out figs --only bias" + specs,
         "splinefig figures: " + std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml: figs/bias.png: write failed (File too "
         "large)\nsplinefig figures: 1 of 1 figures failed\n", 2},
        {"resample " + png + " -o keep.png --filter bspline --size 600x600",
         "splinefig resample: keep.png: write failed (File too large)\n", 2},
        {"resample " + png + " -o keep.tif --filter bspline --size 600x600",
         "splinefig resample: keep.tif: write failed (File too large)\n", 2},
        {"resample " + png + " -o keep.jpg --filter bspline --size 600x600",
         "splinefig resample: keep.jpg: write failed (File too large)\n", 2},
        {"resample " + png + " -o keep.exr --filter bspline --size 600x600",
         "splinefig resample: keep.exr: write failed (File too large)\n", 2},
        {"diff " + png + " " + png + " --triptych keep.png",
         "splinefig diff: cannot write keep.png: write failed (File too large)\n", 4}}) {
    fs::create_directories(dir / "figs");
    const int status = run_shell(dir, "ulimit -f 1", c.args);
    const std::string err = splinefig::test::slurp(dir / "err.txt");
    INFO(c.args << ": " << err);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == c.code);
    CHECK(err == c.err);
    std::vector<std::string> left;
    for (const auto& e : fs::recursive_directory_iterator(dir)) left.push_back(e.path().lexically_relative(dir).string());
    std::sort(left.begin(), left.end());
    CHECK(left == std::vector<std::string>{"err.txt", "figs"});
    fs::remove(dir / "err.txt");
  }
  fs::remove_all(dir);
}

TEST_CASE("a command whose standard output cannot be written says so and fails, never exits 0") {
  const fs::path dir = scratch();
  const std::string png = std::string(SPLINEFIG_SOURCE_DIR) + "/tests/reference/renderer/fills.png";
  struct Case {
    std::string args, who;
    int code;
  };
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml";
  write_file(dir / "knots.csv", "0,0\n1,2\n3,1\n4,4\n");
  // Every command, its help, the hidden reference options and each way a file reaches stdout.
  for (const Case& c : {Case{"version", "splinefig version", 2}, {"--version", "splinefig", 2}, {"--help", "splinefig", 2},
                        {"render --help", "splinefig", 2}, {"version --help", "splinefig", 2}, {"--help-man", "splinefig", 2},
                        {"--completion bash", "splinefig", 2}, {"--completion zsh", "splinefig", 2},
                        {"kernel --basis bspline", "splinefig kernel", 2}, {"kernel --basis bspline --report", "splinefig kernel", 2},
                        {"eval --basis bspline knots.csv", "splinefig eval", 2},
                        {"eval --basis bspline --spacing arclength --count 5 knots.csv", "splinefig eval", 2},
                        {"interp knots.csv", "splinefig interp", 2}, {"interp --output bezier knots.csv", "splinefig interp", 2},
                        {"render " + spec + " -o -", "splinefig render", 2}, {"render " + spec + " -o - --format svg", "splinefig render", 2},
                        {"resample " + png + " -o - --filter bspline --size 8x8", "splinefig resample", 2},
                        {"figures --out figs --only bias", "splinefig figures", 2},
                        {"diff " + png + " " + png, "splinefig diff", 4},
                        {"diff --json " + png + " " + png, "splinefig diff", 4}, {"diff -v " + png + " " + png, "splinefig diff", 4}})
    for (const std::string redirect : {">/dev/full", ">&-"}) {
      const int status = run_shell(dir, "", c.args, redirect);
      const std::string err = splinefig::test::slurp(dir / "err.txt");
      INFO(c.args << " " << redirect << ": " << err);
      REQUIRE(WIFEXITED(status));
      CHECK(WEXITSTATUS(status) == c.code);
      CHECK_THAT(err, Catch::StartsWith(c.who + ": cannot write to standard output ("));
      CHECK(splinefig::test::count_lines(err) == 1);
    }
}

// Numbers read as pixel counts or grid indices are checked before they are converted to int:
// a zoneplate crop of 3.4e10 (a fuzzer's input) converted out of range, which is undefined
// (UBSan: "outside the range of representable values of type 'int'"), and so did a cell of 1e10.
TEST_CASE("a zone plate crop or an axes cell past an int is refused naming the key") {
  const std::string zp = "[[axes]]\nbox = [0, 0, 100, 100]\n[[axes.zoneplate]]\nfilter = \"catmull-rom\"\nsize = 512\n";
  check_refused("crop_huge", zp + "crop = [0, 0, 3.43597e10, 1]\n",
                "crop_huge.toml:6: axes[0].zoneplate[0].crop: must be whole output pixels inside the 512x512 output");
  check_refused("crop_fraction", zp + "crop = [0.5, 0, 256, 256]\n",
                "crop_fraction.toml:6: axes[0].zoneplate[0].crop: must be whole output pixels inside the 512x512 output");
  check_refused("crop_outside", zp + "crop = [300, 0, 256, 256]\n",
                "crop_outside.toml:6: axes[0].zoneplate[0].crop: must lie inside the 512x512 output");
  check_refused("cell_huge", "[[axes]]\ncell = [1e10, 0]\n", "cell_huge.toml:2: axes[0].cell: expected [row, col], non-negative integers");
  check_refused("cell_fraction", "[[axes]]\ncell = [0, 0.5]\n",
                "cell_fraction.toml:2: axes[0].cell: expected [row, col], non-negative integers");
}
