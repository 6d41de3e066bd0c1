// Panel layout: data ranges, the plot box inside the panel's cell, and the ticks.
#include "panel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
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
  const bool log = axis.scale == Scale::Log;
  std::vector<Tick> ticks;
  try {
    if (log) return log_ticks(range[0], range[1]);
    ticks = nice_ticks(range[0], range[1], std::clamp(std::abs(pixels) / spacing, 2.0, 12.0), axis.tick_step.value_or(0));
  } catch (const TickError& e) {
    throw KeyError(std::string(1, name) + (axis.tick_step && !log ? "_tick_step" : "_range"), e.what());
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

int legend_rows(int columns, std::size_t entries) {
  const std::size_t cols = static_cast<std::size_t>(std::max(1, columns));
  return static_cast<int>(std::max<std::size_t>(1, (entries + cols - 1) / cols));
}

int legend_columns_used(int columns, std::size_t entries) {
  const std::size_t rows = static_cast<std::size_t>(legend_rows(columns, entries));
  return static_cast<int>(std::max<std::size_t>(1, (entries + rows - 1) / rows));
}

std::array<double, 2> legend_size(const AxesSpec& ax, const std::vector<std::string>& labels, const TextMeasure& p,
                                  const Guides& g) {
  const Font& f = g.legend_font;
  double text_w = 0;
  for (const auto& l : labels) text_w = std::max(text_w, p.measure(l, f).width);
  Font tf = f;
  tf.bold = true;
  double title_h = 0;
  if (!ax.legend_title.empty()) {
    text_w = std::max(text_w, p.measure(ax.legend_title, tf).width - kLegendSample - kLegendGap);
    title_h = legend_row(g);
  }
  const int cols = legend_columns_used(ax.legend_columns, labels.size());
  const int rows = legend_rows(ax.legend_columns, labels.size());
  const double col_w = kLegendSample + kLegendGap + text_w + kLegendColumnGap;
  return {std::ceil(kLegendPad + cols * col_w - kLegendColumnGap + kLegendPad),
          std::ceil(kLegendPad + title_h + legend_row(g) * rows + kLegendPad - 4)};
}

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

Rect text_rect(const render::TextExtent& e, Vec2 at, TextAnchor a, double angle) {
  double ox = 0, oy = 0;  // as the painter aligns a label (painter.cpp, draw_text)
  if (a.halign == render::HAlign::Center) ox = -0.5 * e.width;
  else if (a.halign == render::HAlign::Right) ox = -e.width;
  if (a.valign == render::VAlign::Top) oy = e.ascent;
  else if (a.valign == render::VAlign::Middle) oy = 0.5 * (e.ascent - e.descent);
  else if (a.valign == render::VAlign::Bottom) oy = -e.descent;
  // In the label's frame (y down) it covers [ox, ox + width] x [oy - ascent, oy + descent].
  const double u0 = ox, u1 = ox + e.width, v0 = oy - e.ascent, v1 = oy + e.descent;
  if (angle == 0) return {at.x + u0, at.y + v0, at.x + u1, at.y + v1};
  const double r = angle * std::numbers::pi / 180;
  const double c = angle == 90 ? 0.0 : std::cos(r), sn = angle == 90 ? 1.0 : std::sin(r);
  Rect out{1e300, 1e300, -1e300, -1e300};
  for (double u : {u0, u1})
    for (double v : {v0, v1}) {
      const double x = at.x + c * u + sn * v, y = at.y - sn * u + c * v;
      out = {std::min(out.left, x), std::min(out.top, y), std::max(out.right, x), std::max(out.bottom, y)};
    }
  return out;
}

bool rects_meet(const Rect& a, const Rect& b, double gap) {
  return a.left < b.right + gap && b.left < a.right + gap && a.top < b.bottom + gap && b.top < a.bottom + gap;
}

namespace {

// Text smaller than this is not made by shrinking a title or an axis label.
constexpr double kMinTextSize = 9;

PlacedText placed(std::string what, const std::string& text, Vec2 at, const Font& f, TextAnchor a, const TextMeasure& p,
                  double angle = 0) {
  PlacedText t{std::move(what), text, at, f, a, angle, {}};
  t.rect = text.empty() ? Rect{at.x, at.y, at.x, at.y} : text_rect(p.measure(text, f), at, a, angle);
  return t;
}

PlacedText x_tick_text(const Tick& t, double x, const Rect& b, const TextMeasure& p, const Guides& g) {
  return placed("x tick label", t.label, {x, b.bottom + 1 + g.tick_length + 3}, g.tick_font,
                {render::HAlign::Center, render::VAlign::Top}, p);
}
PlacedText y_tick_text(const Tick& t, double y, const Rect& b, const TextMeasure& p, const Guides& g) {
  return placed("y tick label", t.label, {b.left - 1 - g.tick_length - 4, y}, g.tick_font,
                {render::HAlign::Right, render::VAlign::Middle}, p);
}

struct AxisSide {
  const AxisSpec& spec;
  char name;  // 'x' or 'y'
  std::array<double, 2> range;
  AxisMap map(const Rect& b) const {
    return name == 'x' ? AxisMap{spec.scale, range[0], range[1], b.left, b.right, 'x'}
                       : AxisMap{spec.scale, range[0], range[1], b.bottom, b.top, 'y'};
  }
};

// The labelled ticks' texts inside the box, in order along the axis.
std::vector<PlacedText> tick_texts(const AxisSide& side, const std::vector<Tick>& ticks, const Rect& b,
                                   const TextMeasure& p, const Guides& g) {
  const AxisMap m = side.map(b);
  const double lo = std::min(m.p0, m.p1) - 0.01, hi = std::max(m.p0, m.p1) + 0.01;
  std::vector<std::pair<double, PlacedText>> at;
  for (const Tick& t : ticks) {
    if (t.label.empty()) continue;
    const double v = tick_pixel(m, t.value);
    if (!(v >= lo && v <= hi)) continue;
    at.emplace_back(v, side.name == 'x' ? x_tick_text(t, v, b, p, g) : y_tick_text(t, v, b, p, g));
  }
  std::sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<PlacedText> out;
  for (auto& [v, t] : at) out.push_back(std::move(t));
  return out;
}

// Whether two neighbouring tick labels come closer than kTickLabelGap.
bool tick_labels_meet(const AxisSide& side, const std::vector<Tick>& ticks, const Rect& b, const TextMeasure& p,
                      const Guides& g) {
  const std::vector<PlacedText> t = tick_texts(side, ticks, b, p, g);
  for (size_t i = 0; i + 1 < t.size(); ++i) {
    const Rect &r = t[i].rect, &s = t[i + 1].rect;
    if (side.name == 'x' ? r.right + kTickLabelGap > s.left : r.bottom + kTickLabelGap > s.top) return true;
  }
  return false;
}

size_t labelled(const std::vector<Tick>& ticks) {
  return static_cast<size_t>(std::count_if(ticks.begin(), ticks.end(), [](const Tick& t) { return !t.label.empty(); }));
}

// Coarser sets of ticks, finest first, each with at least two labels: automatic ticks of a
// linear or dB axis take the next steps of 1, 2, 5 times a power of ten; ticks that are
// given, forced by a tick step, or at the decades of a log axis keep every k-th.
std::vector<std::vector<Tick>> coarser_ticks(const AxisSide& side, const std::vector<Tick>& ticks) {
  std::vector<std::vector<Tick>> out;
  const AxisSpec& axis = side.spec;
  if (!axis.ticks && !axis.tick_step && axis.scale != Scale::Log && ticks.size() >= 2) {
    double step = std::abs(ticks[1].value - ticks[0].value);
    for (int i = 0; i < 40 && std::isfinite(step) && step > 0; ++i) {
      const double p10 = std::pow(10.0, std::floor(std::log10(step) + 1e-9)), m = step / p10;
      step = (m < 1.5 ? 2 : m < 3.5 ? 5 : 10) * p10;
      std::vector<Tick> t = nice_ticks(side.range[0], side.range[1], 0, step);
      if (axis.scale == Scale::Decibel)
        for (auto& k : t) k.label += " dB";
      if (labelled(t) < 2) break;
      out.push_back(std::move(t));
    }
    return out;
  }
  for (size_t k = 2; k < ticks.size(); ++k) {
    std::vector<Tick> t;
    for (size_t i = 0; i < ticks.size(); i += k) t.push_back(ticks[i]);
    if (labelled(t) < 2) break;
    out.push_back(std::move(t));
  }
  return out;
}

// The ticks, or the first coarser set whose labels stay apart in this box (the coarsest if
// none does: the layout then refuses).
std::vector<Tick> thin_ticks(const AxisSide& side, const std::vector<Tick>& ticks, const Rect& b, const TextMeasure& p,
                             const Guides& g) {
  if (!tick_labels_meet(side, ticks, b, p, g)) return ticks;
  const std::vector<std::vector<Tick>> coarser = coarser_ticks(side, ticks);
  for (const auto& t : coarser)
    if (!tick_labels_meet(side, t, b, p, g)) return t;
  return coarser.empty() ? ticks : coarser.back();
}

// The least length of the axis (layout units) at which the coarsest set of ticks keeps its
// neighbouring labels apart.
double tick_length_needed(const AxisSide& side, const std::vector<Tick>& ticks, const TextMeasure& p, const Guides& g) {
  const std::vector<std::vector<Tick>> coarser = coarser_ticks(side, ticks);
  const std::vector<Tick>& t = coarser.empty() ? ticks : coarser.back();
  const AxisMap m = side.map({0, 0, 1, 1});  // unit length: pixel = fraction of the axis
  std::vector<std::pair<double, double>> at;  // (fraction along the axis, label extent)
  for (const Tick& k : t) {
    if (k.label.empty()) continue;
    const double f = tick_pixel(m, k.value), lo = std::min(m.p0, m.p1), hi = std::max(m.p0, m.p1);
    if (!(f >= lo - 1e-9 && f <= hi + 1e-9)) continue;
    const render::TextExtent e = p.measure(k.label, g.tick_font);
    at.emplace_back(f, side.name == 'x' ? e.width : e.ascent + e.descent);
  }
  std::sort(at.begin(), at.end());
  double need = 0;
  for (size_t i = 0; i + 1 < at.size(); ++i) {
    const double df = at[i + 1].first - at[i].first;
    if (df > 0) need = std::max(need, (0.5 * (at[i].second + at[i + 1].second) + kTickLabelGap) / df);
  }
  return std::ceil(need);
}

std::string px(double v) { return std::to_string(static_cast<long long>(std::ceil(std::max(0.0, v) - 1e-9))); }

// Shifts a text along x (or y) into [lo, hi], shrinking its font first if it is longer than
// that (not below kMinTextSize). False if it cannot fit.
bool fit_text(PlacedText& t, double lo, double hi, bool along_x, const TextMeasure& p) {
  if (t.text.empty()) return true;
  auto extent = [&] { return along_x ? t.rect.width() : t.rect.height(); };
  if (extent() > hi - lo) {
    const double size = std::floor(2 * t.font.size * (hi - lo) / extent()) / 2;
    if (size < kMinTextSize) return false;
    t.font.size = size;
    t = placed(t.what, t.text, t.at, t.font, t.anchor, p, t.angle);
    while (extent() > hi - lo && t.font.size - 0.5 >= kMinTextSize) {
      t.font.size -= 0.5;
      t = placed(t.what, t.text, t.at, t.font, t.anchor, p, t.angle);
    }
    if (extent() > hi - lo) return false;
  }
  const double a = along_x ? t.rect.left : t.rect.top, b = along_x ? t.rect.right : t.rect.bottom;
  const double shift = a < lo ? lo - a : b > hi ? hi - b : 0;
  if (shift != 0) {
    (along_x ? t.at.x : t.at.y) += shift;
    (along_x ? t.rect.left : t.rect.top) += shift;
    (along_x ? t.rect.right : t.rect.bottom) += shift;
  }
  return true;
}

}  // namespace

Panel layout_panel(const PreparedAxes& prepared, const Rect& cell, double canvas_w, double canvas_h, const TextMeasure& p,
                   const Guides& g) {
  const AxesSpec& ax = prepared.axes;
  std::array<double, 2> xb{}, yb{};
  bool hx, hy;
  data_bounds(prepared, xb, yb, hx, hy);
  const std::array<double, 2> xr0 = auto_range(ax.x, xb, hx), yr0 = auto_range(ax.y, yb, hy);

  const bool guides = ax.frame != Frame::None;
  const render::TextExtent digit = p.measure("0", g.tick_font);
  const double tick_h = digit.ascent + digit.descent;
  auto ink_height = [&](const std::string& s, const Font& f) {
    if (s.empty()) return 0.0;
    const render::TextExtent e = p.measure(s, f);
    return e.ascent + e.descent;
  };
  // A rotated y label takes a strip at the left: its ink height and a gap.
  double ylabel_h = 0;
  if (!ax.y.label.empty() && ax.y.label_rotated) ylabel_h = ink_height(ax.y.label, g.label_font) + 8;
  const bool ylabel_above = !ax.y.label.empty() && !ax.y.label_rotated;
  const double title_h = ink_height(ax.title, g.title_font), xlabel_h = ink_height(ax.x.label, g.label_font);
  const double above_h = ylabel_above ? ink_height(ax.y.label, g.label_font) : 0;
  Panel panel;
  Rect box = cell;
  if (ax.box) {
    box = {(*ax.box)[0], (*ax.box)[1], (*ax.box)[2], (*ax.box)[3]};
  }
  // A legend outside the box on the right takes its width (and the gap) from the cell.
  const std::vector<std::string> legend_texts = ax.legend == LegendPlace::None ? std::vector<std::string>{} : legend_labels(ax);
  const std::array<double, 2> legend_wh =
      legend_texts.empty() ? std::array<double, 2>{0, 0} : legend_size(ax, legend_texts, p, g);
  const bool legend_outside = ax.legend == LegendPlace::OutsideRight && !legend_texts.empty();
  const double legend_room = legend_outside && !ax.box ? legend_wh[0] + kLegendOutsideGap : 0;
  std::array<double, 2> xr = xr0, yr = yr0;
  // A range from the data (or widened for equal aspect) is checked as a given one is.
  auto check_range = [](const AxisSpec& axis, char name, const std::array<double, 2>& r) {
    const std::string why = range_problem(r[0], r[1]);
    if (!why.empty())
      throw KeyError(std::string(1, name) + "_range", why + (axis.range ? "" : " (from the data)"));
  };
  auto thin = [&](const Rect& b) {
    if (!guides) return;
    panel.x_ticks = thin_ticks({ax.x, 'x', xr}, panel.x_ticks, b, p, g);
    panel.y_ticks = thin_ticks({ax.y, 'y', yr}, panel.y_ticks, b, p, g);
  };
  for (int pass = 0; pass < 3; ++pass) {
    xr = xr0, yr = yr0;
    if (ax.equal_aspect) equalize(xr, yr, std::max(1.0, box.width()), std::max(1.0, box.height()));
    check_range(ax.x, 'x', xr);
    check_range(ax.y, 'y', yr);
    panel.x_ticks = make_ticks(ax.x, 'x', xr, box.width(), 90);
    panel.y_ticks = make_ticks(ax.y, 'y', yr, box.height(), 55);
    if (ax.box) break;
    // Tick labels that would meet in this box are thinned before the box makes room for them.
    thin(box);
    double ylabel_w = 0, xlabel_last = 0, xtick_h = 0, ytick_h = 0;
    if (guides) {
      for (const auto& t : panel.y_ticks) {
        ylabel_w = std::max(ylabel_w, p.measure(t.label, g.tick_font).width);
        ytick_h = std::max(ytick_h, ink_height(t.label, g.tick_font));
      }
      for (const auto& t : panel.x_ticks) xtick_h = std::max(xtick_h, ink_height(t.label, g.tick_font));
      if (!panel.x_ticks.empty()) xlabel_last = p.measure(panel.x_ticks.back().label, g.tick_font).width;
    }
    double top = cell.top + (ax.title.empty() ? 0 : g.title_font.size + 12) + (ylabel_above ? g.label_font.size + 10 : 0);
    top = std::max(top, cell.top + (guides ? 0.5 * tick_h + 2 : 0));
    double bottom = cell.bottom - (guides ? g.tick_length + 4 + tick_h + 2 : 0) - (ax.x.label.empty() ? 0 : g.label_font.size + 10);
    double left = cell.left + (guides ? ylabel_w + g.tick_length + 6 : 0) + ylabel_h;
    double right = cell.right - std::max(guides ? std::max(4.0, 0.5 * xlabel_last) : 0, legend_room);
    // The measured texts must also fit: a title, a y label above the box or the top tick
    // label below each other, the x tick labels above the x label and inside the canvas.
    const double below_title = cell.top + (ax.title.empty() ? 0 : title_h + kTextGap);
    top = std::max(top, below_title + (ylabel_above ? above_h + 8 : guides ? 0.5 * ytick_h : 0));
    if (guides && xtick_h > 0)
      bottom = std::min(bottom, (ax.x.label.empty() ? canvas_h : cell.bottom - xlabel_h - kTextGap) - xtick_h -
                                    g.tick_length - 4);
    box = {std::round(left), std::round(top), std::round(right), std::round(bottom)};
    if (box.width() < 1 || box.height() < 1) break;  // refused below
  }
  if (box.width() >= 1 && box.height() >= 1) thin(box);
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

  // ---- The texts, placed where they are drawn, then checked against each other ----------
  const Rect& b = box;
  std::string problem;  // the first text that does not fit, and why
  if (guides) {
    for (const Tick& t : panel.x_ticks) panel.x_tick_labels.push_back(x_tick_text(t, tick_pixel(panel.map.x, t.value), b, p, g));
    for (const Tick& t : panel.y_ticks) panel.y_tick_labels.push_back(y_tick_text(t, tick_pixel(panel.map.y, t.value), b, p, g));
  }
  auto fit = [&](PlacedText t, double lo, double hi, bool along_x, const char* room) {
    if (!fit_text(t, lo, hi, along_x, p) && problem.empty())
      problem = "its " + t.what + " needs " + px(along_x ? t.rect.width() : t.rect.height()) + " px " + room + ", the " +
                (along_x ? "cell has " : "space beside the box has ") + px(hi - lo);
    panel.labels.push_back(std::move(t));
    return panel.labels.back().rect;
  };
  std::optional<Rect> title_rect, xlabel_rect;
  if (!ax.title.empty())
    title_rect = fit(placed("title", ax.title, {0.5 * (b.left + b.right), cell.top}, g.title_font,
                            {render::HAlign::Center, render::VAlign::Top}, p),
                     cell.left, cell.right, true, "across");
  if (!ax.x.label.empty())
    xlabel_rect = fit(placed("x label", ax.x.label, {0.5 * (b.left + b.right), cell.bottom}, g.label_font,
                             {render::HAlign::Center, render::VAlign::Bottom}, p),
                      cell.left, cell.right, true, "across");
  if (ylabel_above) {
    fit(placed("y label", ax.y.label, {std::max(cell.left, b.left - 30), b.top - 8}, g.label_font,
               {render::HAlign::Left, render::VAlign::Bottom}, p),
        cell.left, cell.right, true, "across");
  } else if (!ax.y.label.empty()) {
    // Turned a quarter to read upwards, centred on the box, its ink starting at the cell's
    // left edge (the layout keeps that strip free); kept clear of the title, the x label and
    // the x tick labels where they reach over that strip.
    PlacedText t = placed("y label", ax.y.label, {cell.left, 0.5 * (b.top + b.bottom)}, g.label_font,
                          {render::HAlign::Center, render::VAlign::Top}, p, 90);
    double lo = cell.top, hi = cell.bottom;
    auto reaches = [&](const Rect& r) { return r.left < t.rect.right + kTextGap && r.right > t.rect.left - kTextGap; };
    if (title_rect && reaches(*title_rect)) lo = std::max(lo, title_rect->bottom + kTextGap);
    if (xlabel_rect && reaches(*xlabel_rect)) hi = std::min(hi, xlabel_rect->top - kTextGap);
    for (const PlacedText& x : panel.x_tick_labels)
      if (!x.text.empty() && reaches(x.rect)) hi = std::min(hi, x.rect.top - kTextGap);
    fit(std::move(t), lo, hi, false, "high");
  }
  // Drawn in this order: the x label, the y label, the title.
  auto rank = [](const PlacedText& t) { return t.what == "x label" ? 0 : t.what == "y label" ? 1 : 2; };
  std::stable_sort(panel.labels.begin(), panel.labels.end(),
                   [&](const PlacedText& a, const PlacedText& c) { return rank(a) < rank(c); });
  if (legend_outside)
    panel.legend = Rect{b.right + kLegendOutsideGap, b.top, b.right + kLegendOutsideGap + legend_wh[0], b.top + legend_wh[1]};

  // ---- The checks: a big enough box, every text inside the canvas and apart ----------------
  // A panel without guides (an image tile) needs only a pixel.
  double need_w = guides ? kMinPlotBox : 1, need_h = guides ? kMinPlotBox : 1;
  std::string need_why;
  auto need = [&](double w, double h, const std::string& why) {
    if (w > need_w || h > need_h) need_why = why;
    need_w = std::max(need_w, w), need_h = std::max(need_h, h);
  };
  if (guides) {
    const AxisSide xs{ax.x, 'x', xr}, ys{ax.y, 'y', yr};
    need(tick_length_needed(xs, panel.x_ticks, p, g), 0, "for its x tick labels");
    need(0, tick_length_needed(ys, panel.y_ticks, p, g), "for its y tick labels");
    if (problem.empty() && tick_labels_meet(xs, panel.x_ticks, b, p, g)) problem = "its x tick labels would meet";
    if (problem.empty() && tick_labels_meet(ys, panel.y_ticks, b, p, g)) problem = "its y tick labels would meet";
  }
  if (!legend_texts.empty() && !legend_outside)
    need(legend_wh[0] + kLegendInset, legend_wh[1] + kLegendInset, "for its legend");
  const bool small = box.width() < need_w || box.height() < need_h;
  if (!small && problem.empty()) {
    std::vector<std::pair<std::string, Rect>> all;
    for (const auto* v : {&panel.x_tick_labels, &panel.y_tick_labels, &panel.labels})
      for (const PlacedText& t : *v)
        if (!t.text.empty()) all.emplace_back(t.what, t.rect);
    if (panel.legend) all.emplace_back("legend", *panel.legend);
    const Rect canvas{0, 0, canvas_w, canvas_h};
    for (size_t i = 0; i < all.size() && problem.empty(); ++i) {
      const Rect& r = all[i].second;
      if (r.left < canvas.left || r.top < canvas.top || r.right > canvas.right || r.bottom > canvas.bottom)
        problem = "its " + all[i].first + " would leave the canvas";
      for (size_t j = i + 1; j < all.size() && problem.empty(); ++j)
        if (rects_meet(r, all[j].second)) problem = "its " + all[i].first + " would meet its " + all[j].first;
    }
  }
  if (small || !problem.empty()) {
    std::string msg = "the canvas " + px(canvas_w) + "x" + px(canvas_h) + " leaves a plot box of " + px(box.width()) +
                      " x " + px(box.height()) + " px after its labels; it needs at least " + px(need_w) + " x " +
                      px(need_h) + " px";
    if (small) msg += need_why.empty() ? "" : " " + need_why;
    else msg += ", and room: " + problem;
    throw LayoutRefused(msg);
  }
  return panel;
}

}  // namespace splinefig::figures::detail
