// The filter figures' plot elements (filter_figures.hpp): data from the filter analysis
// (kernel/analysis.hpp) and the resampler (resample/resample.hpp), computed at load time.
#include "filter_figures.hpp"

#include <splinefig/resample/prefilter.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/kernel.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace splinefig::figures::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

Kernel filter_key(TableReader& r) {
  auto spec = r.opt_string("filter");
  if (!spec) r.fail("filter", "needs filter = \"SPEC\" (a basis spec, box, tent or lanczos3)");
  try {
    return parse_kernel(*spec);
  } catch (const SpecError& e) {
    r.fail("filter", e.what());
  }
}

std::array<double, 2> range_key(TableReader& r, std::array<double, 2> fallback) {
  if (!r.has("range")) return fallback;
  auto v = r.numbers("range");
  if (v.size() != 2 || !(v[0] < v[1])) r.fail("range", "expected [lo, hi] with lo < hi");
  return {v[0], v[1]};
}

Edge edge_key(TableReader& r, const char* fallback) {
  const std::string name = r.string("edge", fallback);
  auto e = parse_edge(name);
  if (!e) r.fail("edge", "'" + name + "' is not one of clamp, mirror, wrap, black");
  return *e;
}

// The look of a generated series: the keys of [[axes.series]] drawn as a line.
SeriesElement styled(TableReader& r) {
  SeriesElement s;
  if (auto c = r.opt_color("color")) s.color = c;
  render::StrokeStyle st;
  st.width = 2;
  st.join = render::Join::Round;
  st.cap = render::Cap::Round;
  s.style_stroke = r.stroke(st);
  s.label = parse_labelling(r);
  return s;
}

// k(s) on [s0, s1]: 1024 even steps plus both one-sided values at every breakpoint, so jumps
// (the box) are drawn upright.
SeriesElement parse_filter_curve(TableReader& r) {
  const Kernel f = filter_key(r);
  const auto [s0, s1] = range_key(r, {f.support().lo, f.support().hi});
  SeriesElement s = styled(r);
  std::vector<double> breaks{f.support().lo, f.support().hi};
  for (size_t p = 0; p < f.pieces().size(); ++p) breaks.push_back(f.lo() + double(p));
  const int n = 1024;
  for (int i = 0; i <= n; ++i) {
    const double x = s0 + (s1 - s0) * i / n;
    s.points.push_back({x, f(x)});
  }
  for (double b : breaks)
    if (b > s0 && b < s1) {
      s.points.push_back({b, f(std::nextafter(b, -std::numeric_limits<double>::infinity()))});
      s.points.push_back({b, f(b)});
    }
  std::stable_sort(s.points.begin(), s.points.end(), [](const Vec2& a, const Vec2& b) { return a.x < b.x; });
  return s;
}

SeriesElement parse_response(TableReader& r) {
  const Kernel f = filter_key(r);
  const auto [f0, f1] = range_key(r, {0.0, 2.0});
  const int n = r.integer("samples", 801, 2, 100000);
  SeriesElement s = styled(r);
  for (int i = 0; i < n; ++i) {
    const double fr = f0 + (f1 - f0) * i / (n - 1);
    s.points.push_back({fr, response(f, fr)});
  }
  return s;
}

// X(t) = sum_j c_j k(t - j) / sum_j k(t - j) for samples at t = 0 .. n-1, extended beyond them
// by the edge mode (default clamp); c = the samples, or their inverse prefilter.
SeriesElement parse_step(TableReader& r) {
  const Kernel f = filter_key(r);
  std::vector<double> values = r.has("values") ? r.numbers("values") : std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1};
  if (values.empty()) r.fail("values", "needs at least one sample");
  const long n = static_cast<long>(values.size());
  const Edge edge = edge_key(r, "clamp");
  const bool interpolating = r.boolean("interpolating", false);
  const auto [t0, t1] = range_key(r, {-0.5, double(n) - 0.5});
  const double step = r.positive("step", 1.0 / 64);
  if ((t1 - t0) / step > 1e6) r.fail("step", "more than a million points");
  SeriesElement s = styled(r);
  std::vector<float> c(values.begin(), values.end());
  if (interpolating) {
    try {
      prefilter_line(c.data(), n, 1, sampled_kernel(f), edge);
    } catch (const std::invalid_argument& e) {
      r.fail("interpolating", e.what());
    }
  }
  const long count = static_cast<long>(std::floor((t1 - t0) / step + 1e-9));
  for (long i = 0; i <= count; ++i) {
    const double t = t0 + double(i) * step;
    double num = 0, den = 0;
    for (double j = std::ceil(t - f.support().hi); j <= std::floor(t - f.support().lo); j += 1) {
      const double k = f(t - j);
      den += k;
      const long q = edge_index(static_cast<long>(j), n, edge);
      if (q >= 0) num += k * c[static_cast<size_t>(q)];
    }
    s.points.push_back({t, num / den});
  }
  return s;
}

