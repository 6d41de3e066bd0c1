#pragma once
// What a basis function (kernel, basis.hpp) is as a filter: its derivatives, its integral
// and its continuity class, all read off the matrix's polynomial coefficients.
#include <splinefig/spline/basis.hpp>

#include <vector>

namespace splinefig {

// The m-th derivative of k at s (m = 0 is kernel(b, s)); 0 outside the support. At an
// interior knot the piece to the right is used.
double kernel_derivative(const Basis& b, double s, int m);

// The integral of k over its support, exact up to the rounding of the matrix entries:
// sum over columns c and rows r of M(r,c) / (degree - r + 1). It is 1 for every family
// (partition of unity), so k reproduces constants.
double kernel_integral(const Basis& b);

// The jump k^(m)(j+) - k^(m)(j-) at each integer knot j = lo, lo+1, ..., hi of the support
// (the ends included, where k meets 0).
std::vector<double> kernel_jumps(const Basis& b, int m);

// The continuity class: the largest m (-1 .. degree-1) such that k, k', ..., k^(m) have no
// jump at any knot, a jump counting when it exceeds `tolerance` times the largest |k^(m)|
// at the knots. Catmull-Rom is C1, the B-spline C2, the degree-n B-spline C(n-1); a
// Beta-spline with b1 != 1 is only C0 as a function (its curves are G2, see continuity.hpp).
int kernel_continuity(const Basis& b, double tolerance = 1e-12);

}  // namespace splinefig
