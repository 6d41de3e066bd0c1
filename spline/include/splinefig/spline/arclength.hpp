#pragma once
// Arc length of a curve and points evenly spaced along it (the memo, "On Using the Program").
//
// Two methods:
//   polygon   the memo's: sample at `grain`, take the polyline's cumulative chord length, mark
//             off equal lengths on it. Cheap; its error is the chord error, O(1/grain^2).
//   accurate  s(t) = integral of |X'(t)| dt per piece by adaptive Gauss-Kronrod (7/15 points).
//             Each piece is first split where the speed has a local minimum (a sign change of
//             X'.X'' from - to +), so a cusp, where the speed vanishes and |X'| has a kink,
//             falls on an interval end; the adaptive bisection then resolves the sharp bend of
//             the speed near an almost-cusp. The inverse t(s) is Newton's method on
//             s(t) - target with bisection as the safeguard (always inside a bracket; bisect
//             whenever the step leaves it or the speed is zero).
// Accuracy reached (tests/spline/arclength.cpp, against a brute-force polyline of 2^20+
// points with Richardson extrapolation): spacing errors below 1e-12 of the total length,
// cusps included; the target is 1e-9.
#include <splinefig/spline/curve.hpp>

#include <cstddef>
#include <vector>

namespace splinefig {

// The accurate arc-length function of a curve: breakpoints t[k] (increasing, t[0] = 0,
// t.back() = segments(); every piece end is one) where the length s[k] from t = 0 is known to
// full precision, and between which a single 15-point Kronrod rule is accurate.
struct ArcLength {
  std::vector<double> t;
  std::vector<double> s;
  double total() const { return s.empty() ? 0.0 : s.back(); }
};

// Builds the table; `tolerance` is relative to the curve's length. The work is bounded for any
// curve (at most 2^20 intervals); throws std::overflow_error when the length is beyond the
// range of a double (a knot at 1e155 squares to infinity).
ArcLength arc_length(const Curve& c, double tolerance = 1e-13);

// s(t): the length from 0 to t (t clamped to [0, segments()]).
double length_at(const Curve& c, const ArcLength& a, double t);

// t(s): the parameter where the length from 0 reaches s (s clamped to [0, total()]).
double parameter_at_length(const Curve& c, const ArcLength& a, double s);

// `count` (>= 2) parameters whose lengths are k*total/(count-1): first 0, last segments().
// A curve of zero length gets parameters evenly spaced in t.
std::vector<double> evenly_spaced_parameters(const Curve& c, std::size_t count);

// The memo's polygon method: parameters of `count` points equally spaced along the polyline
// through sample(c, grain), each found on its chord and mapped back linearly in t.
std::vector<double> polygon_evenly_spaced_parameters(const Curve& c, int grain, std::size_t count);
// The length of the polyline through sample(c, grain).
double polygon_length(const Curve& c, int grain);

// X (or its derivative) at each parameter, into a Points of c.dim(); for a closed curve and
// derivative 0 a parameter equal to segments() gives exactly the first point.
Points evaluate_at(const Curve& c, const std::vector<double>& t, int derivative = 0);

}  // namespace splinefig
