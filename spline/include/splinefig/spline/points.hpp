#pragma once
// Points of any dimension stored flat: the memo splines x, y, z (and its Genesis demo six
// coordinates) one coordinate at a time, so a point is just `dim` consecutive doubles.
#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

namespace splinefig {

struct Points {
  int dim = 0;                  // coordinates per point (>= 1 once a point is added)
  std::vector<double> coords;   // point i is coords[i*dim .. i*dim + dim)

  Points() = default;
  explicit Points(int dim, std::size_t count = 0)
      : dim(dim), coords(count * static_cast<std::size_t>(dim), 0.0) {}

  std::size_t size() const { return dim > 0 ? coords.size() / static_cast<std::size_t>(dim) : 0; }
  bool empty() const { return size() == 0; }

  std::span<const double> operator[](std::size_t i) const {
    return {coords.data() + i * static_cast<std::size_t>(dim), static_cast<std::size_t>(dim)};
  }
  std::span<double> operator[](std::size_t i) {
    return {coords.data() + i * static_cast<std::size_t>(dim), static_cast<std::size_t>(dim)};
  }

  void push_back(std::span<const double> p) {
    assert(dim == 0 || static_cast<int>(p.size()) == dim);
    if (dim == 0) dim = static_cast<int>(p.size());
    coords.insert(coords.end(), p.begin(), p.end());
  }
};

}  // namespace splinefig
