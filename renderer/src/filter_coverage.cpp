#include "filter_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace splinefig::render::detail {
namespace {

// Gauss-Legendre nodes and weights on [0, 1] for n points (exact for degree 2n - 1).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(static_cast<std::size_t>(n), 0);
  w.assign(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = 0;
      for (int j = 0; j < n; ++j) {
        double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j + 1) * z * p1 - j * p2) / (j + 1);
      }
      dp = n * (z * p0 - p1) / (z * z - 1);
      double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[static_cast<std::size_t>(i)] = 0.5 * (1 - z);
    w[static_cast<std::size_t>(i)] = 1.0 / ((1 - z * z) * dp * dp);
  }
}

struct MomentRow {
  FilterScratch& fs;
  int D;
  int qmin;       // cell index of column 0 of the arrays
  int qcount;     // number of columns
  double top;     // cell row top (cell-grid y)
  int cmin, cmax; // touched columns (array indices)
  const std::vector<double>& gx;
  const std::vector<double>& gw;

  void piece(int c, double ua, double va, double ub, double vb, double s) {
    const double dv = vb - va;
    if (!(dv > 0)) return;
    double* own = &fs.own[static_cast<std::size_t>(c) * D * D];
    double* cov = &fs.cover[static_cast<std::size_t>(c) * D];
    cmin = std::min(cmin, c);
    cmax = std::max(cmax, c);
    for (std::size_t g = 0; g < gx.size(); ++g) {
      const double t = gx[g], wt = s * gw[g] * dv;
      const double v = va + t * dv, u = ua + t * (ub - ua);
      double vn = wt;
      for (int n = 0; n < D; ++n) {
        cov[n] += vn;
        double um1 = u;  // u^(m+1)
        for (int m = 0; m < D; ++m) {
          own[m * D + n] += vn * (1 - um1) / (m + 1);
          um1 *= u;
        }
        vn *= v;
      }
    }
  }

  void edge(double xa, double ya, double xb, double yb, double s) {
    const double lo = std::min(xa, xb), hi = std::max(xa, xb);
    int q0 = std::clamp(static_cast<int>(std::floor(lo)), qmin, qmin + qcount - 1);
    int q1 = std::clamp(static_cast<int>(std::floor(hi)), qmin, qmin + qcount - 1);
    if (q1 > q0 && static_cast<double>(q1) == hi) --q1;
    if (q0 == q1) {
      piece(q0 - qmin, xa - q0, ya - top, xb - q0, yb - top, s);
      return;
    }
    // Split at column boundaries, keeping the edge's direction (y increasing).
    const double dx = xb - xa;
    double tprev = 0;
    double xp = xa, yp = ya;
    const int step = dx > 0 ? 1 : -1;
    int q = dx > 0 ? q0 : q1;
    for (;;) {
      const double X = dx > 0 ? q + 1.0 : static_cast<double>(q);
      const bool last = dx > 0 ? q == q1 : q == q0;
      double xn = xb, yn = yb;
      if (!last) {
        double t = (X - xa) / dx;
        t = std::clamp(t, tprev, 1.0);
        xn = X;
        yn = ya + t * (yb - ya);
        tprev = t;
      }
      piece(q - qmin, xp - q, yp - top, xn - q, yn - top, s);
      if (last) break;
      xp = xn;
      yp = yn;
      q += step;
    }
  }
};

}  // namespace

bool exact_area(const Kernel& k) {
  return k.polynomial() && k.lo() == -0.5 && k.pieces().size() == 1 && k.pieces()[0].size() == 1;
}

FilterGrid make_filter_grid(const Kernel& k, int width, int height) {
  FilterGrid g;
  g.width = width;
  g.height = height;
  g.pieces = static_cast<int>(k.pieces().size());
  g.degree1 = k.degree() + 1;
  const int P = g.pieces, D = g.degree1;
  double d = 0.5 - k.lo();
  g.delta = d - std::floor(d);
  g.K = static_cast<int>(std::lround(d - g.delta)) - 1;
  const double norm = 1.0 / k.integral();  // per axis
  g.b.assign(static_cast<std::size_t>(P * D), 0.0);
  // k on piece p in the local variable 1 - u: sum_e a_e (1 - u)^e = sum_m b_m u^m.
  for (int p = 0; p < P; ++p) {
    const auto& a = k.pieces()[static_cast<std::size_t>(p)];
    for (int e = 0; e < static_cast<int>(a.size()); ++e) {
      double binom = 1;
      for (int m = 0; m <= e; ++m) {
        g.b[static_cast<std::size_t>(p * D + m)] += norm * a[static_cast<std::size_t>(e)] * binom * (m % 2 ? -1 : 1);
        binom = binom * (e - m) / (m + 1);
      }
    }
  }
  g.clip = Box{static_cast<double>(g.K - P + 1), static_cast<double>(g.K - P + 1),
               static_cast<double>(width + g.K), static_cast<double>(height + g.K)};
  return g;
}

