// The companion texts' plot elements: spline-library results turned into series.
#include "companion_figures.hpp"

#include "spec_parse.hpp"

#include <splinefig/spline/bezier.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/interp.hpp>
#include <splinefig/spline/lagrange.hpp>
#include <splinefig/spline/local_beta.hpp>
#include <splinefig/spline/subdivision.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace splinefig::figures::detail {
namespace {

const Color kGrey = *render::parse_hex_color("#888888");

Points to_points(const std::vector<Vec2>& v) {
  Points p(2);
  for (Vec2 q : v) p.push_back(std::vector<double>{q.x, q.y});
  return p;
}

std::vector<Vec2> to_vec(const Points& p) {
  std::vector<Vec2> v;
  for (std::size_t i = 0; i < p.size(); ++i) v.push_back({p[i][0], p[i][1]});
  return v;
}

// The look of a generated series: a curve (2 px, round), a control polygon (1 px grey dashed
// with dots) or a point set (dots); the spec's own keys override it.
enum class Look { Curve, Polygon, Points };

SeriesElement styled(TableReader& r, std::vector<Vec2> pts, Look look) {
  SeriesElement s;
  s.points = std::move(pts);
  render::StrokeStyle st;
  st.width = 2;
  st.join = render::Join::Round;
  st.cap = render::Cap::Round;
  if (look == Look::Polygon) {
    st.width = 1;
    st.join = render::Join::Miter;
    st.cap = render::Cap::Butt;
    st.dashes = {5, 3};
    s.style = SeriesStyle::LineMarkers;
    s.color = kGrey;
  } else if (look == Look::Points) {
    s.style = SeriesStyle::Markers;
  }
  s.style = static_cast<SeriesStyle>(
      r.choice("style", {"line", "markers", "line+markers", "steps", "stems"}, static_cast<int>(s.style)));
  s.closed = r.boolean("closed", false);
  if (auto c = r.opt_color("color")) s.color = c;
  s.style_stroke = r.stroke(st);
  s.marker = static_cast<render::Marker>(
      r.choice("marker", {"circle", "square", "diamond", "cross", "plus"}, static_cast<int>(s.marker)));
  s.marker_size = r.positive("marker_size", s.marker_size);
  s.marker_color = r.opt_color("marker_color");
  s.label = parse_labelling(r);
  return s;
}

std::vector<Vec2> required_points(TableReader& r, const char* key, std::size_t minimum, const char* what) {
  std::vector<Vec2> p = r.points(key);
  if (p.size() < minimum)
    r.fail(key, std::string(what) + " needs at least " + std::to_string(minimum) + " points, got " +
                    std::to_string(p.size()));
  return p;
}

int samples_per_piece(TableReader& r) { return r.integer("samples", 64, 1, 4096); }

// Polyline of a composite Bezier spline, `samples` points per piece.
std::vector<Vec2> trace(const BezierSpline& b, int samples) {
  std::vector<Vec2> out;
  const std::size_t n = b.pieces();
  double x[2];
  for (std::size_t i = 0; i < n; ++i)
    for (int j = 0; j < samples; ++j) {
      evaluate(b, static_cast<double>(i) + static_cast<double>(j) / samples, 0, x);
      out.push_back({x[0], x[1]});
    }
  evaluate(b, static_cast<double>(n), 0, x);
  out.push_back({x[0], x[1]});
  return out;
}

std::vector<Vec2> velocity(TableReader& r, const char* key) {
  if (!r.has(key)) return {};
  auto v = r.opt_point(key);
  return {*v};
}

void parse_interp(TableReader& r, std::vector<PlotElement>& out) {
  const std::vector<Vec2> data = required_points(r, "points", 2, "interp");
  const int ends = r.choice("ends", {"relaxed", "clamped", "periodic"}, 0);
  const int show = r.choice("show", {"curve", "control", "bezier"}, 0);
  const int samples = samples_per_piece(r);
  const auto v = velocity(r, "start_velocity"), w = velocity(r, "end_velocity");
  if (ends != 1 && (!v.empty() || !w.empty()))
    r.fail(v.empty() ? "end_velocity" : "start_velocity", "end velocities need ends = \"clamped\"");
  Interpolant s;
  try {
    const Points S = to_points(data);
    if (ends == 0) s = interpolate_relaxed(S);
    if (ends == 1) {
      const std::vector<double> a{v.empty() ? 0 : v[0].x, v.empty() ? 0 : v[0].y},
          b{w.empty() ? 0 : w[0].x, w.empty() ? 0 : w[0].y};
      s = interpolate_clamped(S, a, b);
    }
    if (ends == 2) s = interpolate_periodic(S);
  } catch (const std::invalid_argument& e) {
    r.fail("points", e.what());
  }
  if (show == 0) out.push_back(styled(r, trace(bezier_pieces(s), samples), Look::Curve));
  if (show == 1) out.push_back(styled(r, to_vec(s.control), Look::Polygon));
  if (show == 2) out.push_back(styled(r, to_vec(bezier_pieces(s).points), Look::Points));
}

void parse_relaxed_bspline(TableReader& r, std::vector<PlotElement>& out) {
  const Points B = to_points(required_points(r, "points", 2, "relaxed_bspline"));
  const int show = r.choice("show", {"curve", "joints", "division", "bezier", "aframes"}, 0);
  const int samples = samples_per_piece(r);
  const BezierSpline b = relaxed_bspline_bezier(B);
  const std::vector<Vec2> pts = to_vec(b.points);
  if (show == 0) out.push_back(styled(r, trace(b, samples), Look::Curve));
  if (show == 1 || show == 2) {
    std::vector<Vec2> sel;
    for (std::size_t k = 0; k < pts.size(); ++k)
      if ((k % 3 == 0) == (show == 1)) sel.push_back(pts[k]);
    out.push_back(styled(r, sel, Look::Points));
  }
  if (show == 3) out.push_back(styled(r, pts, Look::Points));
  if (show == 4) {
    // One A per interior joint: the legs from the outer division points up to the apex B_i,
    // and the cross-bar between the inner division points, through S_i (seed 003 §3-4).
    const std::size_t n = B.size() - 1;
    for (std::size_t i = 1; i < n; ++i) {
      const Vec2 P1 = pts[3 * i - 2], P2 = pts[3 * i - 1], Q1 = pts[3 * i + 1], Q2 = pts[3 * i + 2];
      const Vec2 A{B[i][0], B[i][1]};
      const std::size_t first = out.size();
      out.push_back(styled(r, {P1, A, Q2}, Look::Curve));
      SeriesElement bar = std::get<SeriesElement>(out[first]);
      bar.points = {P2, Q1};
      bar.label = {};
      out.push_back(bar);
      if (i > 1) std::get<SeriesElement>(out[first]).label = {};  // one legend entry for all
    }
    if (n < 2) r.fail("points", "A-frames need at least 3 control points");
  }
}

void parse_bezier(TableReader& r, std::vector<PlotElement>& out) {
  const Points P = to_points(required_points(r, "points", 2, "bezier"));
  const int samples = r.integer("samples", 128, 2, 65536);
  std::vector<Vec2> pts;
  double x[2];
  for (int j = 0; j <= samples; ++j) {
    de_casteljau(P, static_cast<double>(j) / samples, x);
    pts.push_back({x[0], x[1]});
  }
  out.push_back(styled(r, pts, Look::Curve));
}

void parse_lagrange(TableReader& r, std::vector<PlotElement>& out) {
  const std::vector<Vec2> data = required_points(r, "points", 1, "lagrange");
  std::vector<double> t;
  Points y(1);
  for (Vec2 q : data) {
    t.push_back(q.x);
    y.push_back(std::vector<double>{q.y});
  }
  LagrangePolynomial p;
  try {
    p = lagrange(t, y);
  } catch (const std::invalid_argument& e) {
    r.fail("points", e.what());
  }
  double lo = *std::min_element(t.begin(), t.end()), hi = *std::max_element(t.begin(), t.end());
  if (r.has("range")) {
    auto v = r.numbers("range");
    if (v.size() != 2 || !(v[0] < v[1])) r.fail("range", "expected [x0, x1] with x0 < x1");
    lo = v[0], hi = v[1];
  }
  const int samples = r.integer("samples", 800, 2, 65536);
  std::vector<Vec2> pts;
  for (int j = 0; j <= samples; ++j) {
    const double x = lo + (hi - lo) * j / samples;
    double v;
    evaluate(p, x, std::span<double>(&v, 1));
    pts.push_back({x, v});
  }
  out.push_back(styled(r, pts, Look::Curve));
}

void parse_relaxed_basis(TableReader& r, std::vector<PlotElement>& out) {
  const int n = r.integer("n", 4, 1, 1000);
  const int k = r.integer("k", 0, 0, n);
  const int samples = samples_per_piece(r);
  const Interpolant f = relaxed_basis(n);
  std::vector<Vec2> pts;
  std::vector<double> x(static_cast<std::size_t>(n) + 1);
  for (int j = 0; j <= n * samples; ++j) {
    const double t = static_cast<double>(j) / samples;
    evaluate(f, t, 0, x);
    pts.push_back({t, x[static_cast<std::size_t>(k)]});
  }
  out.push_back(styled(r, pts, Look::Curve));
}

void parse_subdivision(TableReader& r, std::vector<PlotElement>& out) {
  const Points P = to_points(required_points(r, "points", 3, "subdivision"));
  const int steps = r.integer("steps", 1, 0, 12);
  const int show = r.choice("show", {"polygon", "limit"}, 0);
  const Points R = refine(P, steps);
  if (show == 0) out.push_back(styled(r, to_vec(R), Look::Polygon));
  if (show == 1) out.push_back(styled(r, to_vec(limit_points(R)), Look::Points));
}

void parse_local_betas(TableReader& r, std::vector<PlotElement>& out) {
  const std::vector<Vec2> knots = required_points(r, "knots", 2, "local_betas");
  const auto rows = r.matrix("betas");
  if (rows.size() != knots.size())
    r.fail("betas", "one [b1, b2] per knot: " + std::to_string(rows.size()) + " given for " +
                        std::to_string(knots.size()) + " knots");
  std::vector<ShapeParameters> betas;
  for (const auto& row : rows) {
    if (row.size() != 2) r.fail("betas", "each entry is [b1, b2]");
    betas.push_back({row[0], row[1]});
  }
  const Ends ends = static_cast<Ends>(r.choice("ends", {"open", "double", "closed"}, 0));
  const int samples = samples_per_piece(r);
  Points curve;
  try {
    curve = sample_local_betas(make_curve(beta(1, 0), to_points(knots), ends), betas, samples);
  } catch (const std::invalid_argument& e) {
    r.fail("betas", e.what());
  }
  out.push_back(styled(r, to_vec(curve), Look::Curve));
}

void parse_inbetween(TableReader& r, std::vector<PlotElement>& out) {
  // Keyframes: equally long polylines at t = 0, 1, ..., n; each frame is one point of R^(2m)
  // and the in-between frame at `t` lies on the relaxed spline through them.
  const toml::node* n = r.node("frames");
  const toml::array* frames = n ? n->as_array() : nullptr;
  if (!frames || frames->size() < 2) r.fail("frames", "expected frames = [[[x, y], ...], ...], at least 2 keyframes");
  Points keys;
  std::size_t m = 0;
  for (const toml::node& f : *frames) {
    const toml::array* pts = f.as_array();
    if (!pts || pts->empty()) r.fail_at(f, "frames", "each keyframe is a list of [x, y] points");
    if (m == 0) m = pts->size();
    if (pts->size() != m) r.fail_at(f, "frames", "every keyframe needs the same number of points");
    std::vector<double> flat;
    for (const toml::node& q : *pts) {
      const toml::array* xy = q.as_array();
      if (!xy || xy->size() != 2 || !(*xy)[0].is_number() || !(*xy)[1].is_number())
        r.fail_at(q, "frames", "a point is [x, y]");
      flat.push_back((*xy)[0].value<double>().value());
      flat.push_back((*xy)[1].value<double>().value());
    }
    keys.push_back(flat);
  }
  const auto t = r.opt_number("t");
  if (!t || *t < 0 || *t > static_cast<double>(keys.size() - 1))
    r.fail("t", "expected t = TIME between 0 and the last keyframe's " + std::to_string(keys.size() - 1));
  const Interpolant s = interpolate_relaxed(keys);
  std::vector<double> x(2 * m);
  evaluate(s, *t, 0, x);
  std::vector<Vec2> pts;
  for (std::size_t i = 0; i < m; ++i) pts.push_back({x[2 * i], x[2 * i + 1]});
  out.push_back(styled(r, pts, Look::Curve));
}

}  // namespace

void parse_companion_elements(TableReader& r, std::vector<std::pair<size_t, PlotElement>>& elements) {
  auto each = [&](std::string_view key, void (*make)(TableReader&, std::vector<PlotElement>&)) {
    int i = 0;
    const toml::node* n = r.node(key);
    const bool single = n && n->is_table();
    for (const toml::table* t : r.tables(key)) {
      TableReader sub(*t, r.file(), single ? r.key_path(key) : r.key_path(key) + "[" + std::to_string(i++) + "]");
      std::vector<PlotElement> made;
      make(sub, made);
      sub.finish();
      for (auto& e : made) elements.emplace_back(t->source().begin.line, std::move(e));
    }
  };
  each("interp", parse_interp);
  each("relaxed_bspline", parse_relaxed_bspline);
  each("bezier", parse_bezier);
  each("lagrange", parse_lagrange);
  each("relaxed_basis", parse_relaxed_basis);
  each("subdivision", parse_subdivision);
  each("local_betas", parse_local_betas);
  each("inbetween", parse_inbetween);
}

}  // namespace splinefig::figures::detail
