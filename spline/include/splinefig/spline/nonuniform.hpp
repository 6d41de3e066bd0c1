#pragma once
// Non-uniform B-splines of any degree p (seed 002 §4.16, answer 4.103; seed 003 §10):
// the Cox-de Boor recursion for the basis functions and de Boor's algorithm for points.
//
// Knots t_0 <= t_1 <= ... <= t_{m} with m + 1 = count + p + 1 for `count` control points.
//   N_{i,0}(t) = 1 on [t_i, t_{i+1}), else 0;
//   N_{i,p}(t) = (t - t_i)/(t_{i+p} - t_i) N_{i,p-1}(t) + (t_{i+p+1} - t)/(t_{i+p+1} - t_{i+1}) N_{i+1,p-1}(t),
// with 0/0 read as 0 (repeated knots). The curve P(t) = sum_i N_{i,p}(t) P_i is defined on
// [t_p, t_count]; at the right end the last non-empty span is used, so P(t_count) is its limit.
// A knot of multiplicity k lowers the continuity there to C^(p-k); a clamped ("open") knot
// vector repeats each end knot p+1 times so the curve starts at P_0 and ends at P_last.
#include <splinefig/spline/points.hpp>

#include <span>
#include <vector>

namespace splinefig {

struct BSplineCurve {
  int degree = 3;              // p >= 0
  std::vector<double> knots;   // non-decreasing, control.size() + degree + 1 of them
  Points control;              // P_0 .. P_{count-1}

  double t_min() const { return knots[static_cast<std::size_t>(degree)]; }
  double t_max() const { return knots[control.size()]; }
};

// Throws CurveError naming the problem: degree < 0, too few control points
// (count >= degree + 1), wrong knot count, decreasing or non-finite knots, an empty domain.
void validate(const BSplineCurve& c);

// Knot vectors for `count` control points of degree p.
std::vector<double> uniform_knots(std::size_t count, int degree);  // 0, 1, ..., count + p
std::vector<double> clamped_knots(std::size_t count, int degree);  // 0 x(p+1), 1, 2, ..., last x(p+1)

// The span index s with t_s <= t < t_{s+1}, p <= s < count (t clamped into the domain; the
// right end falls into the last non-empty span).
std::size_t find_span(const std::vector<double>& knots, int degree, std::size_t count, double t);

// The p+1 basis functions N_{s-p,p}(t) .. N_{s,p}(t) that are non-zero on span s, by the
// triangular form of the Cox-de Boor recursion (de Boor's BSPLVB); they sum to 1.
void basis_functions(const std::vector<double>& knots, int degree, std::size_t span, double t,
                     std::span<double> out);

// N_{i,p}(t) straight from the recursion above (exponential in p; for checks and plots).
double cox_de_boor(const std::vector<double>& knots, int degree, std::size_t i, double t);

// P(t) by de Boor's algorithm (repeated affine combinations of the p+1 active control points).
void de_boor(const BSplineCurve& c, double t, std::span<double> out);

// The derivative curve: degree p-1, control points p (P_{i+1} - P_i)/(t_{i+p+1} - t_{i+1})
// (0 over a zero-length interval), knots without the first and last. Degree 0 gives the
// zero curve.
BSplineCurve derivative(const BSplineCurve& c);

// P(t), dP/dt or d2P/dt2 at t (derivative 0..p; higher derivatives are 0).
void evaluate(const BSplineCurve& c, double t, int derivative, std::span<double> out);

// P(t) at `grain` evenly spaced parameters in every non-empty span [t_s, t_{s+1}) of the domain,
// then P(t_max): (non-empty spans) * grain + 1 points, each from its p+1 basis functions
// (Cox-de Boor) on that span. On uniform knots this is the memo's sampling of the uniform
// B-spline of degree p (grain >= 1, else CurveError).
Points sample(const BSplineCurve& c, int grain);

// Boehm's knot insertion: the same curve with one more knot at t (t_min <= t <= t_max) and one
// more control point. Inserting the midpoint of every span of a uniform cubic is one step of
// the subdivision of seed 002 §4.16.9.
BSplineCurve insert_knot(const BSplineCurve& c, double t);

}  // namespace splinefig
