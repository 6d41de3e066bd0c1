#pragma once
// A spline curve through (or near) knots: a basis, the knots, and what happens at the ends.
//
// End modes (the memo's "Knot Spacing" section):
//   open     the knots are used as given. A cubic piece needs four knots, and the first and
//            last knot only steer the ends: n knots give n-3 pieces, from x[1]..x[2] to
//            x[n-3]..x[n-2]. For degree d, n knots give n-d pieces.
//   doubled  the first and last knot get multiplicity 2 before the open rule applies
//            (n knots give n+2-d pieces; the CLI calls it `double`).
//   closed   the cyclic spline: the memo appends the last knot before the first and the first
//            two after the last; for degree d the knot list is wrapped by h = (d-1)/2 knots in
//            front and d-h behind, so n knots give n pieces and the curve returns to its start.
// Repeated knots (multiplicity > 1) are simply repeated entries of the knot list.
//
// Parameter: t in [0, segments()], t = i + u runs piece i (u in [0,1]) over control points
// control[i .. i+degree]. In the kernel convention of basis.hpp, X(t) = sum_j x[j] k(t + h - j)
// with x the control list, h = (degree-1)/2.
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/points.hpp>

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string_view>

namespace splinefig {

enum class Ends { open, doubled, closed };

// "open", "double" (or "doubled"), "closed"; throws SpecError naming the value.
Ends parse_ends(std::string_view s);
const char* to_string(Ends e);

// A curve, interpolation or sampling that cannot be made from what it is given: too few knots
// or data points (or none, or mixed dimensions), a grain or count out of range, knots out of
// order, parameters that coincide or overflow. Every spline function but the spec parsers
// (SpecError) throws it.
struct CurveError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

struct Curve {
  Basis basis;
  Ends ends = Ends::open;
  std::size_t knot_count = 0;  // the knots as given
  Points control;              // the knots after the end mode: piece i uses control[i..i+degree]

  int dim() const { return control.dim; }
  int degree() const { return basis.degree; }
  std::size_t segments() const { return control.size() - static_cast<std::size_t>(basis.degree); }
  // The degree+1 control points of piece i, flat.
  std::span<const double> piece_control(std::size_t i) const {
    const std::size_t d = static_cast<std::size_t>(control.dim);
    return {control.coords.data() + i * d, static_cast<std::size_t>(basis.order()) * d};
  }
};

// The fewest knots an end mode accepts for a basis: open d+1, doubled d-1 (at least 2),
// closed 3.
std::size_t min_knots(const Basis& b, Ends ends);

// Builds the curve; throws CurveError when there are too few knots for one piece.
Curve make_curve(const Basis& b, const Points& knots, Ends ends);

// The piece index and local u for parameter t (clamped to [0, segments()]); t = segments()
// is u = 1 of the last piece.
struct PieceParameter {
  std::size_t piece;
  double u;
};
PieceParameter locate(const Curve& c, double t);

// Horner coefficients of piece i (segment.hpp), into a of (degree+1)*dim doubles.
void piece_coefficients(const Curve& c, std::size_t i, std::span<double> a);

// X(t), dX/dt or d2X/dt2 (derivative 0, 1, 2) at t, into out[0..dim).
void evaluate(const Curve& c, double t, int derivative, std::span<double> out);

// The memo's routine done right: `grain` points per piece at u = 0, 1/grain, ...,
// (grain-1)/grain, then the final point u = 1 of the last piece: segments()*grain + 1
// points. For a closed curve the last point is the first one repeated (derivative 0).
// Throws CurveError if grain < 1 or the count overflows.
Points sample(const Curve& c, int grain, int derivative = 0);

// sample() into caller storage of exactly sample_count(c, grain) * dim doubles.
std::size_t sample_count(const Curve& c, int grain);
void sample_into(const Curve& c, int grain, int derivative, std::span<double> out);

}  // namespace splinefig
