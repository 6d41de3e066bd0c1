// splinefig interp: the cubic spline through data points S_0..S_n (seed 003 §5, §9).
// Reads the data (a file or stdin); writes the curve, its B-spline control points or its Bezier pieces.
#include "command.hpp"
#include "number_flags.hpp"
#include "points_io.hpp"
#include "stdio.hpp"

#include <splinefig/spline/interp.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

namespace splinefig::cli {
namespace {

// Output is built in memory before it is written; keep it to a sane size.
constexpr double max_output_points = 1e8;

struct Options {
  std::string ends = "relaxed";
  std::string start_velocity, end_velocity;
  std::string grain = "16";
  std::string output = "curve";
  std::string input, delimiter = "comma";
  bool grain_given = false;
};

std::vector<double> velocity(const std::string& text, const char* flag, int dim) {
  if (text.empty()) return std::vector<double>(static_cast<std::size_t>(dim), 0.0);
  std::vector<double> v = parse_vector(text, flag);
  if (static_cast<int>(v.size()) != dim)
    throw Failure(std::string(flag) + ": " + std::to_string(v.size()) + (v.size() == 1 ? " coordinate" : " coordinates") +
                  " given, but the data points have " + std::to_string(dim));
  return v;
}

// The spline is linear in its data, so a result that is not finite (from finite data) means
// the 1-4-1 solve or the curve overflowed: name the data point (or end velocity) of largest
// magnitude, the one that drives it out of range.
void check_finite(bool finite, const std::string& source, const Points& data, const std::vector<double>& v, const std::vector<double>& w) {
  if (finite) return;
  std::size_t at = 0;
  double big = -1;
  for (std::size_t k = 0; k < data.coords.size(); ++k)
    if (std::abs(data.coords[k]) > big) big = std::abs(data.coords[k]), at = k;
  std::string what = "data point " + std::to_string(at / static_cast<std::size_t>(data.dim) + 1);
  for (const auto& [vel, flag] : {std::pair{&v, "--start-velocity"}, std::pair{&w, "--end-velocity"}})
    for (const double x : *vel)
      if (std::abs(x) > big) big = std::abs(x), what = flag;
  throw Failure(source + ": the spline overflows the range of a double: " + what + " (a coordinate " + format_number(big) +
                ") is too large to interpolate");
}

int run(const Options& o) {
  if (o.ends != "relaxed" && o.ends != "clamped" && o.ends != "periodic")
    throw Failure("--ends: unknown value '" + o.ends + "' (known: relaxed, clamped, periodic)");
  if (o.output != "curve" && o.output != "bspline" && o.output != "bezier")
    throw Failure("--output: unknown value '" + o.output + "' (known: curve, bspline, bezier)");
  if (o.grain_given && o.output != "curve") throw Failure("--grain applies only to --output curve");
  if (o.ends != "clamped") {
    if (!o.start_velocity.empty()) throw Failure("--start-velocity applies only to --ends clamped");
    if (!o.end_velocity.empty()) throw Failure("--end-velocity applies only to --ends clamped");
  }
  const int grain = static_cast<int>(parse_integer(o.grain, "--grain", 1, 1000000));

  const CsvOptions csv = csv_options(o.delimiter);
  const std::string source = input_name(o.input);
  const Points data = read_input(o.input, csv);
  const std::size_t need = o.ends == "periodic" ? 3 : 2;
  if (data.size() < need)
    throw Failure(source + ": " + std::to_string(data.size()) + (data.size() == 1 ? " data point" : " data points") +
                  ", --ends " + o.ends + " needs at least " + std::to_string(need));
  Interpolant s;
  std::vector<double> v, w;  // clamped end velocities
  if (o.ends == "relaxed") {
    s = interpolate_relaxed(data);
  } else if (o.ends == "clamped") {
    v = velocity(o.start_velocity, "--start-velocity", data.dim);
    w = velocity(o.end_velocity, "--end-velocity", data.dim);
    s = interpolate_clamped(data, v, w);
  } else {
    const std::size_t n = data.size() - 1;
    for (int c = 0; c < data.dim; ++c)
      if (data[0][static_cast<std::size_t>(c)] != data[n][static_cast<std::size_t>(c)])
        throw Failure(source + ": --ends periodic needs the last data point to repeat the first (point " +
                      std::to_string(n + 1) + " differs from point 1)");
    s = interpolate_periodic(data);
  }

  std::string out;
  if (o.output == "bspline") {
    std::size_t non_finite = 0;
    out = format_points(s.control, non_finite);
    check_finite(non_finite == s.control.coords.size(), source, data, v, w);
  } else if (o.output == "bezier") {
    const BezierSpline b = bezier_pieces(s);
    check_finite(first_non_finite(b.points.coords) == b.points.coords.size(), source, data, v, w);
    const std::size_t dim = static_cast<std::size_t>(b.points.dim);
    out.reserve(b.pieces() * 4 * dim * 24);
    for (std::size_t i = 0; i < b.pieces(); ++i) {
      const std::span<const double> piece(b.points.coords.data() + 3 * i * dim, 4 * dim);
      append_point(out, piece);
    }
  } else {
    const double rows = static_cast<double>(s.pieces()) * grain + 1;
    if (rows > max_output_points)
      throw Failure("--grain " + std::to_string(grain) + " with " + std::to_string(data.size()) +
                    " data points would write " + std::to_string(static_cast<long long>(rows)) +
                    " points (at most 100000000)");
    const Points curve = sample(s, grain);
    std::size_t non_finite = 0;
    out = format_points(curve, non_finite);
    check_finite(non_finite == curve.coords.size(), source, data, v, w);
  }
  write_stdout(out);
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_input(app, o->input, o->delimiter, "Data points S_0..S_n");
  choices(app.add_option("--ends", o->ends, "relaxed (P''=0 at the ends), clamped (given end velocities) or periodic")
              ->type_name("NAME")
              ->capture_default_str(),
          {"relaxed", "clamped", "periodic"});
  app.add_option("--start-velocity", o->start_velocity, "clamped: P'(0) as comma-separated coordinates (0 when not given)")
      ->type_name("FLOAT,...");
  app.add_option("--end-velocity", o->end_velocity, "clamped: P'(n) as comma-separated coordinates (0 when not given)")
      ->type_name("FLOAT,...");
  app.add_option("--grain", o->grain, "points per piece for --output curve (>= 1)")->type_name("INT")->capture_default_str();
  choices(app.add_option("--output", o->output,
                         "curve (P(t) at t = 0, 1/grain, ..., n), bspline (B_0..B_n) or bezier (4 points per piece per line)")
              ->type_name("NAME")
              ->capture_default_str(),
          {"curve", "bspline", "bezier"});
  app.footer(
      "Reads data points S_0..S_n (one per line, any dimension; see --delimiter) and fits the "
      "cubic spline P(t), t in [0, n], with P(i) = S_i through the B-spline 1-4-1 system. relaxed and "
      "clamped need at least 2 points, periodic at least 3 with the last equal to the first.\n\n"
      "Example: printf '0,0\\n1,2\\n3,1\\n' | splinefig interp --output bezier");
  return [o, &app] {
    o->grain_given = app.count("--grain") > 0;
    return run(*o);
  };
}

const Registration reg{"interp", "Interpolating cubic spline through data points (relaxed, clamped, periodic)",
                       setup};

}  // namespace
}  // namespace splinefig::cli
