#include "stroke.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace splinefig::render::detail {
namespace {

struct Segment {
  Vec2 d, n;  // unit direction, left normal (d turned +90 degrees)
  double len;
};

// The outer side of a join that turns (dt = cos of the turn): up to the miter tip, a bevel, or
// the arc of a round join. A round join whose miter tip is within the arc tolerance of the arc
// (h (1/cos(theta/2) - 1) <= tol, e.g. the tiny turns of a densely sampled curve) is drawn as
// that tip too. The outline and the pieces (stroke_pieces) take the same decision.
enum class OuterJoin { Tip, Bevel, Arc };
OuterJoin outer_join(const StrokeStyle& style, double h, double dt) {
  const double cos_half = std::sqrt(std::max(0.0, 0.5 * (1 + dt)));
  const bool miter_ok = cos_half > 0 && 1.0 / cos_half <= style.miter_limit;
  if ((style.join == Join::Miter && miter_ok) ||
      (style.join == Join::Round && cos_half > 0.5 && h * (1.0 / cos_half - 1.0) <= kArcTolerance))
    return OuterJoin::Tip;
  return style.join == Join::Round ? OuterJoin::Arc : OuterJoin::Bevel;
}

// The interior vertices of a round join's arc at P on side s, from segment a's outer corner
// through the signed turn from a to b (c, dt: its sine and cosine).
template <class Emit>
void join_arc(Vec2 P, double h, const Segment& a, double c, double dt, double s, const Box& near, Emit&& emit) {
  const double theta = c == 0 ? -std::numbers::pi : std::atan2(c, dt);
  arc_interior(P, h, std::atan2(s * a.n.y, s * a.n.x), theta, near, emit);
}

class Outliner {
 public:
  Outliner(const StrokeStyle& s, ChainBuilder& out) : style_(s), h_(0.5 * s.width), out_(out) {}

  void open(std::span<const Vec2> p);    // distinct consecutive points, at least 2
  // The part of open(p)'s contour for the points [a, b] (0 <= a < b < p.size()), as open pieces.
  void open_piece(std::span<const Vec2> p, std::size_t a, std::size_t b);
  void closed(std::span<const Vec2> p);  // distinct cyclically consecutive points, at least 2
  void single_point(Vec2 p, Vec2 d);

 private:
  // Forward vertices of the side `s` (+1 left, -1 right) at the vertex P between segments a, b.
  void join(Vec2 P, const Segment& a, const Segment& b, double s, std::vector<Vec2>& v) const;
  void emit(const std::vector<Vec2>& v, bool reverse, bool first);
  void cap(Vec2 P, Vec2 d, Vec2 n);  // from P + h n to P - h n, bulging towards d

  const StrokeStyle& style_;
  double h_;
  ChainBuilder& out_;
  std::vector<Vec2> buf_;
};

void Outliner::join(Vec2 P, const Segment& a, const Segment& b, double s, std::vector<Vec2>& v) const {
  const double h = h_;
  const double c = cross(a.d, b.d), dt = dot(a.d, b.d);
  const Vec2 A = P + (s * h) * a.n, B = P + (s * h) * b.n;
  if (c == 0 && dt > 0) {  // straight on
    v.push_back(A);
    return;
  }
  const bool outer_left = c < 0 || (c == 0 && dt < 0);
  const bool outer = s > 0 ? outer_left : !outer_left;
  if (!outer) {
    // Inner side: the offset lines' intersection X, if the quadrilateral it cuts off (X, the
    // two inner corners A, B and P) lies in both rectangles (stroke.hpp). Its triangle P A X
    // lies in segment a's rectangle and P X B in b's; the whole of it lies in b's when A does,
    // A being h sin(theta) along b from P, and X, h tan(theta / 2) along b: so both segments
    // must be at least h max(sin theta, tan(theta / 2)) long. The larger is sin theta for turns
    // up to 90 degrees (1 + dt >= 1), tan(theta / 2) = |c| / (1 + dt) beyond.
    const double reach = h * std::abs(c) * std::max(1.0, 1.0 / (1 + dt));
    if (1 + dt > 1e-12 && reach <= std::min(a.len, b.len)) {
      v.push_back(P + (s * h / (1 + dt)) * (a.n + b.n));
    } else {
      v.push_back(A);
      v.push_back(P);
      v.push_back(B);
    }
    return;
  }
  // The miter tip M lies on both outer offset lines, so A (on the line before M) and B (on the
  // line after it) are collinear outline vertices: the miter outline is just M.
  switch (outer_join(style_, h, dt)) {
    case OuterJoin::Tip: v.push_back(P + (s * h / (1 + dt)) * (a.n + b.n)); return;
    case OuterJoin::Arc:
      v.push_back(A);
      join_arc(P, h, a, c, dt, s, out_.clip(), [&](Vec2 q) { v.push_back(q); });
      v.push_back(B);
      return;
    case OuterJoin::Bevel:
      v.push_back(A);
      v.push_back(B);
      return;
  }
}

void Outliner::emit(const std::vector<Vec2>& v, bool reverse, bool first) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    Vec2 q = reverse ? v[v.size() - 1 - k] : v[k];
    if (first && k == 0) out_.move_to(q); else out_.line_to(q);
  }
}

