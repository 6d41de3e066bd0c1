#pragma once
// Paths as y-monotone chains, the input of the scan converter (sweep.hpp).
//
// A ChainBuilder takes closed contours (move_to, line_to, close) and cuts every contour into
// maximal runs of edges that all go down (dir +1) or all go up (dir -1); horizontal edges are
// dropped (they bound no area and cross no scanline). Each chain is stored with ascending y.
// The winding number of a point is the sum of dir over the chains that cross the horizontal
// ray to its left, so the chains carry everything the fill rules need.
//
// A contour may also come in open pieces (move_to, line_to, leave_open), each starting where
// another ends, that together run around it: every edge is then added exactly once, as by the
// whole contour, and the chains merely split where the pieces meet (the sweep treats that like
// any two chains meeting at a vertex). A long stroke's outline is built so (stroke.hpp).
//
// Clipping happens here, once: x is projected onto [clip.x0, clip.x1] (an edge leaving the box
// sideways is split where it crosses the side and continues along the side: the area to the
// right of it inside the box is unchanged), and y is cut to [clip.y0, clip.y1]. So coordinates
// like 1e12 cost nothing later and all arithmetic downstream stays near the canvas.
#include "geometry.hpp"
#include <splinefig/base/huge_pages.hpp>

#include <splinefig/image/image.hpp>

#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace splinefig::render::detail {

struct Chain {
  std::size_t first = 0, last = 0;  // vertex indices in Geometry::verts, inclusive, ascending y
  int dir = 1;                       // +1: the contour runs down (increasing y); -1: up
  double ymin = 0, ymax = 0, xmin = 0, xmax = 0;
  double xdy = 0;  // the integral of x dy along the chain (ascending y): -dir xdy summed over a
                   // shape's chains is the integral of its winding number over the clip box
};

// Vertex storage whose resize() leaves the new vertices unwritten (every vertex is written
// before it is read). A long stroke's outline is assembled so: the array is sized once, then
// each thread copies its pieces into place, and the memory is first touched (and zeroed by the
// system) by those threads, not by one thread beforehand.
using Vertices = std::vector<Vec2, UninitializedAllocator<Vec2>>;

struct Geometry {
  Vertices verts;
  std::vector<Chain> chains;
};

class ChainBuilder {
 public:
  // Points are translated by -shift on input; `clip` is in the translated coordinates.
  ChainBuilder(Geometry& g, Box clip, Vec2 shift = {}) : g_(g), clip_(clip), shift_(shift) {}
  void move_to(Vec2 p);
  void line_to(Vec2 p) {
    const Vec2 b{p.x - shift_.x, p.y - shift_.y};
    // The common case, inline: inside the clip box, continuing the current chain.
    if (in_chain_ && b.x >= clip_.x0 && b.x <= clip_.x1 && b.y >= clip_.y0 && b.y <= clip_.y1 &&
        (b.y - cur_.y) * chain_dir_ > 0 && g_.verts.back() == cur_) {
      cur_ = b;
      g_.verts.push_back(b);
      return;
    }
    line_to_slow(b);
  }
  // Room for about n more vertices (avoids regrowing a large vertex array many times).
  void expect(std::size_t n) {
    auto& v = g_.verts;
    if (v.capacity() < v.size() + n) reserve_huge(v, std::max(2 * v.capacity(), v.size() + n));
  }
  void close();
  // Ends the current contour without its closing edge: a piece of a contour that other pieces
  // complete.
  void leave_open();
  const Box& clip() const { return clip_; }  // in input coordinates when shift is zero

 private:
  void line_to_slow(Vec2 b);  // translated coordinates
  void segment_to(Vec2 b);    // translated coordinates
  void clip_y(Vec2 a, Vec2 b);
  void edge(Vec2 a, Vec2 b);
  void end_chain();

  Geometry& g_;
  Box clip_;
  Vec2 shift_;
  Vec2 start_{}, cur_{};
  bool open_contour_ = false;
  bool in_chain_ = false;
  std::size_t chain_first_ = 0;
  int chain_dir_ = 0;
};

}  // namespace splinefig::render::detail
