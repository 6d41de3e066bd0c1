// The figure spec loader, part 3: the generated plot elements (spec.hpp), read as plain
// parameters. Their data is computed by the layout (generated.cpp), at the output scale.
#include "spec_parse.hpp"

#include <splinefig/base/limits.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <algorithm>
#include <cmath>

namespace splinefig::figures::detail {
namespace {

std::vector<Vec2> required_points(TableReader& r, const char* key, std::size_t minimum, const char* what) {
  std::vector<Vec2> p = r.points(key);
  if (p.size() < minimum)
    r.fail(key, std::string(what) + " needs at least " + std::to_string(minimum) + " points, got " +
                    std::to_string(p.size()));
  return p;
}

std::optional<std::array<double, 2>> opt_range(TableReader& r, const char* expected) {
  if (!r.has("range")) return std::nullopt;
  auto v = r.numbers("range");
  if (v.size() != 2 || !(v[0] < v[1])) r.fail("range", expected);
  return std::array<double, 2>{v[0], v[1]};
}

Kernel filter_key(TableReader& r) {
  auto spec = r.opt_string("filter");
  if (!spec) r.fail("filter", "needs filter = \"SPEC\" (a basis spec, box, tent or lanczos3)");
  return kernel_value(r, "filter", *spec);
}

Edge edge_key(TableReader& r, const char* fallback) {
  const std::string name = r.string("edge", fallback);
  const auto edge = parse_edge(name);
  if (!edge) r.fail("edge", "'" + name + "' is not one of clamp, mirror, wrap, black");
  return *edge;
}

InterpElement parse_interp(TableReader& r) {
  InterpElement e;
  e.points = required_points(r, "points", 2, "interp");
  e.origin = r.origin("points");
  e.ends = static_cast<InterpElement::EndMode>(r.choice("ends", {"relaxed", "clamped", "periodic"}, 0));
  e.show = static_cast<InterpElement::Show>(r.choice("show", {"curve", "control", "bezier"}, 0));
  e.start_velocity = r.opt_point("start_velocity");
  e.end_velocity = r.opt_point("end_velocity");
  if (e.ends != InterpElement::EndMode::Clamped && (e.start_velocity || e.end_velocity))
    r.fail(e.start_velocity ? "start_velocity" : "end_velocity", "end velocities need ends = \"clamped\"");
  e.look = parse_series_look(r, e.show == InterpElement::Show::Curve     ? LookDefault::Curve
                                : e.show == InterpElement::Show::Control ? LookDefault::Polygon
                                                                         : LookDefault::Points);
  return e;
}

RelaxedBsplineElement parse_relaxed_bspline(TableReader& r) {
  RelaxedBsplineElement e;
  e.points = required_points(r, "points", 2, "relaxed_bspline");
  e.show = static_cast<RelaxedBsplineElement::Show>(
      r.choice("show", {"curve", "joints", "division", "bezier", "aframes"}, 0));
  if (e.show == RelaxedBsplineElement::Show::AFrames && e.points.size() < 3)
    r.fail("points", "A-frames need at least 3 control points");
  if (r.has("aframe")) {
    if (e.show != RelaxedBsplineElement::Show::AFrames) r.fail("aframe", "needs show = \"aframes\"");
    e.aframe = r.integer("aframe", 0, 1, static_cast<int>(e.points.size()) - 2);
  }
  const bool line = e.show == RelaxedBsplineElement::Show::Curve || e.show == RelaxedBsplineElement::Show::AFrames;
  e.look = parse_series_look(r, line ? LookDefault::Curve : LookDefault::Points);
  return e;
}

BezierElement parse_bezier(TableReader& r) {
  BezierElement e;
  e.points = required_points(r, "points", 2, "bezier");
  // de Casteljau's evaluation costs the square of the count per sample.
  if (e.points.size() > kMaxBezierPoints)
    r.fail("points", std::to_string(e.points.size()) + " control points (limit " + std::to_string(kMaxBezierPoints) + ")");
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

LagrangeElement parse_lagrange(TableReader& r) {
  LagrangeElement e;
  e.points = required_points(r, "points", 1, "lagrange");
  e.origin = r.origin("points");
  e.range = opt_range(r, "expected [x0, x1] with x0 < x1");
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

RelaxedBasisElement parse_relaxed_basis(TableReader& r) {
  RelaxedBasisElement e;
  e.n = r.integer("n", 4, 1, 1000);
  e.k = r.integer("k", 0, 0, e.n);
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

SubdivisionElement parse_subdivision(TableReader& r) {
  SubdivisionElement e;
  e.points = required_points(r, "points", 3, "subdivision");
  e.steps = r.integer("steps", 1, 0, 12);
  e.limit = r.choice("show", {"polygon", "limit"}, 0) == 1;
  e.look = parse_series_look(r, e.limit ? LookDefault::Points : LookDefault::Polygon);
  return e;
}

LocalBetasElement parse_local_betas(TableReader& r) {
  LocalBetasElement e;
  e.knots = required_points(r, "knots", 2, "local_betas");
  const auto rows = r.matrix("betas");
  e.origin = r.origin("betas");
  if (rows.size() != e.knots.size())
    r.fail("betas", "one [b1, b2] per knot: " + std::to_string(rows.size()) + " given for " +
                        std::to_string(e.knots.size()) + " knots");
  for (const auto& row : rows) {
    if (row.size() != 2) r.fail("betas", "each entry is [b1, b2]");
    e.betas.push_back({row[0], row[1]});
  }
  e.ends = static_cast<Ends>(r.choice("ends", {"open", "double", "closed"}, 0));
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

InbetweenElement parse_inbetween(TableReader& r) {
  // Keyframes: equally long polylines at t = 0, 1, ..., n.
  InbetweenElement e;
  const toml::node* n = r.node("frames");
  const toml::array* frames = n ? n->as_array() : nullptr;
  if (!frames || frames->size() < 2) r.fail("frames", "expected frames = [[[x, y], ...], ...], at least 2 keyframes");
  for (const toml::node& f : *frames) {
    const toml::array* pts = f.as_array();
    if (!pts || pts->empty()) r.fail_at(f, "frames", "each keyframe is a list of [x, y] points");
    if (!e.frames.empty() && pts->size() != e.frames[0].size())
      r.fail_at(f, "frames", "every keyframe needs the same number of points");
    std::vector<Vec2> frame;
    for (const toml::node& q : *pts) {
      const toml::array* xy = q.as_array();
      if (!xy || xy->size() != 2 || !(*xy)[0].is_number() || !(*xy)[1].is_number())
        r.fail_at(q, "frames", "a point is [x, y]");
      frame.push_back({(*xy)[0].value<double>().value(), (*xy)[1].value<double>().value()});
    }
    e.frames.push_back(std::move(frame));
  }
  // One frame at t, or a filmstrip of every 1/steps of a time unit.
  const auto t = r.opt_number("t");
  const double last = static_cast<double>(e.frames.size() - 1);
  const bool strip = r.has("steps");
  if (strip && t) r.fail("steps", "give either t = TIME (one frame) or steps = N (a frame every 1/N time unit), not both");
  if (!strip && !t) r.fail("t", "needs t = TIME (one frame) or steps = N (a frame every 1/N time unit)");
  if (strip) {
    e.steps = r.integer("steps", 1, 1, 64);
    if (static_cast<double>(e.steps) * last + 1 > static_cast<double>(kMaxFilmstripFrames))
      r.fail("steps", std::to_string(e.steps) + " steps over " + std::to_string(e.frames.size() - 1) +
                          " keyframe intervals draw more than " + std::to_string(kMaxFilmstripFrames) + " frames");
    e.shift = r.opt_point("shift").value_or(Vec2{0, 0});
    e.key_color = r.opt_color("key_color");
    Labelling key;
    key.label = r.label("key_label", "");
    e.key_label = key;
  } else {
    for (const char* k : {"shift", "key_color", "key_label"})
      if (r.has(k)) r.fail(k, std::string(k) + " is for a filmstrip (steps = N)");
    if (*t < 0 || *t > last)
      r.fail("t", "expected t = TIME between 0 and the last keyframe's " + std::to_string(e.frames.size() - 1));
    e.t = *t;
  }
  e.interpolation = static_cast<InbetweenElement::Interpolation>(r.choice("interpolation", {"relaxed", "linear"}, 0));
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

FilterCurveElement parse_filter_curve(TableReader& r) {
  FilterCurveElement e;
  e.filter = filter_key(r);
  e.range = opt_range(r, "expected [lo, hi] with lo < hi");
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

ResponseElement parse_response(TableReader& r) {
  ResponseElement e;
  e.filter = filter_key(r);
  e.range = opt_range(r, "expected [lo, hi] with lo < hi").value_or(e.range);
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

StepElement parse_step(TableReader& r) {
  StepElement e;
  e.filter = filter_key(r);
  if (r.has("values")) e.values = r.numbers("values");
  if (e.values.empty()) r.fail("values", "needs at least one sample");
  e.edge = edge_key(r, "clamp");
  e.interpolating = r.boolean("interpolating", false);
  e.origin = r.origin("interpolating");
  e.range = opt_range(r, "expected [lo, hi] with lo < hi");
  e.look = parse_series_look(r, LookDefault::Curve);
  return e;
}

ZoneplateElement parse_zoneplate(TableReader& r) {
  ZoneplateElement e;
  e.filter = filter_key(r);
  e.origin = r.origin("filter");
  e.source = r.integer("source", 64, 2, 4096);
  e.size = r.integer("size", 8 * e.source, 1, 4096);
  e.edge = edge_key(r, "mirror");
  e.interpolating = r.boolean("interpolating", false);
  e.crop = {0, 0, e.size, e.size};
  if (r.has("crop")) {
    auto v = r.numbers("crop");
    if (v.size() != 4) r.fail("crop", "expected [x, y, width, height] in output pixels");
    // In range before the conversion: a number past an int (3.4e10) converted to int is undefined.
    for (size_t i = 0; i < 4; ++i) {
      if (!(v[i] >= 0 && v[i] <= e.size && v[i] == std::floor(v[i])))
        r.fail("crop", "must be whole output pixels inside the " + std::to_string(e.size) + "x" + std::to_string(e.size) + " output");
      e.crop[i] = static_cast<int>(v[i]);
    }
    const auto& c = e.crop;
    if (c[0] < 0 || c[1] < 0 || c[2] < 1 || c[3] < 1 || c[0] + c[2] > e.size || c[1] + c[3] > e.size)
      r.fail("crop", "must lie inside the " + std::to_string(e.size) + "x" + std::to_string(e.size) + " output");
  }
  auto ext = r.numbers("extent");
  if (ext.empty()) ext = {0, double(e.crop[2]), 0, double(e.crop[3])};
  if (ext.size() != 4 || ext[0] == ext[1] || ext[2] == ext[3])
    r.fail("extent", "expected extent = [x0, x1, y0, y1] with x0 != x1, y0 != y1");
  e.extent = {ext[0], ext[1], ext[2], ext[3]};
  e.nearest = r.choice("interpolation", {"nearest", "bilinear"}, 0) == 0;
  // Shown as 1/2 + contrast (v - 1/2): a contrast above 1 makes faint aliasing visible.
  e.contrast = r.positive("contrast", 1);
  return e;
}

}  // namespace

void parse_generated_elements(TableReader& r, std::vector<std::pair<size_t, PlotElement>>& elements) {
  auto each = [&](std::string_view key, auto&& read) {
    r.each_table(key, [&](TableReader& sub, const toml::table& t) {
      auto e = read(sub);
      e.where = sub.origin("");
      elements.emplace_back(t.source().begin.line, PlotElement{std::move(e)});
    });
  };
  each("interp", parse_interp);
  each("relaxed_bspline", parse_relaxed_bspline);
  each("bezier", parse_bezier);
  each("lagrange", parse_lagrange);
  each("relaxed_basis", parse_relaxed_basis);
  each("subdivision", parse_subdivision);
  each("local_betas", parse_local_betas);
  each("inbetween", parse_inbetween);
  each("filter", parse_filter_curve);
  each("response", parse_response);
  each("step", parse_step);
  each("zoneplate", parse_zoneplate);
}

}  // namespace splinefig::figures::detail
