#include "prepare.hpp"

#include <splinefig/base/huge_pages.hpp>
#include "stroke.hpp"
#include "splinefig/base/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

namespace splinefig::render::detail {
namespace {

void disk_contour(Vec2 c, double r, ChainBuilder& out) {
  out.move_to(Vec2{c.x + r, c.y});
  arc_interior(c, r, 0.0, 2 * std::numbers::pi, out.clip(), [&](Vec2 q) { out.line_to(q); });
  out.close();
}

void polygon(const std::vector<Vec2>& pts, ChainBuilder& out) {
  if (pts.empty()) return;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i == 0) out.move_to(pts[i]); else out.line_to(pts[i]);
  }
  out.close();
}

void marker_contour(Marker m, Vec2 c, double s, ChainBuilder& out) {
  if (m == Marker::Circle) disk_contour(c, 0.5 * s, out);
  else polygon(marker_polygon(m, c, s), out);
}

// Whether a stroke is certainly one simple convex-ish contour (|winding| <= 1).
bool single_segment(const std::vector<Vec2>& p, bool closed) {
  if (closed) return false;
  std::size_t distinct = 0;
  for (std::size_t i = 0; i < p.size() && distinct <= 2; ++i)  // a third distinct point decides
    if (i == 0 || !(p[i].x == p[i - 1].x && p[i].y == p[i - 1].y)) ++distinct;
  return distinct <= 2;
}

// Appends a long stroke's outline pieces to g in piece order. This thread builds them from the
// first on straight into g, as it does alone; helpers on the other threads build them from the
// last on, each helper appending its pieces to a geometry of its own, from which every piece is
// then copied to its place in g (its chains' vertex indices moved with it): the same vertices
// and chains for any number of threads. A helper's geometry, like g, is advised for huge pages
// before it is written: fresh memory faulted 4 KiB at a time made a helper's piece cost about
// three times the caller's (a 10^6-point stroke: 35 ms on 2 threads against 43 on one). If some
// piece finds repeated points, g is put back and the stroke cut again without them; false, with
// g as it was, when too few points are left for pieces.
bool outline_in_pieces(OutlinePieces& pieces, Geometry& g, const Box& clip, Vec2 shift, int threads) {
  const std::size_t verts0 = g.verts.size(), chains0 = g.chains.size();
  const std::size_t piece_verts = 3 * kOutlinePiecePoints + 64;  // at most, as stroke_outline reserves
  for (;;) {
    reserve_huge(g.verts, verts0 + 3 * pieces.points() + 64);  // as stroke_outline would
    struct Part {  // piece k built by a helper: where it lies in that helper's geometry
      int worker = 0;
      std::size_t vert = 0, verts = 0, chain = 0, chains = 0;
    };
    std::vector<Geometry> helper(threads > 1 ? static_cast<std::size_t>(worker_count(threads)) : 0);
    std::vector<Part> parts(threads > 1 ? pieces.size() : 0);
    std::atomic<bool> repeats{false};
    std::vector<std::size_t> vert0(pieces.size() + 1), chain0(pieces.size() + 1);  // where parts go
    auto build = [&](std::size_t k, Geometry& into) {
      ChainBuilder b(into, clip, shift);
      if (!repeats && !pieces.build(k, b)) repeats = true;
    };
    auto theirs = [&](std::size_t k, int worker) {
      Geometry& into = helper[static_cast<std::size_t>(worker)];
      // Room for this piece, in steps of four pieces' worth (6 MB: enough for huge pages).
      if (into.verts.capacity() - into.verts.size() < piece_verts)
        reserve_huge(into.verts, std::max(into.verts.size() + piece_verts, 2 * into.verts.capacity() + 4 * piece_verts));
      Part& part = parts[k];
      part = {worker, into.verts.size(), 0, into.chains.size(), 0};
      build(k, into);
      part.verts = into.verts.size() - part.vert;
      part.chains = into.chains.size() - part.chain;
    };
    auto place = [&](std::size_t k) {
      const Part& part = parts[k];
      const Geometry& from = helper[static_cast<std::size_t>(part.worker)];
      const auto v = from.verts.begin() + static_cast<std::ptrdiff_t>(part.vert);
      std::copy(v, v + static_cast<std::ptrdiff_t>(part.verts), g.verts.begin() + static_cast<std::ptrdiff_t>(vert0[k]));
      Chain* c = g.chains.data() + chain0[k];
      for (std::size_t j = part.chain; j < part.chain + part.chains; ++j) {
        *c = from.chains[j];
        c->first = c->first - part.vert + vert0[k];
        c->last = c->last - part.vert + vert0[k];
        ++c;
      }
    };
    const std::size_t mine = split_from_both_ends(pieces.size(), threads, [&](std::size_t k) { build(k, g); }, theirs);
    if (repeats) {
      g.verts.resize(verts0);
      g.chains.resize(chains0);
      pieces.drop_repeats();
      if (pieces.size() == 0) return false;
      continue;
    }
    // The helpers' pieces move to their places in g, each copied by one of the threads.
    vert0[mine] = g.verts.size();
    chain0[mine] = g.chains.size();
    for (std::size_t k = mine; k < pieces.size(); ++k) {
      vert0[k + 1] = vert0[k] + parts[k].verts;
      chain0[k + 1] = chain0[k] + parts[k].chains;
    }
    g.verts.resize(vert0[pieces.size()]);  // unwritten: the copies below write them
    g.chains.resize(chain0[pieces.size()]);
    parallel_for(pieces.size() - mine, threads, [&](std::size_t i, int) { place(mine + i); });
    return true;
  }
}

}  // namespace

