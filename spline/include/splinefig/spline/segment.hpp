#pragma once
// One polynomial piece of a uniform spline, in Horner form.
//
// For a basis M of degree n and control points p_0..p_n (of any dimension), the piece is
//   X(u) = [u^n ... u 1] M [p_0 ... p_n]^T = sum_r a_r u^(n-r),   a_r = sum_c M(r,c) p_c,
// with u in [0, 1]. The memo evaluates it as p3 + u(p2 + u(p1 + u p0)) (its `Matrix`);
// the derivatives use the same nesting on n a_0, (n-1) a_1, ... Knot spacing is 1, so
// d/du is d/dt of the whole curve.
#include <splinefig/spline/basis.hpp>

#include <span>

namespace splinefig {

// a[r*dim + d] = sum_c M(r,c) control[c*dim + d]; control holds degree+1 points.
void segment_coefficients(const Basis& b, std::span<const double> control, int dim,
                          std::span<double> a);

// The derivative-th derivative (0, 1 or 2; any order <= degree works) of the piece with
// coefficients a (from segment_coefficients) at u, written to out[0..dim).
void segment_point(std::span<const double> a, int degree, int dim, double u, int derivative,
                   std::span<double> out);

// The weights w_c = d^k/du^k of basis segment c at u, c = 0..degree: the piece is
// sum_c w_c p_c. These are the columns of M evaluated in Horner form.
void basis_weights(const Basis& b, double u, int derivative, std::span<double> w);

}  // namespace splinefig