void Outliner::cap(Vec2 P, Vec2 d, Vec2 n) {
  const double h = h_;
  switch (style_.cap) {
    case Cap::Butt: break;
    case Cap::Square:
      out_.line_to(P + h * n + h * d);
      out_.line_to(P - h * n + h * d);
      break;
    case Cap::Round:
      arc_interior(P, h, std::atan2(n.y, n.x), -std::numbers::pi, out_.clip(), [&](Vec2 q) { out_.line_to(q); });
      break;
  }
  out_.line_to(P - h * n);
}

Segment segment(Vec2 a, Vec2 b) {
  Vec2 e = b - a;
  double len = (std::abs(e.x) < 1e150 && std::abs(e.y) < 1e150) ? std::sqrt(e.x * e.x + e.y * e.y) : length(e);
  Vec2 d = (1.0 / len) * e;
  return {d, Vec2{-d.y, d.x}, len};
}

// The whole contour is the one piece [0, m]: its start cap ends where its left side began.
void Outliner::open(std::span<const Vec2> p) { open_piece(p, 0, p.size() - 1); }

// open(p)'s contour is the left side's vertices forward (p[0] + h n, the joins at p[1] .. p[m-1]),
// the end cap, the right side's backward, the start cap. The piece for [a, b] takes the left
// side from the last vertex of the join at p[a] to the last of the join at p[b], and the right
// side from the first vertex of the join at p[b] back to the first of the join at p[a] (at the
// ends: through the cap instead). Neighbouring pieces share those vertices, computed from the
// same two segments, so the pieces of a cut [0, c1], [c1, c2], ..., [ck, m] add every edge of
// the contour exactly once.
void Outliner::open_piece(std::span<const Vec2> p, std::size_t a, std::size_t b) {
  const std::size_t m = p.size() - 1;  // segments
  const double h = h_;
  out_.expect(3 * (b - a) + 64);
  const Segment first = segment(p[a], p[a + 1]);
  Segment prev = first;
  if (a == 0) {
    out_.move_to(p[0] + h * prev.n);
  } else {
    buf_.clear();
    join(p[a], segment(p[a - 1], p[a]), prev, 1, buf_);
    out_.move_to(buf_.back());
  }
  // The left side's joins go out as they are made; the right side's, from the same two
  // segments, are kept and go out backward after the end (each segment is made once). The
  // buffer is the thread's, kept from piece to piece (a piece's is up to a few MB, which would
  // otherwise be mapped and faulted in afresh for every piece).
  thread_local std::vector<Vec2> right;
  right.clear();
  for (std::size_t j = a + 1; j < b; ++j) {
    Segment next = segment(p[j], p[j + 1]);
    buf_.clear();
    join(p[j], prev, next, 1, buf_);
    emit(buf_, false, false);
    join(p[j], prev, next, -1, right);
    prev = next;
  }
  if (b == m) {
    out_.line_to(p[m] + h * prev.n);
    cap(p[m], prev.d, prev.n);
  } else {
    const Segment next = segment(p[b], p[b + 1]);
    buf_.clear();
    join(p[b], prev, next, 1, buf_);
    emit(buf_, false, false);
    out_.leave_open();
    buf_.clear();
    join(p[b], prev, next, -1, buf_);
    out_.move_to(buf_.front());
  }
  for (std::size_t k = right.size(); k-- > 0;) out_.line_to(right[k]);
  if (a == 0) {
    Vec2 mn{-first.n.x, -first.n.y}, md{-first.d.x, -first.d.y};
    out_.line_to(p[0] + h * mn);
    cap(p[0], md, mn);
  } else {
    buf_.clear();
    join(p[a], segment(p[a - 1], p[a]), first, -1, buf_);
    emit(buf_, true, false);
  }
  out_.leave_open();
}

