// Panel layout: data ranges, the plot box inside the panel's cell, and the ticks.
#include "plot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace splinefig::figures::detail {
namespace {

void grow(std::array<double, 2>& b, bool& has, double v) {
  if (!std::isfinite(v)) return;
  if (!has) b = {v, v}, has = true;
  b[0] = std::min(b[0], v);
  b[1] = std::max(b[1], v);
}

}  // namespace

void data_bounds(const PreparedAxes& prepared, std::array<double, 2>& xb, std::array<double, 2>& yb, bool& hx,
                 bool& hy) {
  hx = hy = false;
  auto add = [&](Vec2 p) { grow(xb, hx, p.x), grow(yb, hy, p.y); };
  const auto& elements = prepared.axes.elements;
  for (size_t i = 0; i < elements.size(); ++i) {
    const PlotElement& e = elements[i];
    if (std::holds_alternative<CurveElement>(e)) {
      Points s = sample(prepared.curves.at(i), 32);
      for (size_t j = 0; j < s.size(); ++j) add({s[j][0], s[j][1]});
    } else if (const auto* k = std::get_if<KernelElement>(&e)) {
      Support sup = kernel_support(k->basis);
      double s0 = k->range ? (*k->range)[0] : sup.lo, s1 = k->range ? (*k->range)[1] : sup.hi;
      for (int i = 0; i <= 256; ++i) {
        double s = s0 + (s1 - s0) * i / 256;
        add({s, k->scale * kernel(k->basis, s)});
      }
      add({s0, 0.0});
    } else if (const auto* s = std::get_if<SeriesElement>(&e)) {
      for (Vec2 p : s->points) add(p);
    } else if (const auto* f = std::get_if<FillElement>(&e)) {
      for (Vec2 p : f->upper) add(p);
      for (Vec2 p : f->lower) add(p);
      if (!f->under.empty() && f->to.empty() && (prepared.axes.y.scale != Scale::Log || f->baseline > 0))
        grow(yb, hy, f->baseline);
    } else if (const auto* im = std::get_if<ImageElement>(&e)) {
      add({im->extent[0], im->extent[2]});
      add({im->extent[1], im->extent[3]});
    } else if (const auto* r = std::get_if<RuleElement>(&e)) {
      if (r->horizontal) grow(yb, hy, r->value);
      else grow(xb, hx, r->value);
    }
  }
}

namespace {

std::array<double, 2> auto_range(const AxisSpec& axis, std::array<double, 2> b, bool has) {
  if (axis.range) return *axis.range;
  if (!has) return axis.scale == Scale::Log ? std::array<double, 2>{1, 10} : std::array<double, 2>{0, 1};
  if (axis.scale == Scale::Log) {
    double lo = std::log10(std::max(b[0], 1e-300)), hi = std::log10(std::max(b[1], 1e-300));
    if (hi - lo < 1e-12) lo -= 0.5, hi += 0.5;
    return {std::pow(10.0, std::floor(lo)), std::pow(10.0, std::ceil(hi))};
  }
  if (axis.scale == Scale::Decibel) {
    auto db = [](double v) { return 20 * std::log10(std::max(std::abs(v), 1e-15)); };
    b = {std::min(db(b[0]), db(b[1])), std::max(db(b[0]), db(b[1]))};
  }
  double span = b[1] - b[0];
  if (span <= 0) span = std::max(1.0, std::abs(b[0]));
  return {b[0] - 0.05 * span, b[1] + 0.05 * span};
}

// Minor ticks of a log axis whose ticks are every decade (not given, not thinned out, not the
// nice ticks of a range under one decade): 2, 3, ..., 9 times each power of ten in the range.
std::vector<double> log_minor_ticks(const AxisSpec& axis, const std::vector<Tick>& majors, const AxisMap& m) {
  if (axis.scale != Scale::Log || axis.ticks || majors.size() < 2) return {};
  for (size_t i = 0; i + 1 < majors.size(); ++i)
    if (std::abs(std::log10(majors[i + 1].value / majors[i].value) - 1) > 1e-9) return {};
  const double lo = std::min(m.d0, m.d1), hi = std::max(m.d0, m.d1);
  std::vector<double> minor;
  for (int k = static_cast<int>(std::floor(std::log10(lo))); k <= static_cast<int>(std::ceil(std::log10(hi))); ++k)
    for (int f = 2; f <= 9; ++f) {
      const double v = f * std::pow(10.0, k);
      if (v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12)) minor.push_back(v);
    }
  return minor;
}