void prepare_item(const DrawItem& item, const ClipRegion* clip_path, const Compositor& comp, Vec2 shift, const Box& clip,
                  Geometry& g, Prepared& out, int canvas_h, int threads) {
  if (const auto* im = std::get_if<ImageItem>(&item)) {
    // The rows the rectangle touches (composite_raster picks the pixel centres inside).
    out.paint = comp.paint(Color{});
    out.raster = im;
    const double y0 = std::min(im->p0.y, im->p1.y), y1 = std::max(im->p0.y, im->p1.y);
    out.row0 = static_cast<int>(std::clamp(std::floor(y0), 0.0, static_cast<double>(canvas_h)));
    out.row1 = static_cast<int>(std::clamp(std::ceil(y1), 0.0, static_cast<double>(canvas_h)));
    return;
  }
  Shape& s = out.shape;
  s.chain_begin = g.chains.size();
  ChainBuilder b(g, clip, shift);
  std::visit(
      [&](const auto& it) {
        using T = std::decay_t<decltype(it)>;
        if constexpr (std::is_same_v<T, TextItem>) {
          out.paint = comp.paint(it.style.color);
          // Glyph outlines flattened within the arc tolerance, filled with the nonzero rule.
          const Path::Flat flat = it.outline->flatten(kArcTolerance);
          for (const auto& c : flat.contours) polygon(c, b);
          s.rule = FillRule::NonZero;
        } else if constexpr (!std::is_same_v<T, ImageItem>) {
          out.paint = comp.paint(it.color);
        }
        if constexpr (std::is_same_v<T, StrokeItem>) {
          const std::vector<Vec2>& pts = it.points;
          OutlinePieces pieces(pts, it.closed, it.style);
          if (!(pieces.size() > 0 && outline_in_pieces(pieces, g, clip, shift, threads)))
            stroke_path(pts, it.closed, it.style, b);
          s.simple = it.style.dashes.empty() && single_segment(pts, it.closed);
        } else if constexpr (std::is_same_v<T, FillItem>) {
          for (const auto& c : it.contours) {
            if (c.empty()) continue;
            b.move_to(c[0]);
            for (std::size_t i = 1; i < c.size(); ++i) b.line_to(c[i]);
            b.close();
          }
          s.rule = it.rule;
        } else if constexpr (std::is_same_v<T, DiskItem>) {
          if (it.radius > 0) disk_contour(it.centre, it.radius, b);
          s.simple = true;
        } else if constexpr (std::is_same_v<T, RingItem>) {
          if (it.radius == 0) return;
          if (it.style.dashes.empty()) {
            // A circle's stroke is the annulus between radii r - h and r + h (the circle swept by the
            // pen): two circles, the inner one reversed, or a disk when r <= h; exact, and a tenth of
            // the work of stroking the circle's polygon with its joins.
            const double h = 0.5 * it.style.width, r = it.radius;
            if (h == 0) return;
            disk_contour(it.centre, r + h, b);
            if (r > h) {
              const Vec2 c = it.centre;
              b.move_to(Vec2{c.x + (r - h), c.y});
              arc_interior(c, r - h, 0.0, -2 * std::numbers::pi, clip, [&](Vec2 q) { b.line_to(q); });
              b.close();
            }
            s.simple = true;
            return;
          }
          // A closed polygon on the circle, fine enough that its chords stay within the arc
          // tolerance of the circle; then stroked like any closed path.
          std::vector<Vec2> pts;
          Vec2 c = it.centre;
          pts.push_back(Vec2{c.x + it.radius, c.y});
          arc_interior(c, it.radius, 0.0, 2 * std::numbers::pi, clip, [&](Vec2 q) { pts.push_back(q); });
          stroke_path(pts, true, it.style, b);
        } else if constexpr (std::is_same_v<T, MarkerItem>) {
          if (it.size > 0) marker_contour(it.shape, it.centre, it.size, b);
          s.simple = true;
        } else if constexpr (std::is_same_v<T, PathFillItem>) {
          // Flattened here, within the arc tolerance, then exactly a polygon or polylines.
          for (const auto& c : it.path->flatten(kArcTolerance).contours) polygon(c, b);
          s.rule = it.rule;
        } else if constexpr (std::is_same_v<T, PathStrokeItem>) {
          const Path::Flat flat = it.path->flatten(kArcTolerance);
          for (std::size_t i = 0; i < flat.contours.size(); ++i) stroke_path(flat.contours[i], flat.closed[i], it.style, b);
          s.simple = flat.contours.size() == 1 && it.style.dashes.empty() && single_segment(flat.contours[0], flat.closed[0]);
        }
      },
      item);
  const std::size_t own_end = g.chains.size();
  if (clip_path) {
    // The clip path's chains join the shape's with dir scaled by kClipWeight (sweep.hpp), so the
    // sweep resolves the intersection; nothing is drawn where either is empty.
    ChainBuilder cb(g, clip, shift);
    for (const auto& c : clip_path->path.flatten(kArcTolerance).contours) polygon(c, cb);
    const std::size_t own = own_end - s.chain_begin, clip_chains = g.chains.size() - own_end;
    if (own > kMaxClippedChains || clip_chains > kMaxClippedChains)
      throw std::length_error("a clipped item of " + std::to_string(own) + " chains, or a clip path of " +
                              std::to_string(clip_chains) + ": at most " + std::to_string(kMaxClippedChains) +
                              " each (their windings share one integer)");
    for (std::size_t c = own_end; c < g.chains.size(); ++c) g.chains[c].dir *= kClipWeight;
    s.clipped = true;
    s.clip_rule = clip_path->rule;
    s.simple = false;
    if (own == 0 || clip_chains == 0) g.chains.resize(s.chain_begin);  // an empty intersection
  }
  s.chain_end = g.chains.size();
  auto first = g.chains.begin() + static_cast<std::ptrdiff_t>(s.chain_begin);
  auto last = g.chains.begin() + static_cast<std::ptrdiff_t>(s.chain_end);
  // ties broken by position: deterministic, and no allocation (unlike stable_sort)
  std::sort(first, last, [](const Chain& x, const Chain& y) { return x.ymin < y.ymin || (x.ymin == y.ymin && x.first < y.first); });
  if (s.empty()) {
    out.row0 = out.row1 = 0;
    return;
  }
  s.xmin = s.ymin = INFINITY;
  s.xmax = s.ymax = -INFINITY;
  double ink = 0;
  for (auto c = first; c != last; ++c) {
    s.xmin = std::min(s.xmin, c->xmin);
    s.xmax = std::max(s.xmax, c->xmax);
    s.ymin = std::min(s.ymin, c->ymin);
    s.ymax = std::max(s.ymax, c->ymax);
    ink -= c->dir * c->xdy;
  }
  s.ink = std::abs(ink);
  if (s.clipped) {  // only where the shape and the clip meet
    Box own{INFINITY, INFINITY, -INFINITY, -INFINITY}, cut = own;
    for (auto c = first; c != last; ++c) {
      Box& b = std::abs(c->dir) == kClipWeight ? cut : own;
      b = {std::min(b.x0, c->xmin), std::min(b.y0, c->ymin), std::max(b.x1, c->xmax), std::max(b.y1, c->ymax)};
    }
    s.xmin = std::max(own.x0, cut.x0);
    s.ymin = std::max(own.y0, cut.y0);
    s.xmax = std::min(own.x1, cut.x1);
    s.ymax = std::min(own.y1, cut.y1);
    if (!(s.xmin < s.xmax && s.ymin < s.ymax)) {
      s.chain_end = s.chain_begin;
      g.chains.resize(s.chain_begin);
      out.row0 = out.row1 = 0;
      return;
    }
  }
  if (s.simple) {
    // Sum of dir * integral of x dy: negative when the left boundaries run down (winding +1).
    double sum = 0;
    for (auto c = first; c != last; ++c)
      for (std::size_t k = c->first; k < c->last; ++k)
        sum += c->dir * 0.5 * (g.verts[k].x + g.verts[k + 1].x) * (g.verts[k + 1].y - g.verts[k].y);
    s.orient = sum < 0 ? 1 : -1;
  }
}

