// The resampler against a float64 reference written here from the contract alone: a direct
// 2-D sum over source pixels (no separability, no weight tables), kernels from their own
// formulas or the spline core's kernel(), edges mapped by hand.
#include <catch2/catch.hpp>

#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <numbers>
#include <functional>
#include <random>
#include <type_traits>

using namespace splinefig;

namespace {

constexpr double pi = std::numbers::pi;

using RefKernel = std::function<double(double)>;

RefKernel reference_kernel(const std::string& spec) {
  if (spec == "box") return [](double s) { return s >= -0.5 && s < 0.5 ? 1.0 : 0.0; };
  if (spec == "tent") return [](double s) { return std::max(0.0, 1 - std::abs(s)); };
  if (spec == "lanczos3")
    return [](double s) {
      if (s == 0) return 1.0;
      if (std::abs(s) >= 3) return 0.0;
      return 3 * std::sin(pi * s) * std::sin(pi * s / 3) / (pi * pi * s * s);
    };
  if (spec == "catmull-rom")  // Mitchell-Netravali B = 0, C = 1/2
    return [](double s) {
      const double x = std::abs(s);
      return x < 1 ? 1.5 * x * x * x - 2.5 * x * x + 1 : x < 2 ? -0.5 * x * x * x + 2.5 * x * x - 4 * x + 2 : 0.0;
    };
  if (spec == "bspline")
    return [](double s) {
      const double x = std::abs(s);
      return x < 1 ? (3 * x * x * x - 6 * x * x + 4) / 6 : x < 2 ? (2 - x) * (2 - x) * (2 - x) / 6 : 0.0;
    };
  const Basis b = parse_basis(spec);
  return [b](double s) { return kernel(b, s); };
}

// Source index of position j, or -1 for black; written from the contract's pictures.
long reference_edge(long j, long n, Edge e) {
  if (j >= 0 && j < n) return j;
  if (e == Edge::black) return -1;
  if (e == Edge::clamp) return j < 0 ? 0 : n - 1;
  if (e == Edge::wrap) {
    while (j < 0) j += n;
    return j % n;
  }
  // mirror: ... p1 p0 | p0 p1 ... p_{n-1} | p_{n-1} p_{n-2} ...
  while (j < 0 || j >= n) j = j < 0 ? -1 - j : 2 * n - 1 - j;
  return j;
}

std::vector<double> reference_resample(const Image& src, int W, int H, const RefKernel& k, Edge e) {
  const int C = src.channels;
  std::vector<double> out(static_cast<size_t>(W) * H * C);
  const double fx = std::max(1.0, double(src.width) / W), fy = std::max(1.0, double(src.height) / H);
  for (int i = 0; i < H; ++i)
    for (int o = 0; o < W; ++o) {
      const double x = (o + 0.5) * src.width / W, y = (i + 0.5) * src.height / H;
      std::vector<double> acc(static_cast<size_t>(C), 0.0);
      double wsum = 0;
      // Every position whose kernel value can be non-zero (supports lie within [-3, 3]).
      for (long r = static_cast<long>(std::floor(y - 3 * fy)) - 1; r <= static_cast<long>(std::ceil(y + 3 * fy)) + 1; ++r)
        for (long c = static_cast<long>(std::floor(x - 3 * fx)) - 1; c <= static_cast<long>(std::ceil(x + 3 * fx)) + 1; ++c) {
          const double w = k((x - (c + 0.5)) / fx) * k((y - (r + 0.5)) / fy);
          if (w == 0) continue;
          wsum += w;
          const long sr = reference_edge(r, src.height, e), sc = reference_edge(c, src.width, e);
          if (sr < 0 || sc < 0) continue;
          for (int ch = 0; ch < C; ++ch) acc[static_cast<size_t>(ch)] += w * src.at(static_cast<int>(sc), static_cast<int>(sr), ch);
        }
      for (int ch = 0; ch < C; ++ch) out[(static_cast<size_t>(i) * W + o) * C + ch] = acc[static_cast<size_t>(ch)] / wsum;
    }
  return out;
}

Image random_image(int w, int h, int c, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Image img(w, h, c);
  for (auto& v : img.pixels) v = u(rng);
  return img;
}

double max_error(const Image& got, const std::vector<double>& ref) {
  double e = 0;
  for (size_t i = 0; i < ref.size(); ++i) e = std::max(e, std::abs(double(got.pixels[i]) - ref[i]));
  return e;
}

}  // namespace

TEST_CASE("resampling matches a float64 reference for every edge mode, up, down and non-uniform") {
  struct Case { int sw, sh, dw, dh; };
  const Case cases[] = {{13, 9, 29, 31}, {37, 41, 11, 7}, {20, 20, 45, 8}, {7, 30, 7, 30}, {1, 5, 3, 2}, {64, 3, 5, 17}};
  const char* filters[] = {"catmull-rom", "bspline", "beta:b1=2,b2=1", "cardinal:a=1", "tensioned-bspline:a=0.5",
                           "uniform-bspline:degree=2", "box", "tent", "lanczos3"};
  const Edge edges[] = {Edge::clamp, Edge::mirror, Edge::wrap, Edge::black};
  unsigned seed = 1;
  for (const auto& cs : cases)
    for (const char* spec : filters)
      for (Edge e : edges) {
        const int channels = 1 + static_cast<int>(seed % 5);  // 1 .. 5
        const Image src = random_image(cs.sw, cs.sh, channels, seed++);
        INFO(spec << " " << edge_name(e) << " " << cs.sw << "x" << cs.sh << " -> " << cs.dw << "x" << cs.dh
                  << " channels " << channels);
        ResampleOptions opt;
        opt.edge = e;
        const Image got = resample(src, cs.dw, cs.dh, parse_kernel(spec), opt);
        REQUIRE(got.channels == channels);
        CHECK(max_error(got, reference_resample(src, cs.dw, cs.dh, reference_kernel(spec), e)) <= 1e-5);
      }
}

