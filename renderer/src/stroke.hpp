#pragma once
// A stroke as the outline whose nonzero region is exactly the union of the stroke's pieces.
//
// The pieces (docs/conventions.md, as SVG 2 defines them): one rectangle of the stroke width per
// segment; at each interior vertex a join piece on the outer side of the turn (round: the
// circular sector between the two outer corners; miter: the quadrilateral up to the miter tip,
// a bevel instead when miter length / width exceeds the limit; bevel: the triangle); caps at
// the two ends of an open path (butt: none; square: a half-square; round: a half-disk).
//
// Why the outline is exact: orient every piece the same way. The sum of their boundaries, as a
// chain, has winding number = the number of pieces covering a point, so the union is
// {winding > 0}. In that sum the radii shared by a rectangle's end and its join piece cancel,
// leaving the familiar outline: offset lines, outer join geometry, and on the inner side the
// two half-ends meeting at the vertex ("pivot"). Where the inner offset lines meet at a point X,
// replacing the pivot by X removes the quadrilateral (vertex, inner corner, X, inner corner).
// When both segments are at least h max(sin theta, tan(theta / 2)) long (h the half-width,
// theta the turn), X lies within both and each inner corner within the other segment's
// rectangle, so the quadrilateral lies in both rectangles (X within both is not enough: a turn
// under 90 degrees into a segment shorter than h sin theta puts a corner past that segment's
// end, and the part of the quadrilateral beyond it may lie in one piece only). Then the
// winding drops by one there but stays >= 1, since a point in k such
// quadrilaterals lies in at least k+1 rectangles. So {winding > 0} is still the union, while a
// densely sampled smooth curve gives two clean offset curves instead of a comb of spikes.
// The rasterizer then needs union semantics only where the path really overlaps itself.
#include "chains.hpp"

#include <span>
#include <vector>

namespace splinefig::render::detail {

// Appends the closed contours of the stroke of `pts` (dashes included) to `out`. Dash runs
// farther from the clip box than the stroke can reach are skipped, not generated, so a dash
// pattern on a path with vertices at 1e12 costs only what is near the canvas.
void stroke_path(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, ChainBuilder& out);

// The work of the dashes stroke_path generates for `pts` near `clip`, computed without
// generating them: the number of dashes (at most; segment ends count as one each) times the
// square of 1 + width / period, the number of dashes each one's outline overlaps.
// Scene::stroke_polyline refuses more than kMaxDashWork (base/limits.hpp): a few seconds.
double visible_dash_work(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip);

// An upper bound on the outline vertices stroke_path appends for `pts`, computed from the
// points alone (one pass, no allocation): per join both sides' vertices, a round join's arc as
// arc_vertex_bound counts it (a hairpin turn of a pen of width w takes about
// pi / sqrt(8e-4 / w) vertices: 100 at w = 2), the caps, and per dash near `clip` (as
// visible_dash_work counts them) its two caps; the joins inside dashes are the path's own.
// `clip` must contain the box the rasterizer clips to (the canvas and the filter's margin).
// Scene refuses an outline past kMaxOutlineVertices (base/limits.hpp) before building it.
double stroke_vertex_bound(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip);

// The dashes stroke_path generates for `pts` near `clip`, at most (segment ends count as one
// each): visible_dash_work's count.
double visible_dash_count(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip);

// The stroke of a path with no dashes.
void stroke_outline(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, ChainBuilder& out);

// The stroke's pieces themselves (the list above), each a convex polygon given counter-clockwise
// in the canvas's y-down frame (positive shoelace area), for drawing a stroke whose outline
// crosses itself too often to sweep (piece_coverage.hpp). Their vertices are the outline's:
// the same corners, miter tips and arc points (arcs flattened as the outline's are, near `clip`),
// so their union is the outline's nonzero region. Pieces of zero area and pieces whose bounding
// box misses `clip` are left out. Solid strokes of at least two distinct points only: false (and
// nothing appended) for dashes or a single point.
struct ConvexPieces {
  std::vector<Vec2> verts;
  std::vector<std::size_t> start{0};  // piece i is verts[start[i], start[i + 1])
  std::vector<Box> bounds;            // each piece's bounding box
  std::size_t size() const { return bounds.size(); }
  std::span<const Vec2> piece(std::size_t i) const { return {verts.data() + start[i], start[i + 1] - start[i]}; }
};
bool stroke_pieces(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip, ConvexPieces& out);

// A long open stroke's outline in pieces that can be built independently, each as open pieces
// of the contour (chains.hpp): the piece k covers the points [k P, (k + 1) P] (the last one up
// to the end), P = kOutlinePiecePoints. The cut depends on the points only, so the pieces built
// one after another into one geometry, or each into its own and appended in order, give the
// same vertices and chains. The union is stroke_outline's; only its chains split at the cuts.
//
// Repeated consecutive points carry no direction and are dropped, as stroke_outline does; a
// piece finds them among its own points (so that no thread scans the whole path first), and
// the stroke is then cut again without them.
inline constexpr std::size_t kOutlinePiecePoints = std::size_t{1} << 15;
class OutlinePieces {
 public:
  // No pieces (size() == 0) unless the stroke is open, has no dashes and more than two pieces'
  // worth of points; stroke_path draws it then.
  OutlinePieces(std::span<const Vec2> pts, bool closed, const StrokeStyle& style);
  // It holds a reference to the style and a span into its own copy of the points: neither a
  // copy nor a move would keep them valid.
  OutlinePieces(const OutlinePieces&) = delete;
  OutlinePieces& operator=(const OutlinePieces&) = delete;
  std::size_t size() const { return pieces_; }
  std::size_t points() const { return p_.size(); }
  // Appends piece k to `out`; false, appending nothing, if its points repeat a point.
  bool build(std::size_t k, ChainBuilder& out) const;
  // Heights [y0, y1] that piece k's outline stays within: the y range of the points build()
  // uses, grown by the farthest any outline vertex lies from them (a miter tip at the limit, a
  // square cap's corner). False if those points repeat a point (build() would refuse the piece).
  bool y_range(std::size_t k, double& y0, double& y1) const;
  // Cuts the points without their repeats (then size() is 0 if too few are left).
  void drop_repeats();

 private:
  void cut(std::span<const Vec2> p);

  const StrokeStyle& style_;
  std::vector<Vec2> copy_;  // the points without repeats, after drop_repeats
  std::span<const Vec2> p_;
  std::size_t pieces_ = 0;
};

}  // namespace splinefig::render::detail