bool prepare_streamed(const DrawItem& item, const Compositor& comp, const Box& clip, Geometry& g, Prepared& out,
                      int canvas_h, OutlineStream& stream) {
  const auto* it = std::get_if<StrokeItem>(&item);
  if (!it || !stream.start(it->points, it->closed, it->style, clip, g, out.shape)) return false;
  out.paint = comp.paint(it->color);
  out.row0 = std::max(0, static_cast<int>(std::floor(stream.ymin())));
  out.row1 = std::min(canvas_h, static_cast<int>(std::ceil(stream.ymax())));
  return true;
}

}  // namespace splinefig::render::detail

namespace splinefig::render {

// Plus and cross arms are s/4 thick.
std::vector<Vec2> marker_polygon(Marker m, Vec2 c, double s) {
  const double a = 0.5, t = 0.125;
  std::vector<Vec2> unit;
  switch (m) {
    case Marker::Circle: return {};
    case Marker::Square: unit = {{-a, -a}, {a, -a}, {a, a}, {-a, a}}; break;
    case Marker::Diamond: unit = {{0, -a}, {a, 0}, {0, a}, {-a, 0}}; break;
    case Marker::Plus:
      unit = {{-t, -a}, {t, -a}, {t, -t}, {a, -t}, {a, t}, {t, t}, {t, a}, {-t, a}, {-t, t}, {-a, t}, {-a, -t}, {-t, -t}};
      break;
    case Marker::Cross: {
      // The plus turned by 45 degrees, arms reaching the corners of the s x s square.
      const double k = std::sqrt(0.5), A = a * std::sqrt(2.0);
      auto rot = [&](double x, double y) { return Vec2{k * (x - y), k * (x + y)}; };
      unit = {rot(-t, -A), rot(t, -A), rot(t, -t), rot(A, -t), rot(A, t), rot(t, t), rot(t, A), rot(-t, A),
              rot(-t, t), rot(-A, t), rot(-A, -t), rot(-t, -t)};
      break;
    }
  }
  for (Vec2& p : unit) p = Vec2{c.x + s * p.x, c.y + s * p.y};
  return unit;
}

}  // namespace splinefig::render
