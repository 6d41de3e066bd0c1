#pragma once
// The memo's sampling of an open cubic curve whose pieces are computed point by point (the
// spaced Catmull-Rom and the locally shaped Beta-spline): pieces i = 1 .. n-3 (between knots
// i and i+1) at u = 0, 1/grain, ..., (grain-1)/grain, then u = 1 of the last piece, i.e.
// (n-3)*grain + 1 points.
#include <splinefig/spline/points.hpp>
#include <splinefig/spline/curve.hpp>

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

namespace splinefig::detail {

// point(i, u, out) writes the point of piece i at u into out (dim doubles). `curve` names the
// curve in the errors for fewer than 4 knots or grain < 1 ("a Beta-spline curve needs ...").
template <class PointAt>
Points sample_open_cubic(const char* curve, int dim, std::size_t knots, int grain, PointAt&& point) {
  if (knots < 4)
    throw CurveError(std::string("a ") + curve + " curve needs at least 4 knots, got " +
                                std::to_string(knots));
  if (grain < 1) throw CurveError("grain must be at least 1, got " + std::to_string(grain));
  const std::size_t g = static_cast<std::size_t>(grain), d = static_cast<std::size_t>(dim);
  Points out(dim, (knots - 3) * g + 1);
  std::size_t row = 0;
  for (std::size_t i = 1; i + 2 < knots; ++i)
    for (std::size_t j = 0; j < g; ++j, ++row)
      point(i, static_cast<double>(j) / static_cast<double>(g), std::span<double>(out.coords.data() + row * d, d));
  point(knots - 3, 1.0, std::span<double>(out.coords.data() + row * d, d));
  return out;
}

}  // namespace splinefig::detail
