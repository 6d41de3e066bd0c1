#pragma once
// Exact area coverage of one pixel row from signed boundary edges (the box pixel filter).
//
// An edge piece with sign s says "the region begins (s = +1) or ends (s = -1) to my right". For
// the part of the edge inside column i, the area to its right within the column is dy times
// (i + 1 - mean x); the rest of dy is the full-width cover of every column after i. Writing the
// first into acc[i] and the remainder into acc[i+1] makes the prefix sum of acc the exact area
// of the region in each pixel (the accumulation of font-rs, fed only with boundary edges).
#include <algorithm>
#include <cmath>
#include <vector>

namespace splinefig::render::detail {

struct BoxRow {
  std::vector<double> acc;  // width + 2 entries, kept zero between rows
  int width = 0;
  double y0 = 0;            // top of the row
  int cmin = 0, cmax = -1;  // touched columns

  void reset(int w) {
    width = w;
    acc.assign(static_cast<std::size_t>(w) + 2, 0.0);
    cmin = 0;
    cmax = -1;
  }
  void begin(double top) {
    y0 = top;
    cmin = width + 1;
    cmax = -1;
  }
  void cell(int i, double dy, double xmean, double s) {
    const double a = dy * (static_cast<double>(i + 1) - xmean);
    acc[static_cast<std::size_t>(i)] += s * a;
    acc[static_cast<std::size_t>(i) + 1] += s * (dy - a);
  }
  void edge(double xa, double ya, double xb, double yb, double s) {
    const double dy = yb - ya;
    if (xa > xb) std::swap(xa, xb);  // the region right of the edge does not depend on direction
    const int W = width;
    int i0 = std::clamp(static_cast<int>(std::floor(xa)), 0, W);
    int i1 = std::clamp(static_cast<int>(std::floor(xb)), 0, W);
    if (i1 > i0 && static_cast<double>(i1) == xb) --i1;  // ends exactly on a column boundary
    cmin = std::min(cmin, i0);
    cmax = std::max(cmax, i1);
    if (i0 == i1) {
      cell(i0, dy, 0.5 * (xa + xb), s);
      return;
    }
    const double dydx = dy / (xb - xa);
    double used = 0;
    double x = xa;
    for (int i = i0; i < i1; ++i) {
      const double xn = static_cast<double>(i + 1);
      const double d = (xn - x) * dydx;
      cell(i, d, 0.5 * (x + xn), s);
      used += d;
      x = xn;
    }
    cell(i1, dy - used, 0.5 * (x + xb), s);
  }
};

}  // namespace splinefig::render::detail