void Outliner::closed(std::span<const Vec2> p) {
  const std::size_t m = p.size();  // segment j runs from p[j] to p[(j+1) % m]
  out_.expect(6 * m + 64);
  auto seg = [&](std::size_t j) { return segment(p[j % m], p[(j + 1) % m]); };
  for (int side : {1, -1}) {
    bool first = true;
    for (std::size_t k = 0; k < m; ++k) {
      std::size_t j = side > 0 ? k : m - 1 - k;
      buf_.clear();
      join(p[j], seg(j + m - 1), seg(j), side, buf_);
      emit(buf_, side < 0, first);
      first = false;
    }
    out_.close();
  }
}

void Outliner::single_point(Vec2 P, Vec2 d) {
  const double h = h_;
  const Vec2 n{-d.y, d.x};
  switch (style_.cap) {
    case Cap::Butt: return;
    case Cap::Square:
      out_.move_to(P + h * n - h * d);
      out_.line_to(P + h * n + h * d);
      out_.line_to(P - h * n + h * d);
      out_.line_to(P - h * n - h * d);
      out_.close();
      return;
    case Cap::Round: {
      const double a0 = std::atan2(n.y, n.x);
      out_.move_to(P + h * n);
      arc_interior(P, h, a0, -std::numbers::pi, out_.clip(), [&](Vec2 q) { out_.line_to(q); });
      out_.line_to(P - h * n);
      arc_interior(P, h, a0 + std::numbers::pi, -std::numbers::pi, out_.clip(), [&](Vec2 q) { out_.line_to(q); });
      out_.close();
      return;
    }
  }
}

}  // namespace

void stroke_outline(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, ChainBuilder& out) {
  if (!(style.width > 0) || pts.empty()) return;
  // Repeated consecutive points carry no direction: drop them (copying only if there are any).
  std::vector<Vec2> copy;
  bool repeats = false;
  for (std::size_t i = 1; i < pts.size() && !repeats; ++i) repeats = pts[i] == pts[i - 1];
  if (closed && pts.size() > 1 && pts.back() == pts.front()) repeats = true;
  std::span<const Vec2> p = pts;
  if (repeats) {
    for (Vec2 q : pts)
      if (copy.empty() || !(q == copy.back())) copy.push_back(q);
    if (closed)
      while (copy.size() > 1 && copy.back() == copy.front()) copy.pop_back();
    p = copy;
  }
  Outliner o(style, out);
  if (p.size() < 2) {
    // A path of one point: SVG draws its caps as if it ran along +x.
    o.single_point(p[0], Vec2{1, 0});
    return;
  }
  if (closed) o.closed(p); else o.open(p);
}

OutlinePieces::OutlinePieces(std::span<const Vec2> pts, bool closed, const StrokeStyle& style) : style_(style) {
  if (closed || !(style.width > 0) || !style.dashes.empty()) return;
  cut(pts);
}

void OutlinePieces::cut(std::span<const Vec2> p) {
  p_ = p;
  const std::size_t segments = p.size() > 0 ? p.size() - 1 : 0;
  pieces_ = segments > 2 * kOutlinePiecePoints ? (segments + kOutlinePiecePoints - 1) / kOutlinePiecePoints : 0;
}

void OutlinePieces::drop_repeats() {
  std::vector<Vec2> distinct;
  distinct.reserve(p_.size());
  for (Vec2 q : p_)
    if (distinct.empty() || !(q == distinct.back())) distinct.push_back(q);
  copy_ = std::move(distinct);
  cut(copy_);
}

bool OutlinePieces::build(std::size_t k, ChainBuilder& out) const {
  const std::size_t a = k * kOutlinePiecePoints, b = std::min(a + kOutlinePiecePoints, p_.size() - 1);
  // The piece uses the points [a - 1, b + 1]; a repeat among them would make a segment without
  // a direction.
  for (std::size_t i = std::max<std::size_t>(a, 1); i <= std::min(b + 1, p_.size() - 1); ++i)
    if (p_[i] == p_[i - 1]) return false;
  Outliner o(style_, out);
  o.open_piece(p_, a, b);
  return true;
}

