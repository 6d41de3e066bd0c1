#pragma once
// The exact Bezier form of uniform spline pieces, by change of basis.
//
// A piece of degree n is X(u) = U M G with U = [u^n ... u 1] (basis.hpp), M the basis matrix and
// G its n+1 control points. The Bernstein polynomials of degree n are U M_B for one fixed matrix
// M_B, so X(u) = U M_B (M_B^-1 M G): the piece's Bezier control points are (M_B^-1 M) G, with no
// approximation, for any basis (cardinal, B-spline, tensioned, Beta, Mitchell-Netravali, or
// a uniform B-spline of any degree). For the cubic B-spline, M_B^-1 M is seed 003's A-frame
// construction: 1/6 [1 4 1 0; 0 4 2 0; 0 2 4 0; 0 1 4 1].
//
// The kernel's pieces likewise: on each unit interval the basis function is a polynomial of
// degree n in x, so the graph (x, k(x)) of a piece is a Bezier curve of degree n (x, linear
// in u, is elevated exactly).
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/points.hpp>

#include <span>
#include <vector>

namespace splinefig {

// The Bezier control points of the polynomial sum_k a_k v^k, v in [0, 1], of degree n: point j
// is sum_{k<=j} C(j,k)/C(n,k) a_k. `ascending` holds (n+1)*dim values, a_k at [k*dim, k*dim+dim).
Points bezier_from_power(std::span<const double> ascending, int degree, int dim);

// M_B^-1 M, (n+1)x(n+1) row-major: row j holds the weights of the control points in Bezier
// point j.
std::vector<double> bezier_matrix(const Basis& b);

// The n+1 Bezier control points of piece i of the curve (the curve's dimension each).
Points piece_bezier(const Curve& c, std::size_t i);

// The graph (x, scale * k(x)) of the kernel's piece p (p = 0 is the leftmost, on
// [lo, lo + 1) of kernel_support(b)) for u in [u0, u1] of that interval (x = lo + p + u), as the
// n+1 control points of a 2-D Bezier curve of degree n.
Points kernel_piece_bezier(const Basis& b, int piece, double u0 = 0, double u1 = 1, double scale = 1);

}  // namespace splinefig
