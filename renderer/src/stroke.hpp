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
// two half-ends meeting at the vertex ("pivot"). Where the inner offset lines meet at a point X
// lying within both segments, replacing the pivot by X removes a quadrilateral lying in both
// rectangles: the winding drops by one there but stays >= 1, since a point in k such
// quadrilaterals lies in at least k+1 rectangles. So {winding > 0} is still the union, while a
// densely sampled smooth curve gives two clean offset curves instead of a comb of spikes.
// The rasterizer then needs union semantics only where the path really overlaps itself.
#include "chains.hpp"

#include <span>

namespace splinefig::render::detail {

// Appends the closed contours of the stroke of `pts` (dashes included) to `out`. Dash runs
// farther from the clip box than the stroke can reach are skipped, not generated, so a dash
// pattern on a path with vertices at 1e12 costs only what is near the canvas.
void stroke_path(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, ChainBuilder& out);

// The work of the dashes stroke_path generates for `pts` near `clip`, computed without
// generating them: the number of dashes (at most; segment ends count as one each) times the
// square of 1 + width / period, the number of dashes each one's outline overlaps.
double visible_dash_work(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip);
// The most dash work one stroke may take (Scene::stroke_polyline refuses more): a few seconds.
inline constexpr double kMaxDashWork = 1 << 20;

// The stroke of a path with no dashes.
void stroke_outline(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, ChainBuilder& out);

}  // namespace splinefig::render::detail