// A zone plate z = 1/2 + 1/2 cos(pi r^2 / N) sampled at the centres of N x N pixels (r from the
// image centre, in pixels): its local frequency r/N reaches Nyquist at the edges' midpoints and
// passes it towards the corners. Resampled to `size` with the filter and cropped.
ImageElement parse_zoneplate(TableReader& r) {
  const Kernel f = filter_key(r);
  const int n = r.integer("source", 64, 2, 4096);
  const int size = r.integer("size", 8 * n, 1, 4096);
  ResampleOptions opt;
  opt.edge = edge_key(r, "mirror");
  opt.interpolating = r.boolean("interpolating", false);
  std::array<int, 4> crop{0, 0, size, size};
  if (r.has("crop")) {
    auto v = r.numbers("crop");
    if (v.size() != 4) r.fail("crop", "expected [x, y, width, height] in output pixels");
    for (size_t i = 0; i < 4; ++i) crop[i] = static_cast<int>(v[i]);
    if (crop[0] < 0 || crop[1] < 0 || crop[2] < 1 || crop[3] < 1 || crop[0] + crop[2] > size || crop[1] + crop[3] > size)
      r.fail("crop", "must lie inside the " + std::to_string(size) + "x" + std::to_string(size) + " output");
  }
  ImageElement im;
  auto ext = r.numbers("extent");
  if (ext.empty()) ext = {0, double(crop[2]), 0, double(crop[3])};
  if (ext.size() != 4 || ext[0] == ext[1] || ext[2] == ext[3])
    r.fail("extent", "expected extent = [x0, x1, y0, y1] with x0 != x1, y0 != y1");
  im.extent = {ext[0], ext[1], ext[2], ext[3]};
  im.raster.nearest = r.choice("interpolation", {"nearest", "bilinear"}, 0) == 0;
  // Shown as 1/2 + contrast (v - 1/2): a contrast above 1 makes faint aliasing visible.
  const double contrast = r.positive("contrast", 1);

  Image src(n, n, 1);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double dx = x + 0.5 - n / 2.0, dy = y + 0.5 - n / 2.0;
      src.at(x, y, 0) = static_cast<float>(0.5 + 0.5 * std::cos(kPi * (dx * dx + dy * dy) / n));
    }
  Image out;
  try {
    out = resample(src, size, size, f, opt);
  } catch (const std::invalid_argument& e) {
    r.fail("filter", e.what());
  }
  im.raster.width = crop[2];
  im.raster.height = crop[3];
  im.raster.channels = 1;
  for (int y = crop[1]; y < crop[1] + crop[3]; ++y)
    for (int x = crop[0]; x < crop[0] + crop[2]; ++x) im.raster.data.push_back(
          static_cast<float>(std::clamp(0.5 + contrast * (out.at(x, y, 0) - 0.5), 0.0, 1.0)));
  return im;
}

}  // namespace

void parse_filter_elements(TableReader& r, const ParseContext& ctx,
                           std::vector<std::pair<size_t, PlotElement>>& elements) {
  (void)ctx;
  auto each = [&](std::string_view key, auto&& make) {
    int i = 0;
    const toml::node* n = r.node(key);
    const bool single = n && n->is_table();
    for (const toml::table* t : r.tables(key)) {
      TableReader sub(*t, r.file(), single ? r.key_path(key) : r.key_path(key) + "[" + std::to_string(i++) + "]");
      elements.emplace_back(t->source().begin.line, PlotElement{make(sub)});
      sub.finish();
    }
  };
  each("filter", [](TableReader& s) { return parse_filter_curve(s); });
  each("response", [](TableReader& s) { return parse_response(s); });
  each("step", [](TableReader& s) { return parse_step(s); });
  each("zoneplate", [](TableReader& s) { return parse_zoneplate(s); });
}

}  // namespace splinefig::figures::detail
