#pragma once
// Spline basis functions as reconstruction filters, and the numbers that describe a filter.
//
// The memo: "the basis functions for splines turn out to be interesting filter functions".
// A Filter is a kernel k(s) of finite support used as X(t) = sum_j x[j] k(t - j) (the kernel
// convention of docs/conventions.md; asymmetric Beta kernels keep their orientation). Every basis spec
// is a filter; `box`, `tent` and `lanczos3` are there for comparison.
//
// The analysis is pure math over doubles:
//   integral, support, continuity class, interpolating or not;
//   the frequency response K(f) = integral k(s) e^{-2 pi i f s} ds (f in cycles per sample),
//     in closed form for piecewise polynomials: each piece's transform is
//     e^{-i w a} sum_m c_m L^{m+1} I_m(w L) with I_m(t) = integral_0^1 u^m e^{-i t u} du,
//     obtained by the exact two-term recurrence I_m = (m I_{m-1} - e^{-it}) / (it), run upwards
//     when t >= degree and downwards otherwise (each direction is stable in its range);
//   passband droop |K(1/4)| / |K(0)|, stopband leakage (the fraction of the kernel's energy
//     above Nyquist, using Parseval: integral |K|^2 df = integral k^2 ds), the step response
//     (overshoot, undershoot, 10-90% rise distance: ringing and blur);
//   the Mitchell-Netravali (1988) B, C parameters for cubic kernels that belong to their family.
#include <splinefig/spline/basis.hpp>

#include <complex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig {

// k(s) = sum_m c[m] (s - lo)^m on [lo, hi).
struct PolynomialPiece {
  double lo = 0, hi = 0;
  std::vector<double> c;  // ascending powers of (s - lo)
};

struct Filter {
  std::string spec;                     // canonical name: a basis spec, "box", "tent", "lanczos3"
  std::vector<PolynomialPiece> pieces;  // sorted, contiguous; empty for a Lanczos filter
  int lanczos = 0;                      // a > 0: k(s) = sinc(s) sinc(s/a) on |s| < a
  std::optional<Basis> basis;           // set when the filter is a spline basis function
  Support support{0, 0};
};

// A basis function as a filter (pieces taken from the matrix columns, exactly).
Filter basis_filter(const Basis& b);
// Any basis spec, or box ([-1/2, 1/2), value 1), tent (1 - |s| on [-1, 1]), lanczos3.
// Throws SpecError naming the unknown filter or the bad parameter.
Filter parse_filter(std::string_view spec);

// k(s). Pieces are half-open [lo, hi), so k vanishes at the support's right end (every basis
// function is 0 there, so this agrees with kernel(); the box is [-1/2, 1/2)).
double evaluate(const Filter& f, double s);

double integral(const Filter& f);        // integral of k
double energy(const Filter& f);          // integral of k^2
// Smoothness class: -1 discontinuous, k >= 0 for C^k (derivatives 0..k continuous everywhere,
// including at the support's ends, where k joins the zero function).
int continuity(const Filter& f);
// k(0) = 1 and k(n) = 0 at every other integer n (to 1e-12): reconstruction passes through the
// samples.
bool interpolating(const Filter& f);

// K(f) with f in cycles per sample, and |K(f)|.
std::complex<double> fourier(const Filter& f, double freq);
double response(const Filter& f, double freq);

struct StepResponse {
  double overshoot = 0;   // max X(t) - 1 >= 0, X the normalised reconstruction of a unit step
  double undershoot = 0;  // -min X(t) >= 0
  double rise = 0;        // distance from the last crossing of 0.1 to the first reach of 0.9
};
// Reconstruction of the samples x[j] = (j >= 0) as X(t) = sum_{j>=0} k(t-j) / sum_j k(t-j).
double step_value(const Filter& f, double t);
StepResponse step_response(const Filter& f);

// Mitchell and Netravali's cubic family, in the memo's matrix form (rows u^3 .. u^0):
//   M(B,C) = 1/6 [ -B-6C     12-9B-6C   -12+9B+6C  B+6C ]
//                [ 3B+12C   -18+12B+6C   18-15B-12C -6C ]
//                [ -3B-6C    0           3B+6C      0   ]
//                [ B         6-2B        B          0   ]
// It holds exactly the cubic kernels that are symmetric, C1 and a partition of unity; so
// B = 6 M[3][0] and C = -M[1][3], and membership is M == M(B,C). Cardinal C_a is (0, a),
// Duff's B_a is (a, 0), the Beta-spline with b1 = 1 is (12/(b2+12), 0).
struct MitchellNetravali {
  double b = 0, c = 0;
};
Basis mitchell_netravali_basis(double b, double c);
// The filter's place in the B,C plane, or nullopt (with the reason in *why) when it is not in
// the family.
std::optional<MitchellNetravali> mitchell_netravali(const Filter& f, std::string* why = nullptr);

struct FilterReport {
  std::string spec;
  Support support{0, 0};
  double integral = 0, energy = 0;
  int continuity = 0;
  bool interpolating = false;
  double response_at_0 = 0, response_at_quarter = 0, response_at_nyquist = 0;
  double droop = 0;    // 1 - |K(0.25)| / |K(0)|
  double leakage = 0;  // fraction of the energy at |f| > 0.5
  StepResponse step;
  std::optional<MitchellNetravali> bc;
  std::string not_bc;  // why not in the B,C family
};
FilterReport analyse(const Filter& f);
// "key: value" lines, one per measure.
std::string report_text(const FilterReport& r);

}  // namespace splinefig
