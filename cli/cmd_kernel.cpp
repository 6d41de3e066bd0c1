// `splinefig kernel`: a kernel k(x) (a basis function, box, tent, lanczos3) as x,k(x) lines,
// its frequency response, or its filter analysis (kernel/analysis.hpp).
#include "command.hpp"
#include "number_flags.hpp"
#include "points_io.hpp"
#include "stdio.hpp"

#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <string>
#include <utility>

namespace {

using namespace splinefig;
using splinefig::cli::Failure;

struct Options {
  std::string basis, from = "-2", to = "2", step = "0.015625";
  bool response = false, report = false;  // filter analysis (kernel/analysis.hpp)
  bool range_given = false;               // --from/--to/--step given: they apply to f too
  std::string input, delimiter = "comma";  // x (or f) values to evaluate at, instead of a range
  bool input_given = false;
};

constexpr double max_rows = 1e8;

// The basis spec as a message repeats it: whole when short, else excerpt()'s 40 bytes.
std::string shown(const std::string& basis) { return basis.size() <= 40 ? basis : excerpt(basis); }

// A number about to be printed, refused if it is not finite (the kernel overflows there).
double finite(double v, const std::string& basis, const char* what, double at) {
  if (!std::isfinite(v))
    throw Failure("--basis " + shown(basis) + ": " + what + cli::format_number(at) + " overflows the range of a double");
  return v;
}

// --report: every measure must be finite to be printed.
void check_report(const FilterReport& r, const std::string& basis) {
  const std::pair<const char*, double> measures[] = {
      {"integral", r.integral}, {"energy", r.energy}, {"response_at_0", r.response_at_0},
      {"response_at_0.25", r.response_at_quarter}, {"response_at_nyquist", r.response_at_nyquist},
      {"passband_droop_at_0.25", r.droop}, {"stopband_leakage", r.leakage}, {"step_overshoot", r.step.overshoot},
      {"step_undershoot", r.step.undershoot}, {"step_rise_10_90", r.step.rise},
      {"mitchell_netravali B", r.bc ? r.bc->b : 0.0}, {"mitchell_netravali C", r.bc ? r.bc->c : 0.0}};
  for (const auto& [name, v] : measures)
    if (!std::isfinite(v))
      throw Failure("--basis " + shown(basis) + ": the filter's " + name + " overflows the range of a double");
}

// One line "x,f(x)"; a value that is not finite is an error (`what` names it: "k(x) at x = ").
template <class F>
void append_row(std::string& text, double x, const Options& o, const char* what, F& f) {
  cli::append_number(text, x);
  text += ',';
  cli::append_number(text, finite(f(x), o.basis, what, x));
  text += '\n';
}

// x,f(x) lines for x_i = x0 + i*step (not accumulated), up to x1 allowing for the rounding of
// (x1-x0)/step; the flags as given are named in messages, and so is a value that is not finite
// (`what` names it: "k(x) at x = ").
template <class F>
int write_rows(const Options& o, double x0, double x1, double step, const char* what, F&& f) {
  if (!(step > 0)) throw Failure("--step: " + o.step + " must be positive");
  if (x1 < x0) throw Failure("--to " + o.to + " is less than --from " + o.from);
  // Near the ends of the doubles x1 - x0 and i * step can overflow where the rows cannot
  // (--from -1.7e308 --to 1.7e308 --step 1.7e308 is 3 rows): then both are taken halved, which
  // is exact for numbers this large.
  const bool halve = !std::isfinite(x1 - x0) || !std::isfinite(step * max_rows);
  const double span = halve ? (x1 / 2 - x0 / 2) / (step / 2) : (x1 - x0) / step;
  if (!(span < max_rows)) throw Failure("--step " + o.step + ": more than 1e8 rows from --from to --to");
  const long long rows = static_cast<long long>(std::floor(span * (1 + 1e-12) + 1e-9)) + 1;
  std::string text;
  text.reserve(static_cast<size_t>(rows) * 24);
  for (long long i = 0; i < rows; ++i) {
    const double n = static_cast<double>(i);
    append_row(text, halve ? 2 * (x0 / 2 + n * (step / 2)) : x0 + n * step, o, what, f);
  }
  cli::write_stdout(text);
  return 0;
}

Kernel parse(const Options& o) {
  return cli::parse_spec_flag("--basis", o.basis, [](const std::string& s) { return parse_kernel(s); });
}

// x,f(x) lines for the values of the input file (one per line); `what` as for write_rows.
template <class F>
int write_input_rows(const Options& o, const char* what, F&& f) {
  if (o.range_given) throw Failure("--from, --to and --step cannot be combined with an input file of values");
  const Points xs = cli::read_input(o.input, cli::csv_options(o.delimiter));
  if (xs.dim > 1)
    throw Failure(cli::input_name(o.input) + ": " + std::to_string(xs.dim) + " values per line, expected one (x)");
  std::string text;
  text.reserve(xs.size() * 24);
  for (std::size_t i = 0; i < xs.size(); ++i) append_row(text, xs[i][0], o, what, f);
  cli::write_stdout(text);
  return 0;
}

// --report: the filter's numbers; --response: f,|K(f)| lines (f in cycles per sample, by default
// 0 to 2 in steps of 1/256). Any basis spec or box, tent, lanczos3.
int run_filter(const Options& o) {
  const Kernel f = parse(o);
  if (o.report) {
    const FilterReport r = analyse(f);
    check_report(r, o.basis);
    cli::write_stdout(report_text(r));
    return 0;
  }
  if (o.input_given) return write_input_rows(o, "|K(f)| at f = ", [&](double fr) { return response(f, fr); });
  const double f0 = o.range_given ? cli::parse_number(o.from, "--from") : 0.0;
  const double f1 = o.range_given ? cli::parse_number(o.to, "--to") : 2.0;
  const double step = o.range_given ? cli::parse_number(o.step, "--step") : 1.0 / 256;
  return write_rows(o, f0, f1, step, "|K(f)| at f = ", [&](double fr) { return response(f, fr); });
}

int run(const Options& o) {
  if (o.response || o.report) return run_filter(o);
  const Kernel k = parse(o);
  if (o.input_given) return write_input_rows(o, "k(x) at x = ", [&](double x) { return k(x); });
  const double x0 = cli::parse_number(o.from, "--from");
  const double x1 = cli::parse_number(o.to, "--to");
  const double step = cli::parse_number(o.step, "--step");
  return write_rows(o, x0, x1, step, "k(x) at x = ", [&](double x) { return k(x); });
}

const splinefig::cli::Registration reg{
    "kernel", "Write a kernel k(x) (a basis function, box, tent, lanczos3) as x,k(x) lines", [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      app.add_option("INPUT", o->input,
                     "Values to evaluate at instead of --from/--to/--step: a CSV file of one x (or f) "
                     "per line, or - for stdin; a first line of names is skipped")
          ->type_name("PATH");
      splinefig::cli::choices(app.add_option("--delimiter", o->delimiter, "Input delimiter: comma, semicolon, tab or space")
                                  ->type_name("NAME")
                                  ->capture_default_str(),
                              {"comma", "semicolon", "tab", "space"});
      app.add_option("--basis", o->basis,
                     "Basis spec NAME[:key=value,...] (see splinefig eval --help), or box, tent, lanczos3")
          ->type_name("SPEC")
          ->required();
      app.add_option("--from", o->from, "First x (or f with --response, default 0)")->type_name("FLOAT")->capture_default_str();
      app.add_option("--to", o->to, "Last x (or f with --response, default 2)")->type_name("FLOAT")->capture_default_str();
      app.add_option("--step", o->step, "Step in x (or f with --response, default 1/256)")
          ->type_name("FLOAT")
          ->capture_default_str();
      app.add_flag("--response", o->response,
                   "Write f,|K(f)| lines instead (f in cycles/sample from --from to --to by --step)");
      app.add_flag("--report", o->report,
                   "Print the filter's integral, continuity, droop, leakage, step response and "
                   "Mitchell-Netravali B,C");
      app.footer(
          "k is the basis function: a curve is X(t) = sum_j x[j] k(t - j) (see docs/conventions.md).\n\n"
          "Example: splinefig kernel --basis lanczos3 --from -3 --to 3 --step 0.5");
      return splinefig::cli::Runner([o, &app] {
        o->range_given = app.count("--from") + app.count("--to") + app.count("--step") > 0;
        o->input_given = app.count("INPUT") > 0;
        if (o->report && o->input_given) throw Failure("--report takes no input file");
        // A flag that would change nothing is refused rather than ignored.
        if (o->report && o->response)
          throw Failure("--report and --response cannot be combined (--report prints the filter's numbers, "
                        "--response its f,|K(f)| lines)");
        if (o->report && o->range_given)
          throw Failure("--report takes no --from, --to or --step (it reports on the whole filter)");
        if (app.count("--delimiter") && !o->input_given)
          throw Failure("--delimiter applies only to an INPUT file of values");
        return run(*o);
      });
    }};

}  // namespace
