// Refinement steps and limit points of seed 002 §4.16.9.
#include <splinefig/spline/subdivision.hpp>
#include <splinefig/spline/curve.hpp>

#include <stdexcept>
#include <string>

namespace splinefig {

Points refine(const Points& polygon) {
  const std::size_t c = polygon.size(), dim = static_cast<std::size_t>(polygon.dim);
  if (c < 3) throw CurveError("refinement needs at least 3 control points, got " + std::to_string(c));
  Points r(polygon.dim, 2 * c - 3);
  const double* p = polygon.coords.data();
  double* o = r.coords.data();
  for (std::size_t i = 0; i + 1 < c; ++i) {
    // Edge point of P_i P_{i+1} at 2i, vertex point of P_{i+1} at 2i+1 (interior vertices only).
    for (std::size_t q = 0; q < dim; ++q) o[2 * i * dim + q] = (p[i * dim + q] + p[(i + 1) * dim + q]) / 2;
    if (i + 2 < c)
      for (std::size_t q = 0; q < dim; ++q)
        o[(2 * i + 1) * dim + q] = (p[i * dim + q] + 6 * p[(i + 1) * dim + q] + p[(i + 2) * dim + q]) / 8;
  }
  return r;
}

Points refine(const Points& polygon, int steps) {
  if (steps < 0) throw CurveError("refinement steps must be >= 0, got " + std::to_string(steps));
  Points r = polygon;
  for (int k = 0; k < steps; ++k) r = refine(r);
  return r;
}

Points refine_closed(const Points& polygon) {
  const std::size_t c = polygon.size(), dim = static_cast<std::size_t>(polygon.dim);
  if (c < 3) throw CurveError("closed refinement needs at least 3 control points, got " + std::to_string(c));
  Points r(polygon.dim, 2 * c);
  const double* p = polygon.coords.data();
  for (std::size_t i = 0; i < c; ++i) {
    const double* a = p + ((i + c - 1) % c) * dim;
    const double* b = p + i * dim;
    const double* n = p + ((i + 1) % c) * dim;
    for (std::size_t q = 0; q < dim; ++q) {
      r.coords[2 * i * dim + q] = (a[q] + 6 * b[q] + n[q]) / 8;
      r.coords[(2 * i + 1) * dim + q] = (b[q] + n[q]) / 2;
    }
  }
  return r;
}

Points limit_points(const Points& polygon) {
  const std::size_t c = polygon.size(), dim = static_cast<std::size_t>(polygon.dim);
  if (c < 3) throw CurveError("limit points need at least 3 control points, got " + std::to_string(c));
  Points r(polygon.dim, c - 2);
  const double* p = polygon.coords.data();
  for (std::size_t i = 1; i + 1 < c; ++i)
    for (std::size_t q = 0; q < dim; ++q)
      r.coords[(i - 1) * dim + q] = (p[(i - 1) * dim + q] + 4 * p[i * dim + q] + p[(i + 1) * dim + q]) / 6;
  return r;
}

}  // namespace splinefig
