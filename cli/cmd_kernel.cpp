// `splinefig kernel`: a kernel k(x) (a basis function, box, tent, lanczos3) as x,k(x) lines,
// its frequency response, or its filter analysis (kernel/analysis.hpp).
#include "command.hpp"
#include "csv.hpp"

#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/kernel.hpp>

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
};

constexpr double max_rows = 1e8;

// A number about to be printed, refused if it is not finite (the kernel overflows there).
double finite(double v, const std::string& basis, const char* what, double at) {
  if (!std::isfinite(v))
    throw Failure("--basis " + basis + ": " + what + cli::format_number(at) + " overflows the range of a double");
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
      throw Failure("--basis " + basis + ": the filter's " + name + " overflows the range of a double");
}

// x,f(x) lines for x_i = x0 + i*step (not accumulated), up to x1 allowing for the rounding of
// (x1-x0)/step; the flags as given are named in messages, and so is a value that is not finite
// (`what` names it: "k(x) at x = ").
template <class F>
int write_rows(const Options& o, double x0, double x1, double step, const char* what, F&& f) {
  if (!(step > 0)) throw Failure("--step: " + o.step + " must be positive");
  if (x1 < x0) throw Failure("--to " + o.to + " is less than --from " + o.from);
  const double span = (x1 - x0) / step;
  if (!(span < max_rows)) throw Failure("--step " + o.step + ": more than 1e8 rows from --from to --to");
  const long long rows = static_cast<long long>(std::floor(span * (1 + 1e-12) + 1e-9)) + 1;
  std::string text;
  text.reserve(static_cast<size_t>(rows) * 24);
  for (long long i = 0; i < rows; ++i) {
    const double x = x0 + static_cast<double>(i) * step;
    cli::append_number(text, x);
    text += ',';
    cli::append_number(text, finite(f(x), o.basis, what, x));
    text += '\n';
  }
  cli::write_stdout(text);
  return 0;
}

Kernel parse(const Options& o) {
  return cli::parse_spec_flag("--basis", o.basis, [](const std::string& s) { return parse_kernel(s); });
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
  const double f0 = o.range_given ? cli::parse_number(o.from, "--from") : 0.0;
  const double f1 = o.range_given ? cli::parse_number(o.to, "--to") : 2.0;
  const double step = o.range_given ? cli::parse_number(o.step, "--step") : 1.0 / 256;
  return write_rows(o, f0, f1, step, "|K(f)| at f = ", [&](double fr) { return response(f, fr); });
}

int run(const Options& o) {
  if (o.response || o.report) return run_filter(o);
  const Kernel k = parse(o);
  const double x0 = cli::parse_number(o.from, "--from");
  const double x1 = cli::parse_number(o.to, "--to");
  const double step = cli::parse_number(o.step, "--step");
  return write_rows(o, x0, x1, step, "k(x) at x = ", [&](double x) { return k(x); });
}

const splinefig::cli::Registration reg{
    "kernel", "Write a kernel k(x) (a basis function, box, tent, lanczos3) as x,k(x) lines", [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      app.add_option("--basis", o->basis,
                     "Basis spec NAME[:key=value,...] (see splinefig eval --help), or box, tent, lanczos3")
          ->required();
      app.add_option("--from", o->from, "First x (default -2)");
      app.add_option("--to", o->to, "Last x (default 2)");
      app.add_option("--step", o->step, "Step in x (default 1/64)");
      app.add_flag("--response", o->response,
                   "Write f,|K(f)| lines instead (f in cycles/sample; default 0 to 2 step 1/256, "
                   "or --from/--to/--step)");
      app.add_flag("--report", o->report,
                   "Print the filter's integral, continuity, droop, leakage, step response and "
                   "Mitchell-Netravali B,C");
      app.footer("k is the basis function: a curve is X(t) = sum_j x[j] k(t - j) (see docs/conventions.md).");
      return splinefig::cli::Runner([o, &app] {
        o->range_given = app.count("--from") + app.count("--to") + app.count("--step") > 0;
        return run(*o);
      });
    }};

}  // namespace
