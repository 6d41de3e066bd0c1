#pragma once
// Pixel values under a piecewise-polynomial pixel filter, computed exactly.
//
// The value of pixel (i, j) is the shape's indicator convolved with k(x) k(y) at the pixel
// centre c: V = integral over the shape of k(c_x - x) k(c_y - y), divided by (integral of k)^2
// so that a solid fill gives 1. The kernel's breakpoints lo + p all fall on one grid offset by
// delta = frac(0.5 - lo) from the pixel grid, so on that "cell" grid every unit cell sees one
// polynomial piece per axis, and V is a fixed linear combination of the cells' moments
// M_mn = integral over (shape & cell) of u^m v^n (u, v the cell-local coordinates).
//
// The moments come from the same signed boundary edges as box coverage (sweep.hpp): the part
// of the region right of an edge inside its cell has moment integral v^n (1 - u^(m+1))/(m+1) dv
// along the edge, a polynomial of degree <= 2D-1 in v, integrated exactly by D-point Gauss-
// Legendre; every cell further right gains the full-width term cover_n/(m+1) with
// cover_n = integral v^n dv, carried by a running sum as in the box case. The 2-D convolution
// is then separable: first along x over each cell row, then along y.
#include "prepare.hpp"

#include <vector>

namespace splinefig::render::detail {

struct FilterGrid {
  int pieces = 1, degree1 = 1;  // P pieces, D coefficients (degree + 1) per piece
  double delta = 0;             // cell grid = pixel grid shifted by delta
  int K = 0;                    // pixel i, piece p  <->  cell i - p + K
  std::vector<double> b;        // b[p*D + m]: weight of u^m in cell-local form, normalized
  Box clip;                     // region of cell-grid coordinates that can affect the canvas
  int width = 0, height = 0;
  // Canvas rows that a shape (in cell coordinates) can affect.
  void rows_of(const Shape& s, int& row0, int& row1) const;
};

// A box kernel (one constant piece on [-1/2, 1/2)): pixel values are plain area coverage.
bool exact_area(const Kernel& k);

FilterGrid make_filter_grid(const Kernel& k, int width, int height);

struct FilterScratch {
  std::vector<double> own, cover;  // per cell column: D*D own moments, D cover terms
  std::vector<double> rows;        // x-convolved cell rows: (row count) x width x D
  std::vector<int> row_lo, row_hi; // per x-convolved row: pixel columns in use
  std::vector<double> line;        // one output row of values
};

void render_filtered(const Geometry& g, const Prepared& p, const FilterGrid& grid, Image& img, int r0, int r1,
                     FilterScratch& fs, StripSweep& sweep);

}  // namespace splinefig::render::detail