void FilterGrid::rows_of(const Shape& s, int& row0, int& row1) const {
  const int P = pieces;
  row0 = std::max(0, static_cast<int>(std::floor(s.ymin)) - K);
  row1 = std::min(height, static_cast<int>(std::ceil(s.ymax)) - K + P - 1);
}

void render_filtered(const Geometry& g, const Prepared& p, const FilterGrid& grid, Image& img, int r0, int r1,
                     FilterScratch& fs, StripSweep& sweep) {
  const int P = grid.pieces, D = grid.degree1, K = grid.K, W = img.width;
  const int ya = std::max(r0, p.row0), yb = std::min(r1, p.row1);
  if (ya >= yb) return;
  const int qmin = K - P + 1, qcount = W + P;  // cells qmin .. W-1+K, plus one spare
  const int cr0 = ya - P + 1 + K, cr1 = yb - 1 + K;  // cell rows needed, inclusive
  const int nrows = cr1 - cr0 + 1;
  static thread_local std::vector<double> gx, gw;
  if (static_cast<int>(gx.size()) != D) gauss_legendre(D, gx, gw);
  fs.own.assign(static_cast<std::size_t>(qcount + 1) * D * D, 0.0);
  fs.cover.assign(static_cast<std::size_t>(qcount + 1) * D, 0.0);
  fs.rows.assign(static_cast<std::size_t>(nrows) * W * D, 0.0);
  fs.row_lo.assign(static_cast<std::size_t>(nrows), W);
  fs.row_hi.assign(static_cast<std::size_t>(nrows), -1);

  sweep.reset(g, p.shape);
  std::vector<double> M(static_cast<std::size_t>(D * D)), run(static_cast<std::size_t>(D));
  for (int r = cr0; r <= cr1; ++r) {
    MomentRow row{fs, D, qmin, qcount, static_cast<double>(r), qcount, -1, gx, gw};
    sweep.strip(static_cast<double>(r), static_cast<double>(r + 1), row);
    if (sweep.over()) return;  // stopped at the work limit: the item is refused
    if (row.cmax < row.cmin) continue;
    // Moments per cell = own terms + running full-width cover from the cells to the left.
    std::fill(run.begin(), run.end(), 0.0);
    double* T = &fs.rows[static_cast<std::size_t>(r - cr0) * W * D];
    const int px_lo = std::max(0, row.cmin + qmin - K), px_hi = std::min(W - 1, row.cmax + qmin - K + P - 1);
    fs.row_lo[static_cast<std::size_t>(r - cr0)] = px_lo;
    fs.row_hi[static_cast<std::size_t>(r - cr0)] = px_hi;
    for (int c = row.cmin; c <= row.cmax; ++c) {
      double* own = &fs.own[static_cast<std::size_t>(c) * D * D];
      double* cov = &fs.cover[static_cast<std::size_t>(c) * D];
      for (int m = 0; m < D; ++m)
        for (int n = 0; n < D; ++n) M[static_cast<std::size_t>(m * D + n)] = own[m * D + n] + run[static_cast<std::size_t>(n)] / (m + 1);
      for (int n = 0; n < D; ++n) run[static_cast<std::size_t>(n)] += cov[n];
      std::fill(own, own + D * D, 0.0);
      std::fill(cov, cov + D, 0.0);
      // Cell q feeds pixel px = q - K + pp through kernel piece pp.
      const int q = c + qmin;
      for (int pp = 0; pp < P; ++pp) {
        const int px = q - K + pp;
        if (px < 0 || px >= W) continue;
        double* t = &T[static_cast<std::size_t>(px) * D];
        for (int m = 0; m < D; ++m) {
          const double bm = grid.b[static_cast<std::size_t>(pp * D + m)];
          if (bm == 0) continue;
          for (int n = 0; n < D; ++n) t[n] += bm * M[static_cast<std::size_t>(m * D + n)];
        }
      }
    }
  }
  // Along y: pixel row py takes cell row py - pp + K through piece pp.
  for (int py = ya; py < yb; ++py) {
    int lo = W, hi = -1;
    for (int pp = 0; pp < P; ++pp) {
      const int ri = py - pp + K - cr0;
      lo = std::min(lo, fs.row_lo[static_cast<std::size_t>(ri)]);
      hi = std::max(hi, fs.row_hi[static_cast<std::size_t>(ri)]);
    }
    for (int px = lo; px <= hi; ++px) {
      double v = 0;
      for (int pp = 0; pp < P; ++pp) {
        const int ri = py - pp + K - cr0;
        const double* t = &fs.rows[(static_cast<std::size_t>(ri) * W + px) * D];
        for (int n = 0; n < D; ++n) v += grid.b[static_cast<std::size_t>(pp * D + n)] * t[n];
      }
      if (std::abs(v) > 1e-12) {
        over(img.pixel(px, py), p.paint, static_cast<float>(v));
      }
    }
  }
}

}  // namespace splinefig::render::detail
