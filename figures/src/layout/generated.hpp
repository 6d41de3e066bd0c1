#pragma once
// Internal: the layout of the generated plot elements (spec.hpp). Their data is computed here,
// when a figure is laid out, not when its spec is loaded: point sets directly, curves as paths
// that are sampled once the panel's pixel map is known, to the same 0.05 px flatness as
// [[axes.curve]] at the output scale.
//   generated_companion.cpp: interp, relaxed_bspline, bezier, lagrange, relaxed_basis,
//                            subdivision, local_betas, inbetween (docs/companion.md)
//   generated_filters.cpp:   filter, response, step, zoneplate (docs/resample.md)
#include <splinefig/figures/sampling.hpp>
#include <splinefig/figures/spec.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace splinefig::figures::detail {

// A curve in data space, x(t), y(t) for t from breaks.front() to breaks.back(), smooth
// between consecutive breaks (jumps may sit at a break).
struct Path {
  std::function<Vec2(double)> at;
  std::function<Vec2(double)> before;  // the limit from the left at t; empty: no jumps
  std::vector<double> breaks;          // ascending, at least two
  bool closed = false;                 // ends where it starts (the last point is the first)
  std::vector<Vec2> bezier;            // a cubic spline: its Bezier control points (3n + 1), else empty
};

// A generated series: its points, or the path its points are sampled from.
struct GeneratedSeries {
  SeriesElement series;
  std::optional<Path> path;
};

using GeneratedPart = std::variant<GeneratedSeries, ImageElement>;

bool is_generated(const PlotElement& e);
// The parts of a generated element, in drawing order (none for other elements). Throws
// SpecFileError naming the key (origin) when the library rejects the element's data.
std::vector<GeneratedPart> generate(const PlotElement& e);

// One per generated element kind (generated_companion.cpp, generated_filters.cpp).
std::vector<GeneratedPart> parts_of(const InterpElement& e);
std::vector<GeneratedPart> parts_of(const RelaxedBsplineElement& e);
std::vector<GeneratedPart> parts_of(const BezierElement& e);
std::vector<GeneratedPart> parts_of(const LagrangeElement& e);
std::vector<GeneratedPart> parts_of(const RelaxedBasisElement& e);
std::vector<GeneratedPart> parts_of(const SubdivisionElement& e);
std::vector<GeneratedPart> parts_of(const LocalBetasElement& e);
std::vector<GeneratedPart> parts_of(const InbetweenElement& e);
std::vector<GeneratedPart> parts_of(const FilterCurveElement& e);
std::vector<GeneratedPart> parts_of(const ResponseElement& e);
std::vector<GeneratedPart> parts_of(const StepElement& e);
std::vector<GeneratedPart> parts_of(const ZoneplateElement& e);

// A few points of the path (its breaks and 32 steps between each), enough to find the
// panel's data range before the pixel map exists.
std::vector<Vec2> rough_points(const Path& path);
// The path's points (data) at parameters chosen so that its polyline in pixels stays within
// `tolerance` of the curve.
std::vector<Vec2> sample_path(const Path& path, const PixelMap& map, double tolerance);

}  // namespace splinefig::figures::detail
