// The filter figures' plot elements computed by the filter analysis
// (kernel/analysis.hpp) and the resampler (resample/resample.hpp); see generated.hpp.
#include "generated.hpp"

#include <splinefig/resample/prefilter.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/kernel/analysis.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

namespace splinefig::figures::detail {
namespace {

double left_of(double t) { return std::nextafter(t, -std::numeric_limits<double>::infinity()); }

// The breaks of a piecewise function over [lo, hi]: both ends and every point of `offsets`
// (mod 1) in between.
std::vector<double> breaks_over(double lo, double hi, const std::vector<double>& offsets) {
  std::vector<double> b{lo, hi};
  for (double o : offsets) {
    const double f = o - std::floor(o);
    for (double t = std::ceil(lo - f) + f; t < hi; t += 1)
      if (t > lo) b.push_back(t);
  }
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

// Where a filter's pieces start and end, mod 1 (a Lanczos filter: the integers).
std::vector<double> piece_offsets(const Kernel& k) {
  // Polynomial pieces start at lo + p: one offset covers them all (mod 1).
  std::vector<double> o{k.support().lo, k.support().hi, k.polynomial() ? k.lo() : 0.0};
  return o;
}

// The element's kernel, shared by the path's functions.
std::shared_ptr<const Kernel> shared(const Kernel& k) { return std::make_shared<const Kernel>(k); }

GeneratedSeries traced(Path path, const SeriesLook& look) { return {{{}, look}, std::move(path)}; }

}  // namespace

// k(s) on [s0, s1]; at a jump (the box) both one-sided values, so it is drawn upright.
std::vector<GeneratedPart> parts_of(const FilterCurveElement& e) {
  auto f = shared(e.filter);
  const double s0 = e.range ? (*e.range)[0] : f->support().lo, s1 = e.range ? (*e.range)[1] : f->support().hi;
  Path p;
  p.breaks = breaks_over(s0, s1, piece_offsets(*f));
  p.at = [f](double s) { return Vec2{s, (*f)(s)}; };
  p.before = [f](double s) { return Vec2{s, (*f)(left_of(s))}; };
  return {traced(std::move(p), e.look)};
}

// |K(f)|: smooth but for kinks where K changes sign; breaks every 1/8 cycle per sample seed
// the subdivision.
std::vector<GeneratedPart> parts_of(const ResponseElement& e) {
  auto f = shared(e.filter);
  Path p;
  p.breaks = breaks_over(e.range[0], e.range[1], {0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875});
  p.at = [f](double fr) { return Vec2{fr, response(*f, fr)}; };
  return {traced(std::move(p), e.look)};
}

// X(t) = sum_j c_j k(t - j) / sum_j k(t - j) for samples at t = 0 .. n-1, extended beyond them
// by the edge mode; c = the samples, or their inverse prefilter.
std::vector<GeneratedPart> parts_of(const StepElement& e) {
  auto f = shared(e.filter);
  const long n = static_cast<long>(e.values.size());
  const Edge edge = e.edge;
  auto c = std::make_shared<std::vector<float>>(e.values.begin(), e.values.end());
  if (e.interpolating) {
    try {
      prefilter_line(c->data(), n, 1, sampled_kernel(*f), edge);
    } catch (const std::invalid_argument& x) {
      throw SpecFileError(e.origin, x.what());
    }
  }
  auto X = [f, c, n, edge](double t) {
    double num = 0, den = 0;
    for (double j = std::ceil(t - f->support().hi); j <= std::floor(t - f->support().lo); j += 1) {
      const double k = (*f)(t - j);
      den += k;
      const long q = edge_index(static_cast<long>(j), n, edge);
      if (q >= 0) num += k * (*c)[static_cast<size_t>(q)];
    }
    return num / den;
  };
  const double t0 = e.range ? (*e.range)[0] : -0.5, t1 = e.range ? (*e.range)[1] : double(n) - 0.5;
  Path p;
  p.breaks = breaks_over(t0, t1, piece_offsets(*f));
  p.at = [X](double t) { return Vec2{t, X(t)}; };
  p.before = [X](double t) { return Vec2{t, X(left_of(t))}; };
  return {traced(std::move(p), e.look)};
}

// A zone plate z = 1/2 + 1/2 cos(pi r^2 / N) sampled at the centres of N x N pixels (r from the
// image centre, in pixels): its local frequency r/N reaches Nyquist at the edges' midpoints and
// passes it towards the corners. Resampled to `size` with the filter and cropped.
std::vector<GeneratedPart> parts_of(const ZoneplateElement& e) {
  const Kernel& f = e.filter;
  const int n = e.source;
  ResampleOptions opt;
  opt.edge = e.edge;
  opt.interpolating = e.interpolating;
  // The plate is symmetric under x -> n-1-x, y -> n-1-y and x <-> y, and d(n-1-x)^2 = d(x)^2
  // exactly (d is a half-integer), so one octant is computed and mirrored: every pixel gets the
  // value it would get on its own.
  Image src(n, n, 1);
  std::vector<double> d2(static_cast<std::size_t>(n));
  for (int x = 0; x < n; ++x) {
    const double d = x + 0.5 - n / 2.0;
    d2[static_cast<std::size_t>(x)] = d * d;
  }
  const int half = (n + 1) / 2;
  for (int y = 0; y < half; ++y)
    for (int x = y; x < half; ++x) {
      const double r2 = d2[static_cast<std::size_t>(x)] + d2[static_cast<std::size_t>(y)];
      const float v = static_cast<float>(0.5 + 0.5 * std::cos(std::numbers::pi * r2 / n));
      for (const int a : {x, n - 1 - x})
        for (const int b : {y, n - 1 - y}) {
          src.at(a, b, 0) = v;
          src.at(b, a, 0) = v;
        }
    }
  Image out;
  try {
    out = resample(src, e.size, e.size, f, opt);
  } catch (const std::invalid_argument& x) {
    throw SpecFileError(e.origin, x.what());
  }
  ImageElement im;
  im.extent = e.extent;
  im.raster.nearest = e.nearest;
  im.raster.width = e.crop[2];
  im.raster.height = e.crop[3];
  im.raster.channels = 1;
  for (int y = e.crop[1]; y < e.crop[1] + e.crop[3]; ++y)
    for (int x = e.crop[0]; x < e.crop[0] + e.crop[2]; ++x)
      im.raster.data.push_back(static_cast<float>(std::clamp(0.5 + e.contrast * (out.at(x, y, 0) - 0.5), 0.0, 1.0)));
  return {std::move(im)};
}

}  // namespace splinefig::figures::detail
