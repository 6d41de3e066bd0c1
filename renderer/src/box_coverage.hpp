#pragma once
// Exact area coverage of pixel rows from signed boundary edges (the box pixel filter).
//
// An edge piece with sign s says "the region begins (s = +1) or ends (s = -1) to my right". For
// the part of the edge inside column i, the area to its right within the column is dy times
// (i + 1 - mean x); the rest of dy is the full-width cover of every column after i. Writing the
// first into acc[i] and the remainder into acc[i+1] makes the prefix sum of acc the exact area
// of the region in each pixel (the accumulation of font-rs, fed only with boundary edges).
#include <algorithm>
#include <cmath>
#include <cstddef>
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
  // floor(x) clamped to [0, width], without a libm call (x is clipped to the canvas already).
  int column(double x) const {
    x = std::clamp(x, -1.0, static_cast<double>(width) + 1.0);
    const int i = static_cast<int>(x);  // truncation: floor for x >= 0
    return std::clamp(i - (static_cast<double>(i) > x ? 1 : 0), 0, width);
  }
  void cell(int i, double dy, double xmean, double s) {
    const double a = dy * (static_cast<double>(i + 1) - xmean);
    acc[static_cast<std::size_t>(i)] += s * a;
    acc[static_cast<std::size_t>(i) + 1] += s * (dy - a);
  }
  void edge(double xa, double ya, double xb, double yb, double s) {
    const double dy = yb - ya;
    if (xa > xb) std::swap(xa, xb);  // the region right of the edge does not depend on direction
    int i0 = column(xa), i1 = column(xb);
    if (i1 > i0 && static_cast<double>(i1) == xb) --i1;  // ends exactly on a column boundary
    cmin = std::min(cmin, i0);
    cmax = std::max(cmax, i1);
    if (i0 == i1) {
      cell(i0, dy, 0.5 * (xa + xb), s);
      return;
    }
    // The same sums as cell() for each column in turn, with the share a column passes to the
    // next (`carry`) kept in a register: a column crossed fully gets dy/dx, half its own and
    // half passed on, exactly as cell() would compute it.
    const double dydx = dy / (xb - xa);
    double* acc_p = acc.data();
    double x = static_cast<double>(i0 + 1);
    double d = (x - xa) * dydx;
    double a = d * (x - 0.5 * (xa + x));
    acc_p[i0] += s * a;
    double carry = s * (d - a);
    double used = d;
    const double h = s * (dydx * 0.5);
    for (int i = i0 + 1; i < i1; ++i) {
      acc_p[i] = (acc_p[i] + carry) + h;
      carry = h;
      used += dydx;
    }
    x = static_cast<double>(i1);
    d = dy - used;
    a = d * (static_cast<double>(i1 + 1) - 0.5 * (x + xb));
    acc_p[i1] = (acc_p[i1] + carry) + s * a;
    acc_p[i1 + 1] += s * (d - a);
  }
};

// A band of consecutive rows, fed with edge pieces of any height inside it: each piece is cut
// at the rows' boundaries and goes to its rows. The scan converter resolves the union once for
// the whole band (one strip), so its per-strip work is shared by all the band's rows.
struct BoxBand {
  std::vector<BoxRow> rows;
  int top = 0;  // canvas row of rows[0]
  int count = 0;

  void reset(int w, int max_rows) {
    rows.resize(static_cast<std::size_t>(max_rows));
    for (BoxRow& r : rows) r.reset(w);
  }
  void begin(int first_row, int n) {
    top = first_row;
    count = n;
    for (int i = 0; i < n; ++i) rows[static_cast<std::size_t>(i)].begin(static_cast<double>(first_row + i));
  }
  BoxRow& row(int canvas_row) { return rows[static_cast<std::size_t>(canvas_row - top)]; }
  // Back to the state begin() left: every accumulator zero (a strip abandoned part way).
  void clear() {
    for (int i = 0; i < count; ++i) {
      BoxRow& r = rows[static_cast<std::size_t>(i)];
      if (r.cmax >= r.cmin)
        std::fill(r.acc.begin() + r.cmin, r.acc.begin() + std::min(r.cmax + 2, r.width + 2), 0.0);
      r.begin(r.y0);
    }
  }
  void edge(double xa, double ya, double xb, double yb, double s) {
    int r = static_cast<int>(ya);  // ya >= top >= 0: truncation is floor
    if (r + 1 >= yb) {             // within one row: the common case
      rows[static_cast<std::size_t>(r - top)].edge(xa, ya, xb, yb, s);
      return;
    }
    const double dxdy = (xb - xa) / (yb - ya);
    double x = xa, y = ya;
    for (;; ++r) {
      const double yn = static_cast<double>(r + 1);
      if (yn >= yb) {
        rows[static_cast<std::size_t>(r - top)].edge(x, y, xb, yb, s);
        return;
      }
      const double xn = xa + (yn - ya) * dxdy;
      rows[static_cast<std::size_t>(r - top)].edge(x, y, xn, yn, s);
      x = xn;
      y = yn;
    }
  }
};

}  // namespace splinefig::render::detail
