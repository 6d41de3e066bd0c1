// The outline of a fill under a curve, kernel or series (spec_fill.cpp), in pixels, from the
// same samples those elements are drawn with.
#include "panel.hpp"

#include <splinefig/figures/sampling.hpp>

namespace splinefig::figures::detail {
namespace {

// The pixel polyline of the element labelled `label` (check_fill_references made sure there
// is one).
std::vector<Vec2> outline(const PreparedAxes& prepared, const std::string& label, const PixelMap& map, double tol) {
  const auto& elements = prepared.axes.elements;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const PlotElement& e = elements[i];
    if (const auto* c = std::get_if<CurveElement>(&e); c && c->label.label == label)
      return sample_curve(prepared.curves.at(i), map, tol);
    if (const auto* k = std::get_if<KernelElement>(&e); k && k->label.label == label) {
      const Support sup = kernel_support(k->basis);
      const double s0 = k->range ? (*k->range)[0] : sup.lo, s1 = k->range ? (*k->range)[1] : sup.hi;
      std::vector<Vec2> all;
      for (const auto& piece : sample_kernel(k->basis, s0, s1, k->scale, map, tol))
        for (Vec2 q : piece)
          if (all.empty() || q.x != all.back().x || q.y != all.back().y) all.push_back(q);
      return all;
    }
    if (const auto* s = std::get_if<SeriesElement>(&e); s && s->look.label.label == label) {
      std::vector<Vec2> pts;
      for (Vec2 q : s->points) pts.push_back(map(q));
      return pts;
    }
  }
  return {};
}

}  // namespace

std::vector<Vec2> fill_under_polygon(const PreparedAxes& prepared, const FillElement& f, const PixelMap& map,
                                     double tol) {
  std::vector<Vec2> poly = outline(prepared, f.under, map, tol);
  if (poly.empty()) return poly;
  if (!f.to.empty()) {
    const std::vector<Vec2> lower = outline(prepared, f.to, map, tol);
    poly.insert(poly.end(), lower.rbegin(), lower.rend());
    return poly;
  }
  // On a log axis a baseline <= 0 is the bottom of the range.
  const double base = map.y.scale == Scale::Log && !(f.baseline > 0) ? map.y.p0 : map.y.to_pixel(f.baseline);
  const Vec2 first = poly.front(), last = poly.back();
  poly.push_back({last.x, base});
  poly.push_back({first.x, base});
  return poly;
}

}  // namespace splinefig::figures::detail