namespace {

// Geometry farther than this from the clip box cannot touch it.
double stroke_reach(const StrokeStyle& style) { return 0.5 * style.width * std::max(style.miter_limit, 1.5) + 2.0; }

Box inflated(Box b, double d) {
  b.x0 -= d; b.y0 -= d; b.x1 += d; b.y1 += d;
  return b;
}

// Liang-Barsky: the part [t0, t1] (in length units along the unit direction d) of the segment
// from a of length len inside `box`; t0 >= t1 when none is.
void clip_segment(Vec2 a, Vec2 d, double len, const Box& box, double& t0, double& t1) {
  t0 = 0;
  t1 = len;
  auto clip1 = [&](double pdir, double q) {  // pdir * t <= q
    if (pdir == 0) { if (q < 0) { t0 = 1; t1 = 0; } return; }
    double t = q / pdir;
    if (pdir < 0) t0 = std::max(t0, t); else t1 = std::min(t1, t);
  };
  clip1(-d.x, a.x - box.x0); clip1(d.x, box.x1 - a.x);
  clip1(-d.y, a.y - box.y0); clip1(d.y, box.y1 - a.y);
}

}  // namespace

bool OutlinePieces::y_range(std::size_t k, double& y0, double& y1) const {
  const std::size_t a = k * kOutlinePiecePoints, b = std::min(a + kOutlinePiecePoints, p_.size() - 1);
  const std::size_t first = a > 0 ? a - 1 : 0, last = std::min(b + 1, p_.size() - 1);  // as build() uses them
  double lo = p_[first].y, hi = lo;
  for (std::size_t i = first + 1; i <= last; ++i) {
    if (p_[i] == p_[i - 1]) return false;
    lo = std::min(lo, p_[i].y);
    hi = std::max(hi, p_[i].y);
  }
  const double reach = stroke_reach(style_);
  y0 = lo - reach;
  y1 = hi + reach;
  return true;
}

double visible_dash_count(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip) {
  if (!(style.width > 0) || pts.size() < 2 || style.dashes.empty()) return 0;
  const double period = style.dashes.period();
  const double per_period = static_cast<double>((style.dashes.size() + 1) / 2);
  const Box near = inflated(clip, stroke_reach(style));
  double count = 0;
  const std::size_t n = pts.size(), segments = closed ? n : n - 1;
  for (std::size_t i = 0; i < segments; ++i) {
    const Vec2 a = pts[i], b = pts[(i + 1) % n], e = b - a;
    const double len = length(e);
    if (!(len > 0)) continue;
    double t0, t1;
    clip_segment(a, (1.0 / len) * e, len, near, t0, t1);
    if (t0 < t1) count += (t1 - t0) / period * per_period + 1;
  }
  return count;
}

double visible_dash_work(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip) {
  const double count = visible_dash_count(pts, closed, style, clip);
  if (count == 0) return 0;
  const double period = style.dashes.period();
  const double per_period = static_cast<double>((style.dashes.size() + 1) / 2);
  // Each dash's outline overlaps those within a stroke width, and the rasterizer pays for the
  // crossings of overlapping outlines: a pattern finer than its pen costs that much more
  // (measured: about the square of the overlap).
  const double overlap = std::min(1 + style.width / period * per_period, count);
  return count * overlap * overlap;
}

