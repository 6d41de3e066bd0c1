#pragma once
// Continuously shaped Beta-splines: bias b1 and tension b2 given per knot (Barsky and Beatty,
// "Local Control of Bias and Tension in Beta-splines", SIGGRAPH 83; the memo's "The Future").
//
// The piece between knots x_i and x_{i+1} (u in [0,1], control points x_{i-1}..x_{i+2}, the
// memo's segment convention) is the uniform Beta-spline piece with the shape parameters
// replaced by functions of u that blend the values at its two knots:
//   b(u) = b_i + (b_{i+1} - b_i) h(u),   h(u) = 10u^3 - 15u^4 + 6u^5,
//   X(u) = [u^3 u^2 u 1] B_{b1(u), b2(u)} [x_{i-1} x_i x_{i+1} x_{i+2}]^T.
// h is the quintic Hermite blend with h(0) = 0, h(1) = 1 and h', h'' zero at both ends, so at
// every joint the curve's position and first two u-derivatives are those of the uniformly shaped
// Beta-spline with that knot's (b1, b2): the Beta-constraints hold there and the curve is G2
// (unit tangent and curvature vector continuous). With equal values everywhere it is the
// uniform Beta-spline. The pieces are polynomials of degree 3 only when the values are equal.
//
// Valid shape parameters keep B's denominator d = b2 + 2b1^3 + 4b1^2 + 4b1 + 2 away from 0
// along every piece; we require min(b2) + d_1(min(b1)) > 0 over each piece's two knots (d_1
// increasing in b1), which Barsky's range b1 > 0, b2 >= 0 always meets, and which also admits
// the moderate negative tension of the memo's example.
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/points.hpp>

#include <span>
#include <vector>

namespace splinefig {

struct ShapeParameters {
  double b1 = 1;  // bias
  double b2 = 0;  // tension
};

// Throws CurveError naming the knots of the first piece whose parameters can make d
// vanish, or a count mismatch (one ShapeParameters per knot).
void validate_local_betas(const Points& knots, std::span<const ShapeParameters> betas);

// The blend h(u) and its first two derivatives.
double quintic_blend(double u, int derivative = 0);

// X(u) or dX/du, d2X/du2 on the piece between knots i and i+1 (1 <= i <= n-3).
void local_beta_point(const Points& knots, std::span<const ShapeParameters> betas, std::size_t i, double u,
                      int derivative, std::span<double> out);

// The memo's open curve (n >= 4 knots): pieces 1..n-3 at u = j/grain, and the final point.
Points local_beta_curve(const Points& knots, std::span<const ShapeParameters> betas, int grain,
                        int derivative = 0);

// Per-knot values for the knots as given, extended the way make_curve extends the knots for an
// end mode (doubled: first and last repeated; closed: wrapped), so they match c.control.
std::vector<ShapeParameters> extend_betas(std::span<const ShapeParameters> betas, Ends ends);

// A cubic curve from make_curve (only its knots and end mode are used; its basis is replaced by
// the continuously shaped Beta-spline) with one (b1, b2) per knot as given (c.knot_count):
// as many points as sample(c, grain, derivative). Throws CurveError on a count
// mismatch, a non-cubic curve, or parameters for which the matrix does not exist.
Points sample_local_betas(const Curve& c, std::span<const ShapeParameters> betas, int grain, int derivative = 0);

}  // namespace splinefig
