// Edge modes and the per-axis weight tables of the resampling contract (resample.hpp).
#include <splinefig/resample/resample.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace splinefig {

std::optional<Edge> parse_edge(std::string_view name) {
  if (name == "clamp") return Edge::clamp;
  if (name == "mirror") return Edge::mirror;
  if (name == "wrap") return Edge::wrap;
  if (name == "black") return Edge::black;
  return std::nullopt;
}

const char* edge_name(Edge e) {
  switch (e) {
    case Edge::clamp: return "clamp";
    case Edge::mirror: return "mirror";
    case Edge::wrap: return "wrap";
    case Edge::black: return "black";
  }
  return "?";
}

long edge_index(long j, long size, Edge e) {
  if (j >= 0 && j < size) return j;
  switch (e) {
    case Edge::clamp: return j < 0 ? 0 : size - 1;
    case Edge::mirror: {
      // ... p1 p0 | p0 p1 ... p_{n-1} | p_{n-1} ...: period 2n, reflected in its second half.
      const long m = ((j % (2 * size)) + 2 * size) % (2 * size);
      return m < size ? m : 2 * size - 1 - m;
    }
    case Edge::wrap: return ((j % size) + size) % size;
    case Edge::black: return -1;
  }
  return -1;
}

AxisWeights axis_weights(const Kernel& k, int src, int dst) {
  AxisWeights ax;
  ax.src = src;
  ax.dst = dst;
  const double scale = std::max(1.0, double(src) / double(dst));
  std::vector<std::vector<double>> rows(static_cast<size_t>(dst));
  std::vector<long> first(static_cast<size_t>(dst));
  int taps = 1;
  for (int i = 0; i < dst; ++i) {
    // x = (i + 1/2) S / D with one rounding: the numerator (2i+1) S is an exact integer.
    const double x = double((2 * static_cast<long long>(i) + 1) * src) / (2.0 * dst);
    // k((x - (j + 1/2)) / f) can be non-zero only for (x - (j+1/2))/f in [lo, hi).
    long j0 = static_cast<long>(std::floor(x - k.support().hi * scale - 0.5));
    long j1 = static_cast<long>(std::ceil(x - k.support().lo * scale - 0.5));
    std::vector<double> w;
    double sum = 0, sumabs = 0;
    for (long j = j0; j <= j1; ++j) {
      const double v = k((x - (double(j) + 0.5)) / scale);
      w.push_back(v);
      sum += v;
      sumabs += std::abs(v);
    }
    if (!(std::abs(sum) > 1e-12 * sumabs) || !std::isfinite(sum))
      throw ResampleError("filter " + k.name() + ": its weights sum to zero at output pixel " +
                                  std::to_string(i));
    size_t a = 0, b = w.size();
    while (a + 1 < b && w[a] == 0) ++a;
    while (b - 1 > a && w[b - 1] == 0) --b;
    std::vector<double> kept(w.begin() + static_cast<long>(a), w.begin() + static_cast<long>(b));
    for (double& v : kept) v /= sum;
    first[static_cast<size_t>(i)] = j0 + static_cast<long>(a);
    taps = std::max(taps, static_cast<int>(kept.size()));
    rows[static_cast<size_t>(i)] = std::move(kept);
  }
  ax.taps = taps;
  ax.first = std::move(first);
  ax.w.assign(static_cast<size_t>(dst) * static_cast<size_t>(taps), 0.0f);
  ax.lo = ax.first.empty() ? 0 : ax.first[0];
  ax.hi = ax.lo;
  for (int i = 0; i < dst; ++i) {
    const auto& r = rows[static_cast<size_t>(i)];
    std::transform(r.begin(), r.end(), ax.w.begin() + static_cast<long>(i) * taps,
                   [](double v) { return static_cast<float>(v); });
    ax.lo = std::min(ax.lo, ax.first[static_cast<size_t>(i)]);
    ax.hi = std::max(ax.hi, ax.first[static_cast<size_t>(i)] + taps - 1);
  }
  return ax;
}

}  // namespace splinefig
