#pragma once
// Continuity at the joints of a curve: parametric C0/C1/C2 (X, dX/dt, d2X/dt2 agree from
// both sides) and geometric G1/G2 (unit tangent and curvature vector agree).
//
// A Beta-spline B_{b1,b2} is G2 but in general not C1: at every joint Barsky's constraints
//   X'(t+) = b1 X'(t-),   X''(t+) = b1^2 X''(t-) + b2 X'(t-)
// hold, so the velocity ratio |X'(t+)| / |X'(t-)| is the bias b1 (the memo: "the ratio of the
// velocity right of a knot to the velocity left of the knot").
#include <splinefig/spline/curve.hpp>

#include <cstddef>
#include <vector>

namespace splinefig {

struct Joint {
  double t;                          // parameter of the joint (for a closed curve, also 0)
  std::vector<double> left[3];       // X, X', X'' at t from the left (u = 1 of the piece before)
  std::vector<double> right[3];      // ... and from the right (u = 0 of the piece after)
  double jump[3];                    // |right[m] - left[m]| (Euclidean)
  double velocity_ratio;             // |X'(t+)| / |X'(t-)| (inf or NaN when |X'(t-)| = 0)
  double tangent_angle;              // angle between X'(t-) and X'(t+), radians (NaN at a zero)
  double curvature_jump;             // |K(t+) - K(t-)|, K = (X'' - (X''.T)T) / |X'|^2
};

// Every interior joint (t = 1 .. segments-1), and for a closed curve the joint where the last
// piece meets the first.
std::vector<Joint> joints(const Curve& c);

// The largest m in -1..2 with X, ..., X^(m) continuous at every joint: a jump counts when it
// exceeds `tolerance` times the largest |X^(m)| at the joints (and times the size of the knots
// for m = 0).
int parametric_continuity(const Curve& c, double tolerance = 1e-12);

// 2 if G2 at every joint, 1 if G1 (same unit tangent), 0 if only G0, -1 if not even C0.
// A joint where the velocity vanishes on either side is not G1.
int geometric_continuity(const Curve& c, double tolerance = 1e-9);

// The largest residual of Barsky's constraints over the joints, relative to |X'| and |X''|
// there (0 for a Beta-spline with these b1, b2, up to rounding).
double beta_constraint_residual(const Curve& c, double b1, double b2);

}  // namespace splinefig