TEST_CASE("every channel count from 1 to 4 with each edge mode") {
  for (int c = 1; c <= 4; ++c)
    for (Edge e : {Edge::clamp, Edge::mirror, Edge::wrap, Edge::black}) {
      const Image src = random_image(17, 12, c, 100u + static_cast<unsigned>(c));
      ResampleOptions opt;
      opt.edge = e;
      INFO(c << " channels, " << edge_name(e));
      for (auto [w, h] : {std::pair{40, 27}, std::pair{6, 5}}) {
        const Image got = resample(src, w, h, parse_kernel("catmull-rom"), opt);
        CHECK(max_error(got, reference_resample(src, w, h, reference_kernel("catmull-rom"), e)) <= 1e-5);
      }
    }
}

TEST_CASE("the result is bit-identical for any thread count") {
  for (auto [w, h] : {std::pair{203, 150}, std::pair{31, 22}}) {
    const Image src = random_image(97, 61, 3, 7);
    ResampleOptions opt;
    opt.edge = Edge::mirror;
    opt.threads = 1;
    const Image one = resample(src, w, h, parse_kernel("bspline"), opt);
    for (int t : {2, 3, 7}) {
      opt.threads = t;
      const Image many = resample(src, w, h, parse_kernel("bspline"), opt);
      CHECK(many.pixels == one.pixels);
    }
  }
}

TEST_CASE("weights: double precision, normalised, widened only when reducing") {
  const AxisWeights up = axis_weights(parse_kernel("catmull-rom"), 10, 20);
  CHECK(up.taps == 4);
  // Output 0: x = 0.25; taps at centres -1.5 .. 1.5 give k(1.75), k(0.75), k(-0.25), k(-1.25).
  const RefKernel k = reference_kernel("catmull-rom");
  CHECK(up.first[0] == -2);
  CHECK(up.w[0] == Approx(k(1.75)).margin(1e-7));
  CHECK(up.w[2] == Approx(k(-0.25)).margin(1e-7));
  const AxisWeights down = axis_weights(parse_kernel("bspline"), 40, 10);
  CHECK(down.taps >= 15);
  CHECK(down.taps <= 17);
  for (int i = 0; i < 10; ++i) {
    double s = 0;
    for (int t = 0; t < down.taps; ++t) s += down.w[static_cast<size_t>(i * down.taps + t)];
    CHECK(s == Approx(1).margin(1e-6));
  }
  CHECK_THROWS_AS(resample(random_image(4, 4, 1, 1), 0, 3, parse_kernel("bspline")), std::invalid_argument);
}

TEST_CASE("axis weights depend on the kernel and the sizes only: the edge mode decides what the taps read") {
  // The table takes no edge mode (every mode keeps all taps in the sum), so black edges give the share of the (normalised) weights that fall inside the image:
  // a 10x1 image of ones, doubled in width, predicted from the tables alone.
  const Kernel k = parse_kernel("bspline");
  const AxisWeights ax = axis_weights(k, 10, 20), ay = axis_weights(k, 1, 1);
  double wy = 0;
  for (int t = 0; t < ay.taps; ++t)
    if (ay.first[0] + t == 0) wy = ay.w[static_cast<size_t>(t)];
  Image ones(10, 1, 1);
  std::fill(ones.pixels.begin(), ones.pixels.end(), 1.0f);
  for (Edge e : {Edge::clamp, Edge::mirror, Edge::wrap, Edge::black}) {
    INFO(edge_name(e));
    ResampleOptions opt;
    opt.edge = e;
    const Image out = resample(ones, 20, 1, k, opt);
    for (int i = 0; i < 20; ++i) {
      double inside = 0;
      for (int t = 0; t < ax.taps; ++t) {
        const long j = ax.first[static_cast<size_t>(i)] + t;
        if (j >= 0 && j < 10) inside += ax.w[static_cast<size_t>(i * ax.taps + t)];
      }
      CHECK(out.at(i, 0, 0) == Approx(e == Edge::black ? inside * wy : 1.0).margin(1e-6));
    }
  }
}

TEST_CASE("edge modes map positions as the contract draws them") {
  CHECK(edge_index(-1, 4, Edge::mirror) == 0);
  CHECK(edge_index(-2, 4, Edge::mirror) == 1);
  CHECK(edge_index(4, 4, Edge::mirror) == 3);
  CHECK(edge_index(9, 4, Edge::mirror) == 1);
  CHECK(edge_index(-1, 4, Edge::wrap) == 3);
  CHECK(edge_index(-9, 4, Edge::wrap) == 3);
  CHECK(edge_index(-5, 4, Edge::clamp) == 0);
  CHECK(edge_index(4, 4, Edge::black) == -1);
  CHECK(parse_edge("mirror") == Edge::mirror);
  CHECK_FALSE(parse_edge("reflect"));
}
