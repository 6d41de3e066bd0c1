#pragma once
// Lagrange interpolation (seed 003 §1, Figure 1): the one polynomial of degree n through
// n+1 data points (t_k, S_k), P(t) = sum_k S_k prod_{j != k} (t - t_j)/(t_k - t_j).
// Shown in the notes to contrast with splines: a local change of the data moves the whole
// curve, and high degrees swing far out near the ends.
//
// Evaluated in the barycentric form (Berrut and Trefethen 2004): weights
// w_k = 1 / prod_{j != k}(t_k - t_j) once, then P(t) = sum w_k S_k/(t - t_k) / sum w_k/(t - t_k)
// (P(t_k) = S_k exactly), which is O(n) per point and numerically stable.
#include <splinefig/spline/points.hpp>

#include <span>
#include <vector>

namespace splinefig {

struct LagrangePolynomial {
  std::vector<double> t;        // distinct parameter values t_0..t_n
  Points data;                  // S_0..S_n
  std::vector<double> weights;  // barycentric weights
};

// Throws CurveError when sizes differ, nothing is given, or two t_k coincide.
LagrangePolynomial lagrange(std::vector<double> t, Points data);

void evaluate(const LagrangePolynomial& p, double t, std::span<double> out);

}  // namespace splinefig