double stroke_vertex_bound(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip) {
  if (!(style.width > 0) || pts.empty()) return 0;
  const double h = 0.5 * style.width;
  const bool round_join = style.join == Join::Round;
  // The geometry holds a vertex once more where the outline turns in y (it ends one monotone
  // chain and begins the next): at most each corner vertex, and once in an arc of at most pi.
  // A cap: its two corners, the square's two or the round cap's arc; a dash's caps may lie
  // anywhere near the canvas.
  auto cap_at = [&](Vec2 P) { return 8 + (style.cap == Cap::Round ? 1 + arc_vertex_bound(P, h, std::numbers::pi, clip) : 4); };
  // A join, both sides (Outliner::join): the inner side at most 3, the outer side its miter tip,
  // or its two corners and a round join's arc.
  auto join_at = [&](Vec2 P, Vec2 a, Vec2 b) -> double {
    const double c = cross(a, b), dt = dot(a, b);
    if (c == 0 && dt > 0) return 4;
    if (!round_join) return 10;
    const double cos_half = std::sqrt(std::max(0.0, 0.5 * (1 + dt)));
    if (cos_half > 0.5 && h * (1.0 / cos_half - 1.0) <= kArcTolerance) return 8;
    const double theta = c == 0 ? std::numbers::pi : std::atan2(std::abs(c), dt);
    return 11 + arc_vertex_bound(P, h, theta, clip);
  };
  double joins = 0;
  std::size_t m = 0;  // distinct consecutive points
  Vec2 first{}, prev{}, d_first{}, d_prev{};
  for (const Vec2& p : pts) {
    if (m > 0 && p == prev) continue;
    if (m > 0) {
      const Vec2 d = segment(prev, p).d;  // as the outline makes it
      if (m > 1) joins += join_at(prev, d_prev, d); else d_first = d;
      d_prev = d;
    }
    if (m == 0) first = p;
    prev = p;
    ++m;
  }
  double ends = 0;
  if (m == 1) {
    ends = 2 * cap_at(first);
  } else if (closed) {
    if (!(prev == first)) {
      const Vec2 d = segment(prev, first).d;
      joins += join_at(prev, d_prev, d) + join_at(first, d, d_first);
    } else {
      joins += join_at(first, d_prev, d_first);
    }
  } else {
    ends = cap_at(first) + cap_at(prev);
  }
  double total = joins + ends + 4 * static_cast<double>(m) + 16;
  if (!style.dashes.empty()) {
    // Each dash: its two ends and caps, anywhere near the canvas: a cap centred on the box's
    // edge takes the most (the uniform count below a radius of 1e6; beyond, a dash within the
    // stroke's reach of the box is at most one band of distance farther).
    const double cap = 8 + (style.cap == Cap::Round
                                ? 1 + arc_vertex_bound({clip.x0, clip.y0}, h, std::numbers::pi, clip) + 8 * std::numbers::pi + 2
                                : 4);
    total += visible_dash_count(pts, closed, style, clip) * (2 * cap + 8);
  }
  return total;
}

namespace {

// Appends the polygon in `poly` to `out` as a piece if it has area and may touch `clip`,
// turned counter-clockwise (positive shoelace area in the y-down frame) if it is not.
void add_piece(std::vector<Vec2>& poly, const Box& clip, ConvexPieces& out) {
  Box b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  double area2 = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
    area2 += cross(p, q);
    b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
  }
  if (!(area2 != 0) || b.x1 <= clip.x0 || b.x0 >= clip.x1 || b.y1 <= clip.y0 || b.y0 >= clip.y1) return;
  if (area2 < 0) std::reverse(poly.begin(), poly.end());
  out.verts.insert(out.verts.end(), poly.begin(), poly.end());
  out.start.push_back(out.verts.size());
  out.bounds.push_back(b);
}

}  // namespace

bool stroke_pieces(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip, ConvexPieces& out) {
  if (!(style.width > 0) || !style.dashes.empty()) return false;
  std::vector<Vec2> p;
  p.reserve(pts.size());
  for (Vec2 q : pts)
    if (p.empty() || !(q == p.back())) p.push_back(q);
  if (closed)
    while (p.size() > 1 && p.back() == p.front()) p.pop_back();
  if (p.size() < 2) return false;
  const double h = 0.5 * style.width;
  const std::size_t m = p.size(), segments = closed ? m : m - 1;
  auto seg = [&](std::size_t j) { return segment(p[j % m], p[(j + 1) % m]); };
  std::vector<Vec2> poly;
  // The join at p[j] between segments a (into it) and b (out of it), on the outer side.
  auto join = [&](Vec2 P, const Segment& a, const Segment& b) {
    const double c = cross(a.d, b.d), dt = dot(a.d, b.d);
    if (c == 0 && dt > 0) return;  // straight on
    const double s = c < 0 || (c == 0 && dt < 0) ? 1.0 : -1.0;
    poly.assign({P, P + (s * h) * a.n});
    switch (outer_join(style, h, dt)) {
      case OuterJoin::Tip: poly.push_back(P + (s * h / (1 + dt)) * (a.n + b.n)); break;
      case OuterJoin::Arc: join_arc(P, h, a, c, dt, s, clip, [&](Vec2 q) { poly.push_back(q); }); break;
      case OuterJoin::Bevel: break;
    }
    poly.push_back(P + (s * h) * b.n);
    add_piece(poly, clip, out);
  };
  // A cap at P bulging towards d, n = d turned +90 degrees (Outliner::cap).
  auto cap = [&](Vec2 P, Vec2 d, Vec2 n) {
    switch (style.cap) {
      case Cap::Butt: return;
      case Cap::Square: poly.assign({P + h * n, P + h * n + h * d, P - h * n + h * d, P - h * n}); break;
      case Cap::Round:
        poly.assign({P + h * n});
        arc_interior(P, h, std::atan2(n.y, n.x), -std::numbers::pi, clip, [&](Vec2 q) { poly.push_back(q); });
        poly.push_back(P - h * n);
        break;
    }
    add_piece(poly, clip, out);
  };
  out.verts.reserve(out.verts.size() + 8 * segments);
  Segment prev = seg(closed ? m - 1 : 0);
  for (std::size_t j = 0; j < segments; ++j) {
    const Segment cur = seg(j);
    const Vec2 a = p[j], b = p[(j + 1) % m];
    poly.assign({a + h * cur.n, b + h * cur.n, b - h * cur.n, a - h * cur.n});
    add_piece(poly, clip, out);
    if (closed || j > 0) join(a, prev, cur);
    prev = cur;
  }
  if (!closed) {
    const Segment first = seg(0);
    cap(p[m - 1], prev.d, prev.n);
    cap(p[0], Vec2{-first.d.x, -first.d.y}, Vec2{-first.n.x, -first.n.y});
  }
  return true;
}

