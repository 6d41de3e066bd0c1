// Spec limits and ranges: every quantity that drives a loop or an allocation is refused with a
// one-line "FILE:LINE: KEY: ..." before any work, and data that cannot be mapped to pixels are
// errors naming their element, never undefined behaviour or a silently missing element.
#include "hostile.hpp"

using namespace splinefig::hostile;

namespace {
const std::string kBox = "[axes]\nx_range = [0, 10]\ny_range = [0, 10]\n";
}

TEST_CASE("text and title sizes over 4096 px are refused by the loader, and after --scale") {
  check_refused("big_text", "[[text]]\nat = [10, 10]\ntext = \"hi\"\nsize = 1e6\n",
                "big_text.toml:4: text[0].size: font size 1e+06 is over the limit of 4096 px");
  check_refused("big_title", "title = \"hi\"\ntitle_size = 70000\n",
                "big_title.toml:2: title_size: font size over the limit of 4096 px");
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
