// `splinefig eval`: knots (CSV from a file or stdin) -> points on the curve on stdout (docs/cli.md).
#include "command.hpp"
#include "number_flags.hpp"
#include "points_io.hpp"
#include "stdio.hpp"

#include <splinefig/spline/arclength.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/knot_spacing.hpp>
#include <splinefig/spline/local_beta.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <vector>

namespace {

using namespace splinefig;
using splinefig::cli::Failure;

struct Options {
  std::string basis, grain = "16", ends = "open", derivative = "0", spacing = "parameter", count;
  std::string knot_spacing = "uniform", betas;  // docs/companion.md
  std::string input, delimiter = "comma";
  std::string source = "stdin";  // the input's name in errors
};

// --knot-spacing and --betas (docs/companion.md): the curve's pieces from the spline library's
// spaced Catmull-Rom or continuously shaped Beta-spline instead of the uniform matrix.
Points sample_companion(const Options& o, const Curve& c, int grain, int derivative) {
  try {
    if (o.betas.empty())
      return sample_spaced(c, spacing_exponent(*parse_knot_spacing(o.knot_spacing)), grain, derivative);
    cli::check_input_file(o.betas, "--betas");
    std::ifstream in(o.betas);
    if (!in) throw Failure("--betas: cannot open '" + o.betas + "'", splinefig::ErrorKind::unreadable);
    const Points b = cli::read_points(in, o.betas);
    if (b.dim != 2) throw Failure(o.betas + ": " + std::to_string(b.dim) + " values per line, expected b1,b2");
    std::vector<ShapeParameters> betas;
    for (std::size_t i = 0; i < b.size(); ++i) betas.push_back({b[i][0], b[i][1]});
    return sample_local_betas(c, betas, grain, derivative);
  } catch (const std::invalid_argument& e) {
    throw Failure((o.betas.empty() ? std::string("--knot-spacing: ") : o.betas + ": ") + e.what());
  }
}

// Output above this many numbers (about 1.5 GB of text) is refused rather than exhausting memory.
constexpr long long max_numbers = 1LL << 26;

void check_size(long double points, int dim, const std::string& flag) {
  if (points * dim > max_numbers)
    throw Failure(flag + ": " + std::to_string(static_cast<long long>(points)) + " points of dimension " +
                  std::to_string(dim) + " would be more than " + std::to_string(max_numbers) + " numbers");
}

// The input knots (numbered from 1 as read) that piece p of c uses: "knots 2..5", or a list
// where a closed curve wraps around ("knots 5, 1, 2, 3").
std::string piece_knots(const Curve& c, std::size_t p) {
  const std::size_t n = c.knot_count, h = static_cast<std::size_t>(c.degree() - 1) / 2;
  std::vector<std::size_t> ks;
  for (std::size_t j = p; j <= p + static_cast<std::size_t>(c.degree()); ++j) {
    std::size_t k = j;  // the control point's knot, 0-based
    if (c.ends == Ends::doubled) k = j == 0 ? 0 : std::min(j - 1, n - 1);
    if (c.ends == Ends::closed) k = (j + n * (h + 1) - h) % n;
    if (ks.empty() || ks.back() != k + 1) ks.push_back(k + 1);
  }
  bool run = true;
  for (std::size_t i = 1; i < ks.size(); ++i) run = run && ks[i] == ks[i - 1] + 1;
  if (run) return ks.size() == 1 ? "knot " + std::to_string(ks[0]) : "knots " + std::to_string(ks.front()) + ".." + std::to_string(ks.back());
  std::string s = "knots ";
  for (std::size_t i = 0; i < ks.size(); ++i) s += (i ? ", " : "") + std::to_string(ks[i]);
  return s;
}

// Before measuring length: bounds on |X|, |X'| and |X''| of every piece, from its Horner
// coefficients, whose squares must stay in range (beyond it the length integral and the
// polygon's chords overflow). Names the piece's knots otherwise.
void check_measurable(const Curve& c, const std::string& spacing, const std::string& source) {
  const int n = c.degree();
  const std::size_t dim = static_cast<std::size_t>(c.dim());
  std::vector<double> a(static_cast<std::size_t>(n + 1) * dim);
  for (std::size_t p = 0; p < c.segments(); ++p) {
    piece_coefficients(c, p, a);
    double sum = 0;
    for (std::size_t d = 0; d < dim; ++d) {
      double x = 0, v = 0, acc = 0;
      for (int r = 0; r <= n; ++r) {
        const double m = std::abs(a[static_cast<std::size_t>(r) * dim + d]), e = n - r;
        x += m, v += e * m, acc += e * (e - 1) * m;
      }
      const double bound = std::max({2 * x, v, acc});
      sum += bound * bound;
    }
    if (!std::isfinite(sum))
      throw Failure(source + ": " + piece_knots(c, p) + " are too large for --spacing " + spacing +
                    ": the curve's length there overflows the range of a double");
  }
}

// No non-finite number is printed: the first one (coords[k]) names the knots of its piece and
// the basis.
void check_finite(const Points& out, std::size_t k, const Curve& c, const Options& o, int derivative, int grain,
                  const std::vector<double>& ts) {
  if (k == out.coords.size()) return;
  const std::size_t row = k / static_cast<std::size_t>(out.dim);
  double t = 0;
  std::size_t piece = 0;
  if (!ts.empty()) {
    t = ts[row];
    piece = locate(c, t).piece;
  } else {
    piece = std::min(row / static_cast<std::size_t>(grain), c.segments() - 1);
    t = static_cast<double>(row) / grain;
  }
  const char* what = derivative == 0 ? "the curve" : derivative == 1 ? "its first derivative" : "its second derivative";
  throw Failure(o.source + ": " + piece_knots(c, piece) + " with --basis " + o.basis +
                (o.betas.empty() ? "" : " and --betas " + o.betas) + ": " + what +
                " overflows the range of a double at t = " + cli::format_number(t));
}

int run(Options o) {
  const Basis b = cli::parse_spec_flag("--basis", o.basis, [](const std::string& s) { return parse_basis(s); });
  const int grain = static_cast<int>(cli::parse_integer(o.grain, "--grain", 1, 1 << 24));
  const int derivative = static_cast<int>(cli::parse_integer(o.derivative, "--derivative", 0, 2));
  Ends ends;
  try {
    ends = parse_ends(o.ends);
  } catch (const std::invalid_argument& e) {
    throw Failure(std::string("--ends: ") + e.what());
  }
  if (o.spacing != "parameter" && o.spacing != "arclength" && o.spacing != "polygon")
    throw Failure("--spacing: unknown spacing '" + o.spacing + "' (known: parameter, arclength, polygon)");
  const bool by_length = o.spacing != "parameter";
  if (by_length && o.count.empty()) throw Failure("--spacing " + o.spacing + " needs --count N");
  if (!by_length && !o.count.empty()) throw Failure("--count needs --spacing arclength (or polygon)");
  const long long count = by_length ? cli::parse_integer(o.count, "--count", 2, max_numbers) : 0;
  if (!parse_knot_spacing(o.knot_spacing))
    throw Failure("--knot-spacing: unknown spacing '" + o.knot_spacing + "' (known: uniform, chordal, centripetal)");
  const bool companion = o.knot_spacing != "uniform" || !o.betas.empty();
  if (companion && by_length) throw Failure("--knot-spacing and --betas need --spacing parameter");
  if (o.knot_spacing != "uniform" && !o.betas.empty()) throw Failure("--betas cannot be combined with --knot-spacing");
  if (!o.betas.empty() && b.family != "beta") throw Failure("--betas needs --basis beta, not " + b.spec);

  const CsvOptions csv = cli::csv_options(o.delimiter);
  o.source = cli::input_name(o.input);
  const Points knots = cli::read_input(o.input, csv);
  Curve c;
  try {
    c = make_curve(b, knots, ends);
  } catch (const CurveError& e) {
    throw Failure(o.source + ": " + e.what());
  }

  const long double sampled = static_cast<long double>(c.segments()) * grain + 1;
  Points out;
  std::vector<double> ts;  // the parameters of the rows, where not grain per piece
  if (o.spacing == "arclength") {
    check_size(count, c.dim(), "--count " + o.count);
    check_measurable(c, o.spacing, o.source);
    ts = evenly_spaced_parameters(c, static_cast<std::size_t>(count));
  } else if (o.spacing == "polygon") {
    check_size(count, c.dim(), "--count " + o.count);
    check_size(sampled, c.dim(), "--grain " + o.grain);
    check_measurable(c, o.spacing, o.source);
    ts = polygon_evenly_spaced_parameters(c, grain, static_cast<std::size_t>(count));
  } else {
    check_size(sampled, c.dim(), "--grain " + o.grain);
    out = companion ? sample_companion(o, c, grain, derivative) : sample(c, grain, derivative);
  }
  if (!ts.empty()) out = evaluate_at(c, ts, derivative);
  std::size_t non_finite = 0;
  const std::string text = cli::format_points(out, non_finite);
  check_finite(out, non_finite, c, o, derivative, grain, ts);
  cli::write_stdout(text);
  return 0;
}

const splinefig::cli::Registration reg{
    "eval", "Evaluate a spline through knots (CSV from a file or stdin), points on stdout", [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      cli::add_input(app, o->input, o->delimiter, "Knots");
      app.add_option("--basis", o->basis, std::string("Basis spec NAME[:key=value,...]: ") + cli::basis_specs)
          ->type_name("SPEC")
          ->required();
      app.add_option("--grain", o->grain, "Points per piece")->type_name("INT")->capture_default_str();
      cli::choices(app.add_option("--ends", o->ends,
                                  "open (the memo's: n knots give (n-3)*grain+1 points), double (first and last knot "
                                  "doubled), closed (cyclic: n*grain+1 points, last = first)")
                       ->type_name("NAME")
                       ->capture_default_str(),
                   {"open", "double", "closed"});
      cli::choices(app.add_option("--derivative", o->derivative, "0: X(t), 1: dX/dt, 2: d2X/dt2")
                       ->type_name("INT")
                       ->capture_default_str(),
                   {"0", "1", "2"});
      cli::choices(app.add_option("--spacing", o->spacing,
                                  "parameter (grain points per piece), arclength (--count points evenly "
                                  "spaced along the curve), polygon (the same by the memo's polyline method)")
                       ->type_name("NAME")
                       ->capture_default_str(),
                   {"parameter", "arclength", "polygon"});
      app.add_option("--count", o->count, "Number of points for --spacing arclength|polygon (>= 2)")->type_name("INT");
      cli::choices(app.add_option("--knot-spacing", o->knot_spacing,
                                  "catmull-rom only: uniform, chordal or centripetal knot parameters; "
                                  "--derivative is then d/dtau of the spaced parameter")
                       ->type_name("NAME")
                       ->capture_default_str(),
                   {"uniform", "chordal", "centripetal"});
      app.add_option("--betas", o->betas,
                     "beta only: CSV file of b1,b2 per knot (bias, tension), blended along each piece "
                     "(continuously shaped Beta-spline, G2)")
          ->type_name("PATH");
      app.footer(
          "Knots: one per line, coordinates split by --delimiter (any dimension, the same on every line); "
          "blank lines and lines starting with # are ignored, and so is a first line of names (x,y). "
          "Output numbers read back to the same double.\n\n"
          "Example: printf 'x,y\\n0,0\\n1,2\\n3,1\\n4,3\\n' | splinefig eval --basis catmull-rom --grain 4");
      return splinefig::cli::Runner([o, &app] {
        if (app.count("--grain") && o->spacing == "arclength")
          throw Failure("--grain has no effect with --spacing arclength (its rows are the --count points)");
        return run(*o);
      });
    }};

}  // namespace