std::vector<Tick> make_ticks(const AxisSpec& axis, char name, const std::array<double, 2>& range, double pixels,
                             double spacing) {
  if (axis.ticks) {
    std::vector<Tick> t;
    for (size_t i = 0; i < axis.ticks->size(); ++i) {
      double v = (*axis.ticks)[i];
      std::string label = i < axis.tick_labels.size() ? axis.tick_labels[i] : "";
      if (label.empty() && axis.tick_labels.empty()) {
        // Label explicit ticks with the digits their spacing needs.
        double step = axis.ticks->size() > 1 ? std::abs((*axis.ticks)[1] - (*axis.ticks)[0]) : 1;
        int decimals = step > 0 ? std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9))) : 0;
        for (double w : *axis.ticks) {
          double f = w * std::pow(10.0, decimals);
          while (decimals < 6 && std::abs(f - std::round(f)) > 1e-6) ++decimals, f = w * std::pow(10.0, decimals);
        }
        label = tick_number(v, decimals);
      }
      t.push_back({v, label});
    }
    return t;
  }
  if (axis.scale == Scale::Log) return log_ticks(range[0], range[1]);
  double target = std::clamp(std::abs(pixels) / spacing, 2.0, 12.0);
  std::vector<Tick> ticks;
  try {
    ticks = nice_ticks(range[0], range[1], target, axis.tick_step.value_or(0));
  } catch (const std::invalid_argument& e) {
    throw KeyError(std::string(1, name) + (axis.tick_step ? "_tick_step" : "_range"), e.what());
  }
  if (axis.scale == Scale::Decibel)
    for (auto& t : ticks) t.label += " dB";
  return ticks;
}

// Widens the range of whichever axis has more pixels per unit, so both scales agree.
void equalize(std::array<double, 2>& xr, std::array<double, 2>& yr, double w, double h) {
  double sx = w / std::abs(xr[1] - xr[0]), sy = h / std::abs(yr[1] - yr[0]);
  if (sx > sy) {
    double half = 0.5 * w / sy, mid = 0.5 * (xr[0] + xr[1]), sign = xr[1] > xr[0] ? 1 : -1;
    xr = {mid - sign * half, mid + sign * half};
  } else {
    double half = 0.5 * h / sx, mid = 0.5 * (yr[0] + yr[1]), sign = yr[1] > yr[0] ? 1 : -1;
    yr = {mid - sign * half, mid + sign * half};
  }
}

}  // namespace

std::vector<std::string> legend_labels(const AxesSpec& ax) {
  std::vector<std::string> labels;
  auto add = [&](const Labelling& l) {
    if (!l.label.empty() && l.in_legend) labels.push_back(l.label);
  };
  for (const PlotElement& e : ax.elements)
    std::visit(
        [&](const auto& el) {
          if constexpr (requires { el.label.in_legend; }) add(el.label);
          if constexpr (requires { el.look.label.in_legend; }) add(el.look.label);
        },
        e);
  return labels;
}

double tick_pixel(const AxisMap& m, double value) {
  if (m.scale == Scale::Decibel) return m.p0 + (value - m.d0) / (m.d1 - m.d0) * (m.p1 - m.p0);
  return m.to_pixel(value);
}

