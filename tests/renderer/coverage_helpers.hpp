#pragma once
// Test helpers: coverage of one drawing call as rendered (white on transparent black, so the
// alpha channel is the coverage), and error statistics against an oracle.
#include <splinefig/renderer/renderer.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace testutil {

inline std::vector<double> rendered_coverage(int w, int h, const std::function<void(splinefig::render::Scene&)>& draw,
                                             int threads = 1) {
  splinefig::render::Scene s(w, h, {0, 0, 0, 0});
  draw(s);
  auto img = splinefig::render::rasterize(s, threads);
  std::vector<double> cov(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) cov[static_cast<std::size_t>(y) * w + x] = img.pixel(x, y)[3];
  return cov;
}

struct ErrorStats {
  double max = 0, mean = 0;
  int worst = -1;
  std::size_t counted = 0;
};

// Max and mean absolute difference over the pixels where either image has coverage.
inline ErrorStats compare(const std::vector<double>& a, const std::vector<double>& b) {
  ErrorStats e;
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == 0 && b[i] == 0) continue;
    double d = std::abs(a[i] - b[i]);
    if (d > e.max) { e.max = d; e.worst = static_cast<int>(i); }
    sum += d;
    ++e.counted;
  }
  e.mean = e.counted ? sum / static_cast<double>(e.counted) : 0;
  return e;
}

}  // namespace testutil
