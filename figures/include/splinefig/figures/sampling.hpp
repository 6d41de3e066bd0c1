#pragma once
// Spline curves and kernels turned into pixel polylines, sampled adaptively.
//
// On linear axes the map from data to pixels is affine, so a polynomial piece stays a
// polynomial X(u) in pixels. Cut into m equal parameter steps, each chord lies within
// (1/8) max|X''| / m^2 of its arc (the interpolation error of a linear interpolant), so
// m = ceil(sqrt(max|X''| / (8 tol))) steps keep the flatness <= tol; max|X''| is bounded
// from the Horner coefficients. On log axes the pieces are split recursively until the
// midpoints and quarter points lie within tol of their chords.
#include <splinefig/figures/axes.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/spline/curve.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace splinefig::figures {

struct PixelMap {
  AxisMap x, y;
  Vec2 operator()(Vec2 d) const { return {x.to_pixel(d.x), y.to_pixel(d.y)}; }
  bool affine() const { return x.scale == Scale::Linear && y.scale == Scale::Linear; }
};

// The whole curve as one polyline in pixels (closed curves: last point = first point).
std::vector<Vec2> sample_curve(const Curve& curve, const PixelMap& map, double tolerance);

// The kernel of `basis` times `scale` over [s0, s1], one polyline per polynomial piece
// left to right (piece p covers [lo + p, lo + p + 1) of the support [lo, hi]); the parts of
// [s0, s1] outside the support (where k = 0) join the first and last piece. Pieces outside
// [s0, s1] come back empty.
std::vector<std::vector<Vec2>> sample_kernel(const Basis& basis, double s0, double s1, double scale,
                                             const PixelMap& map, double tolerance);

// The exact pixel paths of the same curves: the pieces' Bezier control points (spline/
// bezier_form.hpp) mapped by the affine map, which maps Bezier curves exactly. Degree 1 pieces
// are lines, 2 quadratics (stored as their exact cubics), 3 cubics. None (nullopt) on log axes
// or for degrees above 3, which keep their polylines.
std::optional<render::Path> curve_path(const Curve& curve, const PixelMap& map);
// One path per piece, as sample_kernel's polylines (the zero parts included).
std::optional<std::vector<render::Path>> kernel_paths(const Basis& basis, double s0, double s1, double scale,
                                                      const PixelMap& map);

// Any smooth map u -> pixels on [u0, u1], cut into chords within `tolerance` of it by
// recursive halving until the midpoint and quarter points of every chord are that close (at
// least 2^min_depth chords, at most 2^18): the chords' end parameters, in (u0, u1].
std::vector<double> flat_parameters(const std::function<Vec2(double)>& f, double u0, double u1, double tolerance,
                                    int min_depth);
}  // namespace splinefig::figures
