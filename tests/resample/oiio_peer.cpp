// OpenImageIO's ImageBufAlgo::resize as a peer. Where its semantics are ours (clamped edges,
// per-axis normalised weights, a symmetric kernel widened by the same factor) the two agree to
// 1e-5; the tests below also pin where they differ (docs/resample.md), each side against a
// direct float64 sum written here from the contract.
#include <catch2/catch.hpp>

#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <OpenImageIO/filter.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <functional>
#include <random>

using namespace splinefig;

namespace {

Image random_image(int w, int h, int c, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Image img(w, h, c);
  for (auto& v : img.pixels) v = u(rng);
  return img;
}

Image oiio_resize(const Image& src, int w, int h, const std::string& name, OIIO::Filter2D* filter = nullptr) {
  OIIO::ImageBuf in(OIIO::ImageSpec(src.width, src.height, src.channels, OIIO::TypeDesc::FLOAT),
                    const_cast<float*>(src.pixels.data()));
  OIIO::ImageBuf out(OIIO::ImageSpec(w, h, src.channels, OIIO::TypeDesc::FLOAT));
  const bool ok = filter ? OIIO::ImageBufAlgo::resize(out, in, filter, {}, 1)
                         : OIIO::ImageBufAlgo::resize(out, in, name, 0.0f, {}, 1);
  REQUIRE(ok);
  Image r(w, h, src.channels);
  out.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, r.pixels.data());
  return r;
}

double max_diff(const Image& a, const Image& b) {
  double e = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) e = std::max(e, double(std::abs(a.pixels[i] - b.pixels[i])));
  return e;
}

// The contract as a direct 2-D float64 sum over every source pixel: output (o, i) at source
// position x = (o + 1/2) S/D, weights k((x - (j + 1/2)) / f), f = max(1, S/D), normalised,
// positions outside the image read by `edge` (clamp, wrap or black: 0 but counted).
double max_diff_to_reference(const Image& got, const Image& src, const std::function<double(double)>& k, Edge edge) {
  const int W = got.width, H = got.height;
  const double fx = std::max(1.0, double(src.width) / W), fy = std::max(1.0, double(src.height) / H);
  auto index = [edge](long j, long n) -> long {
    if (j >= 0 && j < n) return j;
    if (edge == Edge::black) return -1;
    if (edge == Edge::clamp) return j < 0 ? 0 : n - 1;
    return ((j % n) + n) % n;  // wrap
  };
  double e = 0;
  for (int i = 0; i < H; ++i)
    for (int o = 0; o < W; ++o) {
      const double x = (o + 0.5) * src.width / W, y = (i + 0.5) * src.height / H;
      std::vector<double> acc(static_cast<size_t>(src.channels), 0.0);
      double wsum = 0;
      for (long r = long(std::floor(y - 3 * fy)) - 1; r <= long(std::ceil(y + 3 * fy)) + 1; ++r)
        for (long c = long(std::floor(x - 3 * fx)) - 1; c <= long(std::ceil(x + 3 * fx)) + 1; ++c) {
          const double w = k((x - (c + 0.5)) / fx) * k((y - (r + 0.5)) / fy);
          if (w == 0) continue;
          wsum += w;
          const long sr = index(r, src.height), sc = index(c, src.width);
          if (sr < 0 || sc < 0) continue;
          for (int ch = 0; ch < src.channels; ++ch) acc[size_t(ch)] += w * src.at(int(sc), int(sr), ch);
        }
      for (int ch = 0; ch < src.channels; ++ch) e = std::max(e, std::abs(double(got.at(o, i, ch)) - acc[size_t(ch)] / wsum));
    }
  return e;
}

// Closed forms, written here (Keys' cubic with a = -1/2, and the cubic B-spline).
double catmull_rom_form(double s) {
  const double x = std::abs(s);
  return x < 1 ? 1.5 * x * x * x - 2.5 * x * x + 1 : x < 2 ? -0.5 * x * x * x + 2.5 * x * x - 4 * x + 2 : 0.0;
}
double bspline_form(double s) {
  const double x = std::abs(s);
  return x < 1 ? (3 * x * x * x - 6 * x * x + 4) / 6 : x < 2 ? (2 - x) * (2 - x) * (2 - x) / 6 : 0.0;
}

// One of our filters inside OpenImageIO, scaled to a width in destination pixels the way its
// own filters are (k(x * support / width)); `mirror` evaluates k(-x).
struct Wrapped : OIIO::Filter2D {
  Kernel f;
  double sx, sy;
  bool mirror;
  Wrapped(Kernel filter, float w, float h, bool m)
      : OIIO::Filter2D(w, h), f(std::move(filter)), sx(4.0 / w), sy(4.0 / h), mirror(m) {}
  float k(double s) const { return static_cast<float>(f(mirror ? -s : s)); }
  float operator()(float x, float y) const override { return k(x * sx) * k(y * sy); }
  bool separable() const override { return true; }
  float xfilt(float x) const override { return k(x * sx); }
  float yfilt(float y) const override { return k(y * sy); }
  OIIO::string_view name() const override { return "splinefig"; }
};

}  // namespace