void stroke_path(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, ChainBuilder& out) {
  if (!(style.width > 0) || pts.empty()) return;
  const DashPattern& dash = style.dashes;  // even, with a positive period (renderer.hpp)
  if (dash.empty()) {
    stroke_outline(pts, closed, style, out);
    return;
  }
  const double period = dash.period();
  std::vector<Vec2> p(pts.begin(), pts.end());
  if (closed && !p.empty()) p.push_back(p.front());

  // Geometry farther than the stroke's reach from the canvas cannot touch it: dash runs are
  // clipped there.
  const Box near = inflated(out.clip(), stroke_reach(style));

  // Dash state: index into the pattern, distance left in that entry.
  double ph = std::fmod(style.dash_offset, period);
  if (ph < 0) ph += period;
  std::size_t idx = 0;
  while (ph >= dash[idx]) { ph -= dash[idx]; idx = (idx + 1) % dash.size(); }
  double left = dash[idx] - ph;
  auto advance_far = [&](double dist) {  // skip `dist` along the pattern
    double r = std::fmod(dist, period);
    // only the remainder matters; walk at most one period
    while (r > 0) {
      if (r < left) { left -= r; r = 0; break; }
      r -= left;
      idx = (idx + 1) % dash.size();
      left = dash[idx];
    }
  };

  StrokeStyle solid = style;
  solid.dashes = {};
  std::vector<Vec2> run;
  Vec2 run_dir{1, 0};
  auto flush = [&]() {
    if (run.empty()) return;
    if (run.size() == 1 || (run.size() == 2 && run[0] == run[1])) {
      Outliner o(solid, out);
      o.single_point(run[0], run_dir);
    } else {
      stroke_outline(run, false, solid, out);
    }
    run.clear();
  };
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    Vec2 a = p[i], b = p[i + 1];
    Vec2 e = b - a;
    double len = length(e);
    if (len == 0) continue;
    Vec2 d = (1.0 / len) * e;
    double t0, t1;
    clip_segment(a, d, len, near, t0, t1);
    if (t0 >= t1) {  // the whole segment is far away
      flush();
      advance_far(len);
      continue;
    }
    if (t0 > 0) { flush(); advance_far(t0); }
    // The dashes are walked from the visible part's start a0, in its own length units: along a
    // segment from 1e14 a step of a short dash would not change t near 1e14.
    const Vec2 a0 = t0 > 0 ? a + t0 * d : a;
    const bool to_end = t1 >= len;
    const double span = to_end ? len - t0 : t1 - t0;
    double t = 0;
    const bool on_at_start = idx % 2 == 0;
    if (on_at_start && run.empty()) run.push_back(a0);
    if (on_at_start && !run.empty() && !(run.back() == a0)) run.push_back(a0);
    while (t < span) {
      double step = std::min(left, span - t);
      t += step;
      left -= step;
      if (left <= 0) {
        Vec2 q = to_end && t >= span ? b : a0 + t * d;
        if (idx % 2 == 0) {  // a dash ends here
          run.push_back(q);
          run_dir = d;
          flush();
        } else {  // a dash starts here
          run.push_back(q);
          run_dir = d;
        }
        idx = (idx + 1) % dash.size();
        left = dash[idx];
      }
    }
    if (idx % 2 == 0 && !run.empty()) {
      run.push_back(to_end ? b : a0 + span * d);
      run_dir = d;
    }
    if (!to_end) { flush(); advance_far(len - t1); }
  }
  flush();
}

}  // namespace splinefig::render::detail