Panel layout_panel(const PreparedAxes& prepared, const Rect& cell, const Painter& p, const Guides& g) {
  const AxesSpec& ax = prepared.axes;
  std::array<double, 2> xb{}, yb{};
  bool hx, hy;
  data_bounds(prepared, xb, yb, hx, hy);
  const std::array<double, 2> xr0 = auto_range(ax.x, xb, hx), yr0 = auto_range(ax.y, yb, hy);

  const bool guides = ax.frame != Frame::None;
  const render::TextExtent digit = p.measure("0", g.tick_font);
  const double tick_h = digit.ascent + digit.descent;
  // A rotated y label takes a strip at the left: its ink height and a gap.
  double ylabel_h = 0;
  if (!ax.y.label.empty() && ax.y.label_rotated) {
    const render::TextExtent e = p.measure(ax.y.label, g.label_font);
    ylabel_h = e.ascent + e.descent + 8;
  }
  Panel panel;
  Rect box = cell;
  if (ax.box) {
    box = {(*ax.box)[0], (*ax.box)[1], (*ax.box)[2], (*ax.box)[3]};
  }
  // A legend outside the box on the right takes its width (and the gap) from the cell.
  double legend_room = 0;
  if (ax.legend == LegendPlace::OutsideRight && !ax.box) {
    const std::vector<std::string> labels = legend_labels(ax);
    if (!labels.empty()) legend_room = legend_size(ax, labels, p, g)[0] + kLegendOutsideGap;
  }
  std::array<double, 2> xr = xr0, yr = yr0;
  // A range from the data (or widened for equal aspect) is checked as a given one is.
  auto check_range = [](const AxisSpec& axis, char name, const std::array<double, 2>& r) {
    const std::string why = range_problem(r[0], r[1]);
    if (!why.empty())
      throw KeyError(std::string(1, name) + "_range", why + (axis.range ? "" : " (from the data)"));
  };
  for (int pass = 0; pass < 3; ++pass) {
    xr = xr0, yr = yr0;
    if (ax.equal_aspect) equalize(xr, yr, box.width(), box.height());
    check_range(ax.x, 'x', xr);
    check_range(ax.y, 'y', yr);
    panel.x_ticks = make_ticks(ax.x, 'x', xr, box.width(), 90);
    panel.y_ticks = make_ticks(ax.y, 'y', yr, box.height(), 55);
    if (ax.box) break;
    double ylabel_w = 0, xlabel_last = 0;
    if (guides) {
      for (const auto& t : panel.y_ticks) ylabel_w = std::max(ylabel_w, p.measure(t.label, g.tick_font).width);
      if (!panel.x_ticks.empty()) xlabel_last = p.measure(panel.x_ticks.back().label, g.tick_font).width;
    }
    const bool ylabel_above = !ax.y.label.empty() && !ax.y.label_rotated;
    double top = cell.top + (ax.title.empty() ? 0 : g.title_font.size + 12) + (ylabel_above ? g.label_font.size + 10 : 0);
    top = std::max(top, cell.top + (guides ? 0.5 * tick_h + 2 : 0));
    double bottom = cell.bottom - (guides ? g.tick_length + 4 + tick_h + 2 : 0) - (ax.x.label.empty() ? 0 : g.label_font.size + 10);
    double left = cell.left + (guides ? ylabel_w + g.tick_length + 6 : 0) + ylabel_h;
    double right = cell.right - std::max(guides ? std::max(4.0, 0.5 * xlabel_last) : 0, legend_room);
    box = {std::round(left), std::round(top), std::round(right), std::round(bottom)};
    if (box.width() < 10 || box.height() < 10) box = cell;
  }
  panel.box = box;
  panel.x_range = xr;
  panel.y_range = yr;
  panel.map.x = {ax.x.scale, xr[0], xr[1], box.left, box.right, 'x'};
  panel.map.y = {ax.y.scale, yr[0], yr[1], box.bottom, box.top, 'y'};
  // Ticks outside the (possibly widened) range are dropped.
  auto inside = [](const AxisMap& m, const Tick& t, double a, double b) {
    double v = tick_pixel(m, t.value);
    return v >= std::min(a, b) - 0.01 && v <= std::max(a, b) + 0.01;
  };
  std::erase_if(panel.x_ticks, [&](const Tick& t) { return !inside(panel.map.x, t, box.left, box.right); });
  std::erase_if(panel.y_ticks, [&](const Tick& t) { return !inside(panel.map.y, t, box.top, box.bottom); });
  panel.x_minor = log_minor_ticks(ax.x, panel.x_ticks, panel.map.x);
  panel.y_minor = log_minor_ticks(ax.y, panel.y_ticks, panel.map.y);
  return panel;
}

}  // namespace splinefig::figures::detail
