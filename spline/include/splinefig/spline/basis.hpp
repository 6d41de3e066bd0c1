#pragma once
// Basis matrices of uniform polynomial splines (Smith, "Spline Tutorial Notes", 1983) and
// their basis functions (kernels).
//
// A Basis is a (degree+1)x(degree+1) matrix M, rows ordered u^degree ... u^0 (the memo's
// U = [u^3 u^2 u 1]). For a cubic, the piece between knots x[i] and x[i+1] is
//   X(u) = [u^3 u^2 u 1] M [x[i-1] x[i] x[i+1] x[i+2]]^T,  u in [0, 1].
// Families: cardinal C_a (Catmull-Rom = C_0.5), B-spline B, Duff's tensioned B_a,
// Barsky's Beta-spline B_{b1,b2}, the uniform B-spline of any degree (seed 002 §4.16.10), and
// Mitchell and Netravali's (1988) cubic family M(B,C).
#include <splinefig/base/error.hpp>
#include <splinefig/kernel/kernel.hpp>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig {

struct Basis {
  std::string family;       // "cardinal", "bspline", "tensioned-bspline", "beta", "uniform-bspline",
                            // "mitchell-netravali"
  std::string spec;         // canonical spec, e.g. "cardinal:a=0.25" (parse_basis(spec) gives it back)
  int degree = 3;           // polynomial degree n; the matrix is (n+1)x(n+1)
  std::vector<double> m;    // row-major, m[r*(n+1)+c]; row r multiplies u^(n-r)

  int order() const { return degree + 1; }
  double operator()(int row, int col) const { return m[static_cast<size_t>(row * order() + col)]; }
};

// An invalid basis spec: the message names the name, key or value and why.
struct SpecError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

// The memo's matrices, exactly as printed.
Basis catmull_rom();                          // C = C_0.5
Basis cardinal(double a);                     // C_a
Basis bspline();                              // B
Basis tensioned_bspline(double a);            // B_a (Duff); a > 0... any finite a != 0 gives a matrix
Basis beta(double b1, double b2);             // B_{b1,b2} (Barsky); throws SpecError where d = 0
Basis uniform_bspline(int degree);            // degree >= 1, seed 002's m_ij formula
// Mitchell and Netravali's cubic family, in the memo's matrix form (rows u^3 .. u^0):
//   M(B,C) = 1/6 [ -B-6C     12-9B-6C   -12+9B+6C  B+6C ]
//                [ 3B+12C   -18+12B+6C   18-15B-12C -6C ]
//                [ -3B-6C    0           3B+6C      0   ]
//                [ B         6-2B        B          0   ]
// Spec "mitchell-netravali:b=B,c=C" (both 1/3 by default, the authors' recommendation).
Basis mitchell_netravali_basis(double b, double c);

// Parses NAME[:key=value[,key=value...]] (docs/spline.md). Throws SpecError.
Basis parse_basis(std::string_view spec);
// The basis names parse_basis knows, comma-separated.
std::string known_bases();

// The basis function k(s) (docs/conventions.md kernel convention): a curve is
// X(t) = sum_j x[j] k(t - j). For a cubic with columns c_0..c_3 of U M:
// k(s) = c_3(s+2) on [-2,-1), c_2(s+1) on [-1,0), c_1(s) on [0,1), c_0(s-1) on [1,2].
// For degree n, the piece between knots i and i+1 uses x[i-h] .. x[i-h+n] with
// h = (n-1)/2 (integer division; h = 1 for the cubic, as in the memo), so odd degrees give
// centred kernels; column c is the piece on [h-c, h-c+1) and the support is [h-n, h+1].
// A convenience for basis_kernel(b)(s) (spline/basis_kernel.hpp): for many values, make the
// Kernel once.
double kernel(const Basis& b, double s);

// Support [lo, hi] of the kernel (for a cubic: [-2, 2]).
Support kernel_support(const Basis& b);

// The basis segment c_i(u) = [u^n ... 1] M column i, for u in [0,1].
double basis_segment(const Basis& b, int i, double u);

}  // namespace splinefig
