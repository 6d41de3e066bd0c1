#pragma once
// A filter kernel k(s) of finite support: the one kernel type shared by the resampler, the
// renderer's pixel filters, the filter analysis and the kernel plots.
//
// Mostly a piecewise polynomial on unit intervals: piece p covers [lo + p, lo + p + 1) and holds
// its coefficients in ascending powers of the local variable u = s - (lo + p) in [0, 1). Every
// spline basis function is one (spline/basis_kernel.hpp converts a basis matrix exactly), and so
// are the box and the tent. A few comparison filters that are not polynomials (lanczos3) sit
// behind the same interface: they are even functions with a stated continuity class, and
// pieces() is empty for them.
//
// The convention of the whole library: a signal is reconstructed as X(t) = sum_j x[j] k(t - j)
// (asymmetric kernels such as a Beta-spline's keep their orientation).
#include <splinefig/base/error.hpp>

#include <functional>
#include <string>
#include <vector>

namespace splinefig {

// A kernel that cannot be made from what it is given (no pieces, a coefficient that is not
// finite, a Lanczos a below 1).
struct KernelError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

// The interval [lo, hi] outside which k is zero.
struct Support {
  double lo = 0, hi = 0;
};

class Kernel {
 public:
  Kernel();  // the box

  // A piecewise polynomial (see the top of this file). Throws KernelError when there
  // are no pieces, a piece has no coefficient, or lo or a coefficient is not finite.
  static Kernel piecewise(std::string name, double lo, std::vector<std::vector<double>> pieces);
  static Kernel box();   // 1 on [-1/2, 1/2)
  static Kernel tent();  // 1 - |s| on [-1, 1], the linear B-spline
  // sinc(s) sinc(s / a) on |s| < a (a >= 1), named "lanczos<a>".
  static Kernel lanczos(int a);

  const std::string& name() const { return name_; }
  Support support() const { return support_; }

  // k(s). Pieces are half-open, so k vanishes at the support's right end (every basis function
  // is 0 there; the box is [-1/2, 1/2)).
  double operator()(double s) const;
  // The integral of k over its support: exact for a piecewise polynomial (sum of c_m / (m + 1)),
  // by Gauss-Legendre quadrature otherwise.
  double integral() const;

  bool polynomial() const { return !pieces_.empty(); }
  // The polynomial form (empty pieces for a non-polynomial kernel).
  double lo() const { return support_.lo; }
  const std::vector<std::vector<double>>& pieces() const { return pieces_; }
  int degree() const;  // the largest piece degree; -1 for a non-polynomial kernel
  // The m-th derivative at s, the piece to the right at a knot; 0 outside the support.
  // Only for a polynomial kernel (std::logic_error otherwise).
  double derivative(double s, int m) const;

  // The continuity class a non-polynomial kernel declares (see analysis.hpp continuity()).
  int declared_continuity() const { return continuity_; }

 private:
  long piece_at(double s) const;  // the piece holding s, for s inside the support

  std::string name_;
  Support support_;
  std::vector<std::vector<double>> pieces_;
  std::function<double(double)> value_;  // a non-polynomial kernel on its support
  int continuity_ = -1;
};

// c[0] + c[1] u + ... by Horner's rule, and its m-th derivative.
double polynomial_value(const std::vector<double>& c, double u);
double polynomial_derivative(const std::vector<double>& c, int m, double u);

}  // namespace splinefig