TEST_CASE("OpenImageIO resize agrees to 1e-5 with clamped edges and symmetric kernels") {
  struct Pair { const char* ours; const char* theirs; };
  const Pair filters[] = {{"catmull-rom", "catmull-rom"}, {"bspline", "bspline"}, {"tent", "triangle"}, {"lanczos3", "lanczos3"}};
  struct Size { int sw, sh, dw, dh; };
  // Up, down, and non-uniform scales where x is enlarged at least as much as y (see below).
  const Size sizes[] = {{16, 16, 40, 40}, {48, 40, 12, 10}, {20, 30, 50, 45}, {40, 24, 10, 24}, {33, 17, 80, 9}};
  unsigned seed = 3;
  for (const auto& p : filters)
    for (const auto& s : sizes) {
      const Image src = random_image(s.sw, s.sh, 1 + static_cast<int>(seed % 4), seed);
      ++seed;
      ResampleOptions opt;
      opt.edge = Edge::clamp;
      opt.threads = 1;
      const Image ours = resample(src, s.dw, s.dh, parse_kernel(p.ours), opt);
      const Image theirs = oiio_resize(src, s.dw, s.dh, p.theirs);
      INFO(p.ours << " " << s.sw << "x" << s.sh << " -> " << s.dw << "x" << s.dh);
      CHECK(max_diff(ours, theirs) <= 1e-5);
    }
}

TEST_CASE("OpenImageIO evaluates k(centre - x): an asymmetric Beta kernel comes out mirrored") {
  const Image src = random_image(24, 20, 3, 11);
  const Kernel beta = parse_kernel("beta:b1=2,b2=1");
  for (auto [w, h] : {std::pair{60, 50}, std::pair{8, 10}}) {
    const float fw = 4.0f * std::max(1.0f, float(w) / src.width), fh = 4.0f * std::max(1.0f, float(h) / src.height);
    ResampleOptions opt;
    opt.threads = 1;
    const Image ours = resample(src, w, h, beta, opt);
    Wrapped same(beta, fw, fh, false), mirrored(beta, fw, fh, true);
    INFO(w << "x" << h);
    // Handing OpenImageIO k(-s) reproduces our k(s) ...
    CHECK(max_diff(ours, oiio_resize(src, w, h, "", &mirrored)) <= 1e-5);
    // ... while handing it k(s) itself gives a visibly different image: the contract's sum
    // with k(-s), where ours is the contract's sum with k(s).
    const Image theirs = oiio_resize(src, w, h, "", &same);
    CHECK(max_diff(ours, theirs) > 1e-2);
    CHECK(max_diff_to_reference(ours, src, [&](double s) { return beta(s); }, Edge::clamp) <= 2e-6);
    CHECK(max_diff_to_reference(theirs, src, [&](double s) { return beta(-s); }, Edge::clamp) <= 1e-5);
  }
}

TEST_CASE("where OpenImageIO differs: edges other than clamp, and y enlarged more than x") {
  const Image src = random_image(16, 12, 1, 21);
  ResampleOptions opt;
  opt.threads = 1;
  // resize always clamps: our black, wrap and mirror edges give other border pixels.
  const Image theirs = oiio_resize(src, 40, 30, "catmull-rom");
  CHECK(max_diff_to_reference(theirs, src, catmull_rom_form, Edge::clamp) <= 1e-5);
  for (Edge e : {Edge::black, Edge::wrap}) {
    opt.edge = e;
    const Image ours = resample(src, 40, 30, parse_kernel("catmull-rom"), opt);
    INFO(edge_name(e));
    CHECK(max_diff(ours, theirs) > 1e-2);
    CHECK(max_diff_to_reference(ours, src, catmull_rom_form, e) <= 2e-6);
  }
  // OpenImageIO 2.4 sizes the tap window of both axes from the filter's width, so when y is
  // enlarged more than x (here 1x and 4x) the y kernel is cut to fewer taps than its support.
  opt.edge = Edge::clamp;
  // Ours keeps the whole support, as the contract's sum does.
  const Image ours = resample(src, 16, 48, parse_kernel("bspline"), opt), cut = oiio_resize(src, 16, 48, "bspline");
  CHECK(max_diff(ours, cut) > 1e-3);
  CHECK(max_diff_to_reference(ours, src, bspline_form, Edge::clamp) <= 2e-6);
  CHECK(max_diff_to_reference(cut, src, bspline_form, Edge::clamp) > 1e-3);
}
