#pragma once
// The numbers that describe a filter kernel (kernel.hpp), as a reconstruction filter.
//
// The memo: "the basis functions for splines turn out to be interesting filter functions".
// Every basis spec is a kernel; box, tent and lanczos3 are there for comparison. Pure math
// over doubles:
//   energy, continuity class, interpolating or not, the jumps of a derivative at the knots;
//   the frequency response K(f) = integral k(s) e^{-2 pi i f s} ds (f in cycles per sample),
//     in closed form for piecewise polynomials: each piece's transform is
//     e^{-i w a} sum_m c_m I_m(w) with I_m(t) = integral_0^1 u^m e^{-i t u} du,
//     obtained by the exact two-term recurrence I_m = (m I_{m-1} - e^{-it}) / (it), run upwards
//     when t >= degree and downwards otherwise (each direction is stable in its range); for the
//     (even) non-polynomial kernels, the cosine integral by Gauss-Legendre quadrature;
//   passband droop |K(1/4)| / |K(0)|, stopband leakage (the fraction of the kernel's energy
//     above Nyquist, using Parseval: integral |K|^2 df = integral k^2 ds), the step response
//     (overshoot, undershoot, 10-90% rise distance: ringing and blur);
//   the Mitchell-Netravali (1988) B, C parameters of a cubic kernel that belongs to their family.
#include <splinefig/kernel/kernel.hpp>

#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace splinefig {

double energy(const Kernel& k);  // integral of k^2

// The jump k^(m)(knot+) - k^(m)(knot-) at each knot lo, lo+1, ..., hi of a polynomial kernel
// (the support's ends included, where k meets 0).
std::vector<double> jumps(const Kernel& k, int m);

// The tolerance of continuity(): a jump in k^(m) counts when it exceeds this times the largest
// |k^(m)| at any knot (either side). The coefficients of a basis matrix are exact up to a few
// roundings, so true jumps are of the order of the derivative itself and rounding residues
// about 1e-16 of it.
inline constexpr double kContinuityTolerance = 1e-9;

// The smoothness class: -1 discontinuous, m >= 0 for C^m (derivatives 0..m continuous
// everywhere, including at the support's ends, where k joins the zero function; m = degree
// when no derivative jumps). Catmull-Rom is C1, the B-spline C2, the degree-n B-spline C(n-1),
// a Beta-spline with b1 != 1 only C0 as a function (its curves are G2). A non-polynomial kernel
// has the class it declares (lanczos3: C1).
int continuity(const Kernel& k);

// k(0) = 1 and k(n) = 0 at every other integer n (to 1e-12): reconstruction passes through the
// samples.
bool interpolating(const Kernel& k);

// K(f) with f in cycles per sample, and |K(f)|.
std::complex<double> fourier(const Kernel& k, double freq);
double response(const Kernel& k, double freq);

struct StepResponse {
  double overshoot = 0;   // max X(t) - 1 >= 0, X the normalised reconstruction of a unit step
  double undershoot = 0;  // -min X(t) >= 0
  double rise = 0;        // distance from the last crossing of 0.1 to the first reach of 0.9
};
// Reconstruction of the samples x[j] = (j >= 0) as X(t) = sum_{j>=0} k(t-j) / sum_j k(t-j).
double step_value(const Kernel& k, double t);
StepResponse step_response(const Kernel& k);

// Mitchell and Netravali's cubic family (spline/basis.hpp mitchell_netravali() gives its matrix)
// holds exactly the cubic kernels on [-2, 2] that are symmetric, C1 and a partition of unity;
// a member has k(1) = B/6 and, on [-2, -1), the u^2 coefficient -C. Cardinal C_a is (0, a),
// Duff's B_a is (a, 0), the Beta-spline with b1 = 1 is (12/(b2+12), 0).
struct MitchellNetravali {
  double b = 0, c = 0;
};
// The kernel's place in the B,C plane, or nullopt (with the reason in *why) when it is not in
// the family.
std::optional<MitchellNetravali> mitchell_netravali(const Kernel& k, std::string* why = nullptr);

struct FilterReport {
  std::string name;
  Support support;
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
FilterReport analyse(const Kernel& k);
// "key: value" lines, one per measure.
std::string report_text(const FilterReport& r);

}  // namespace splinefig
