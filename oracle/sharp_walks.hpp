#pragma once
// Seeded random walks built to reach the hard cases of a stroke's outline, for the tests and the
// benchmarks that hold the renderer to union_coverage.hpp: hairpins and near-reversals (turns of
// 150-180 degrees, exact reversals among them), sharp turns, and segments shorter than the
// half-width next to them. Test input, not a reference: it computes no coverage.
#include "union_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace oracle {

// n points of a walk inside [lo, hi]^2 (reflected at its sides) for a stroke of `width`: each
// step's length is log-uniform in [0.05, 3] half-widths (one in five uniform in [1, 4] widths),
// each turn a near-reversal (two in five, one in ten of those exact), a turn of 60-150 degrees
// (one in four) or any turn.
inline std::vector<P2> sharp_walk(std::mt19937_64& rng, int n, double width, double lo, double hi) {
  std::uniform_real_distribution<double> u(0, 1);
  const double h = width / 2;
  auto reflect = [&](double v) {
    const double span = hi - lo;
    double t = std::fmod(v - lo, 2 * span);
    if (t < 0) t += 2 * span;
    return lo + (t > span ? 2 * span - t : t);
  };
  std::vector<P2> p{{lo + (hi - lo) * u(rng), lo + (hi - lo) * u(rng)}};
  double dir = 2 * kPi * u(rng);
  for (int i = 1; i < n; ++i) {
    const double kind = u(rng);
    double turn;
    if (kind < 0.4)
      turn = u(rng) < 0.1 ? kPi : kPi * (150 + 30 * u(rng)) / 180;
    else if (kind < 0.65)
      turn = kPi * (60 + 90 * u(rng)) / 180;
    else
      turn = kPi * u(rng);
    dir += u(rng) < 0.5 ? turn : -turn;
    const double len = u(rng) < 0.2 ? width * (1 + 3 * u(rng)) : h * std::exp(std::log(0.05) + std::log(60.0) * u(rng));
    p.push_back({reflect(p.back().x + len * std::cos(dir)), reflect(p.back().y + len * std::sin(dir))});
  }
  return p;
}

}  // namespace oracle
