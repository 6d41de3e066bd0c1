#pragma once
// Catmull-Rom splines with non-uniform knot spacing (the memo's "Knot Spacing"; Catmull and Rom
// 1974, Barry and Goldman 1988; Yuksel, Schaefer and Keyser 2011).
//
// Knot x_j gets the parameter tau_j, tau_0 = 0 and tau_{j+1} = tau_j + |x_{j+1} - x_j|^alpha:
//   alpha = 0    uniform (the memo's integer knots; the matrix C = C_0.5),
//   alpha = 1/2  centripetal,
//   alpha = 1    chordal (the memo's "proportional" spacing, [RIESEN]).
// The piece between x_i and x_{i+1} is the cubic that Barry and Goldman's pyramid of linear
// interpolations over tau_{i-1}..tau_{i+2} gives; in Hermite form it has the end velocities
//   X'(tau_i) = (x_i - x_{i-1})/(tau_i - tau_{i-1}) - (x_{i+1} - x_{i-1})/(tau_{i+1} - tau_{i-1})
//             + (x_{i+1} - x_i)/(tau_{i+1} - tau_i)
// (and the same one knot later). Centripetal pieces never have a cusp or a self-intersection.
//
// Coincident knots (zero distance) give a zero-length parameter interval when alpha > 0: a
// difference quotient 0/0 is read as 0, so a doubled end knot gives a zero end velocity and a
// doubled interior knot a piece that stays at the point (the memo's repeated knot).
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/points.hpp>

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace splinefig {

enum class KnotSpacing { uniform, chordal, centripetal };

double spacing_exponent(KnotSpacing s);                           // alpha: 0, 1, 0.5
std::optional<KnotSpacing> parse_knot_spacing(std::string_view);  // "uniform", "chordal", "centripetal"

// tau_0..tau_{n-1} for the knots (tau_0 = 0).
std::vector<double> knot_parameters(const Points& knots, double alpha);

// X(tau) (derivative 0) or dX/dtau, d2X/dtau2 on the piece between knots i and i+1
// (1 <= i <= n-3), at tau = tau_i + u (tau_{i+1} - tau_i), u in [0, 1]. A piece of zero
// parameter length is the constant x_i (its derivatives 0).
void spaced_catmull_rom(const Points& knots, const std::vector<double>& tau, std::size_t i, double u,
                        int derivative, std::span<double> out);

// The memo's open curve over the knots (n >= 4): pieces i = 1..n-3, each at
// u = 0, 1/grain, ..., (grain-1)/grain, and the final point: (n-3)*grain+1 points.
// Doubled or cyclic ends are made by extending the knot list first, as for the uniform bases.
Points spaced_catmull_rom_curve(const Points& knots, double alpha, int grain, int derivative = 0);

// The same for a Catmull-Rom curve from make_curve (its end mode already applied to the
// knots): as many points as sample(c, grain, derivative). Throws CurveError unless
// c's basis is Catmull-Rom (cardinal a = 0.5).
Points sample_spaced(const Curve& c, double alpha, int grain, int derivative = 0);

}  // namespace splinefig
