// Filter analysis pinned to closed forms derived here, to an FFT of the sampled kernel, and to
// the spline core's own basis functions.
#include <catch2/catch.hpp>

#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <numbers>
#include <complex>
#include <vector>

using namespace splinefig;

namespace {

constexpr double pi = std::numbers::pi;

double sinc(double x) { return x == 0 ? 1 : std::sin(pi * x) / (pi * x); }

// Catmull-Rom: k = 3/2|x|^3 - 5/2|x|^2 + 1 on |x| < 1, -1/2|x|^3 + 5/2|x|^2 - 4|x| + 2 on
// 1 <= |x| < 2. Integrating by parts until only the jumps of k'' and k''' remain,
//   K(w) = sum_b [k''](b) e^{-iwb} / (iw)^3 + sum_b [k'''](b) e^{-iwb} / (iw)^4,
// with [k''] = -1, 2, -2, 1 at b = -2, -1, 1, 2 and [k'''] = 3, -12, 18, -12, 3 at b = -2..2:
//   K(w) = (18 - 24 cos w + 6 cos 2w) / w^4 + (2 sin 2w - 4 sin w) / w^3.
double catmull_rom_response(double f) {
  const double w = 2 * pi * f;
  return (18 - 24 * std::cos(w) + 6 * std::cos(2 * w)) / std::pow(w, 4) +
         (2 * std::sin(2 * w) - 4 * std::sin(w)) / std::pow(w, 3);
}

// Radix-2 FFT (in place, forward, e^{-2 pi i jk/n}).
void fft(std::vector<std::complex<double>>& a) {
  const size_t n = a.size();
  for (size_t i = 1, j = 0; i < n; ++i) {
    size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (size_t len = 2; len <= n; len <<= 1) {
    const std::complex<double> wl = std::polar(1.0, -2 * pi / double(len));
    for (size_t i = 0; i < n; i += len) {
      std::complex<double> w = 1;
      for (size_t j = 0; j < len / 2; ++j, w *= wl) {
        const auto u = a[i + j], v = a[i + j + len / 2] * w;
        a[i + j] = u + v;
        a[i + j + len / 2] = u - v;
      }
    }
  }
}

}  // namespace

TEST_CASE("a filter's response at f = 0 equals its integral") {
  for (const char* spec : {"catmull-rom", "bspline", "cardinal:a=1", "tensioned-bspline:a=0.5",
                           "beta:b1=2,b2=3", "uniform-bspline:degree=5", "uniform-bspline:degree=2",
                           "box", "tent", "lanczos3"}) {
    const Kernel f = parse_kernel(spec);
    INFO(spec);
    CHECK(std::abs(fourier(f, 0.0) - f.integral()) < 1e-12);
    CHECK(std::abs(response(f, 1e-9) - std::abs(f.integral())) < 1e-12);
  }
  // Independent integrals: partitions of unity integrate to 1; box and tent to 1.
  for (const char* spec : {"catmull-rom", "bspline", "beta:b1=2,b2=3", "uniform-bspline:degree=4", "box", "tent"})
    CHECK(parse_kernel(spec).integral() == Approx(1).epsilon(1e-14));
  // Lanczos3 against a composite Simpson rule written here.
  double simpson = 0;
  const int n = 60000;
  const double h = 6.0 / n;
  for (int i = 0; i <= n; ++i) {
    const double s = -3 + i * h;
    simpson += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * sinc(s) * sinc(s / 3);
  }
  CHECK(parse_kernel("lanczos3").integral() == Approx(simpson * h / 3).epsilon(1e-11));
}

TEST_CASE("the B-spline's response is sinc^4 and Catmull-Rom's is its closed form, to 1e-9") {
  const Kernel b = parse_kernel("bspline"), c = parse_kernel("catmull-rom");
  for (int i = 0; i <= 400; ++i) {
    const double f = i * 0.005;  // 0 .. 2 cycles per sample
    INFO("f = " << f);
    CHECK(std::abs(response(b, f) - std::pow(sinc(f), 4)) < 1e-9);
    CHECK(std::abs(fourier(b, f) - std::pow(sinc(f), 4)) < 1e-9);  // real and positive
    if (f >= 0.05) CHECK(std::abs(fourier(c, f) - catmull_rom_response(f)) < 1e-9);
  }
  CHECK(std::abs(fourier(c, 0.0) - 1.0) < 1e-15);
  // box and tent: sinc and sinc^2.
  for (double f : {0.1, 0.37, 0.5, 1.3, 1.9}) {
    CHECK(std::abs(fourier(parse_kernel("box"), f) - sinc(f)) < 1e-12);
    CHECK(std::abs(fourier(parse_kernel("tent"), f) - sinc(f) * sinc(f)) < 1e-12);
  }
}

TEST_CASE("analytic responses agree with an FFT of the finely sampled kernel to 1e-6") {
  // K(m/(N h)) ~ h sum_j k(x_j) e^{-2 pi i m x_j/(N h)} with x_j = lo + j h; the kernels are
  // continuous, so the trapezoid rule's error is O(h^2) times derivative jumps.
  for (const char* spec : {"catmull-rom", "bspline", "cardinal:a=1", "tensioned-bspline:a=0.5",
                           "beta:b1=2,b2=0", "tent", "lanczos3"}) {
    INFO(spec);
    const Kernel f = parse_kernel(spec);
    const double h = 1.0 / 2048, lo = f.support().lo;
    const size_t N = 1 << 16;  // period 32 samples: frequencies m/32
    std::vector<std::complex<double>> a(N, 0.0);
    for (size_t j = 0; lo + double(j) * h <= f.support().hi; ++j) a[j] = f(lo + double(j) * h) * h;
    fft(a);
    for (size_t m = 0; m <= 64; ++m) {  // f = 0 .. 2
      const double freq = double(m) / (double(N) * h);
      const auto expected = a[m] * std::polar(1.0, -2 * pi * freq * lo);
      CHECK(std::abs(fourier(f, freq) - expected) < 1e-6);
    }
  }
}

TEST_CASE("integral, energy, continuity and interpolation of the kernels") {
  CHECK(energy(parse_kernel("bspline")) == Approx(151.0 / 315).epsilon(1e-13));  // B7(0)
  CHECK(energy(parse_kernel("box")) == Approx(1).epsilon(1e-15));
  CHECK(energy(parse_kernel("tent")) == Approx(2.0 / 3).epsilon(1e-15));
  CHECK(continuity(parse_kernel("box")) == -1);
  CHECK(continuity(parse_kernel("tent")) == 0);
  CHECK(continuity(parse_kernel("catmull-rom")) == 1);
  CHECK(continuity(parse_kernel("bspline")) == 2);
  CHECK(continuity(parse_kernel("beta:b1=2,b2=0")) == 0);
  CHECK(continuity(parse_kernel("lanczos3")) == 1);
  // The classes the theory gives: every cardinal is C1; Duff's B_a (a != 1) and a Beta-spline
  // with b1 = 1, b2 != 0 are C1 (k'' jumps by b2 k'); with b1 != 1 k' jumps: C0; the degree-n
  // B-spline is C(n-1). Values against the spline core's own evaluation of the matrix.
  for (auto [spec, cls] : {std::pair{"catmull-rom", 1}, {"cardinal:a=0", 1}, {"bspline", 2},
                           {"tensioned-bspline:a=0.25", 1}, {"beta:b1=1,b2=7", 1}, {"beta:b1=0.5,b2=1", 0},
                           {"uniform-bspline:degree=5", 4}, {"mitchell-netravali", 1}}) {
    INFO(spec);
    CHECK(continuity(parse_kernel(spec)) == cls);
    CHECK(parse_kernel(spec).integral() == Approx(1).epsilon(1e-13));
    for (double s = -3; s <= 3; s += 0.0625) CHECK(parse_kernel(spec)(s) == Approx(kernel(parse_basis(spec), s)).margin(1e-15));
  }
  for (const char* spec : {"catmull-rom", "cardinal:a=1", "box", "tent", "lanczos3"}) CHECK(interpolating(parse_kernel(spec)));
  for (const char* spec : {"bspline", "tensioned-bspline:a=0.5", "beta:b1=2,b2=0"}) CHECK_FALSE(interpolating(parse_kernel(spec)));
}

TEST_CASE("passband droop and stopband leakage") {
  // B-spline: |K(1/4)| = sinc(1/4)^4 = (2 sqrt 2 / pi)^4 = 64 / pi^4.
  const FilterReport b = analyse(parse_kernel("bspline"));
  CHECK(b.droop == Approx(1 - 64 / std::pow(pi, 4)).epsilon(1e-12));
  // Tent: K = sinc^2, energy 2/3; leakage = 1 - 2 int_0^{1/2} sinc^4 / (2/3), by Simpson here.
  double s = 0;
  const int n = 20000;
  for (int i = 0; i <= n; ++i) s += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * std::pow(sinc(0.5 * i / n), 4);
  s *= 0.5 / n / 3;
  CHECK(analyse(parse_kernel("tent")).leakage == Approx(1 - 2 * s / (2.0 / 3)).epsilon(1e-10));
  // The B-spline leaks less than Catmull-Rom (it blurs instead); lanczos3 least of all.
  const FilterReport c = analyse(parse_kernel("catmull-rom")), l = analyse(parse_kernel("lanczos3"));
  CHECK(b.leakage < c.leakage);
  CHECK(l.leakage < c.leakage);
  CHECK(b.droop > c.droop);
}

TEST_CASE("step response: ringing of interpolating kernels, none for the B-spline") {
  // Catmull-Rom's step reconstruction X(t) = sum_{j>=0} k(t-j), from the piecewise formula,
  // maximised by brute force on a 1e-6 grid.
  auto cr = [](double x) {
    x = std::abs(x);
    return x < 1 ? 1.5 * x * x * x - 2.5 * x * x + 1 : x < 2 ? -0.5 * x * x * x + 2.5 * x * x - 4 * x + 2 : 0.0;
  };
  double best = 0;
  for (double t = -2; t <= 2; t += 1e-6) {
    double x = 0;
    for (int j = 0; j <= 4; ++j) x += cr(t - j);
    best = std::max(best, x);
  }
  const StepResponse c = step_response(parse_kernel("catmull-rom"));
  CHECK(c.overshoot == Approx(best - 1).margin(1e-10));
  CHECK(c.undershoot == Approx(best - 1).margin(1e-10));  // odd symmetry about t = -1/2
  const StepResponse b = step_response(parse_kernel("bspline"));
  CHECK(b.overshoot == 0);
  CHECK(b.undershoot == 0);
  // Tent: linear ramp from t = -1 to 0, so 10% to 90% takes 0.8; box: a jump.
  CHECK(step_response(parse_kernel("tent")).rise == Approx(0.8).margin(1e-9));
  CHECK(step_response(parse_kernel("box")).rise == Approx(0).margin(1e-9));
  CHECK(b.rise > c.rise);
}

TEST_CASE("Mitchell-Netravali B,C placement of cardinal, Duff and Beta kernels") {
  auto bc = [](const char* spec) { return mitchell_netravali(parse_kernel(spec)); };
  auto is = [&](const char* spec, double B, double C) {
    INFO(spec);
    const auto p = bc(spec);
    REQUIRE(p);
    CHECK(p->b == Approx(B).margin(1e-14));
    CHECK(p->c == Approx(C).margin(1e-14));
  };
  is("catmull-rom", 0, 0.5);
  is("cardinal:a=0.75", 0, 0.75);
  is("cardinal:a=0", 0, 0);
  is("bspline", 1, 0);
  is("uniform-bspline:degree=3", 1, 0);
  is("tensioned-bspline:a=0.5", 0.5, 0);
  is("beta:b1=1,b2=12", 0.5, 0);  // B = 12 / (b2 + 12)
  is("beta:b1=1,b2=0", 1, 0);
  std::string why;
  CHECK_FALSE(mitchell_netravali(parse_kernel("beta:b1=2,b2=0"), &why));
  CHECK(why == "asymmetric kernel");
  CHECK_FALSE(mitchell_netravali(parse_kernel("uniform-bspline:degree=5")));
  CHECK_FALSE(mitchell_netravali(parse_kernel("tent")));
  CHECK_FALSE(mitchell_netravali(parse_kernel("lanczos3")));
  // A member's spec names it; parse_basis reads the spec back to the same matrix.
  for (auto [B, C] : {std::pair{0.2, 0.4}, {1.0 / 3, 1.0 / 3}, {0.0, 0.5}, {1.5, -0.25}}) {
    const Basis mn = mitchell_netravali_basis(B, C);
    INFO(mn.spec);
    const Basis back = parse_basis(mn.spec);
    CHECK(back.spec == mn.spec);
    CHECK(back.m == mn.m);
    const auto p = mitchell_netravali(parse_kernel(mn.spec));
    REQUIRE(p);
    CHECK(p->b == Approx(B).margin(1e-15));
    CHECK(p->c == Approx(C).margin(1e-15));
  }
  CHECK(parse_basis("mitchell-netravali").spec == mitchell_netravali_basis(1.0 / 3, 1.0 / 3).spec);
  CHECK_THROWS_WITH(parse_basis("mitchell-netravali:b=1,d=2"), Catch::Contains("unknown parameter 'd'"));
  // The family matrix against Mitchell and Netravali's piecewise formula, at B = C = 1/3.
  const double B = 1.0 / 3, C = 1.0 / 3;
  const Kernel m = basis_kernel(mitchell_netravali_basis(B, C));
  for (double x = -2; x <= 2; x += 1.0 / 32) {
    const double a = std::abs(x);
    const double ref = a < 1 ? ((12 - 9 * B - 6 * C) * a * a * a + (-18 + 12 * B + 6 * C) * a * a + (6 - 2 * B)) / 6
                     : a < 2 ? ((-B - 6 * C) * a * a * a + (6 * B + 30 * C) * a * a + (-12 * B - 48 * C) * a + (8 * B + 24 * C)) / 6
                             : 0;
    CHECK(m(x) == Approx(ref).margin(1e-14));
  }
}

TEST_CASE("filter specs: basis specs plus box, tent, lanczos3, unknown names are errors") {
  CHECK(parse_kernel("beta:b1=2").name() == "beta:b1=2,b2=0");
  CHECK(parse_kernel("lanczos3").support().hi == 3);
  CHECK_THROWS_WITH(parse_kernel("gauss"), Catch::Contains("unknown filter 'gauss'"));
  CHECK_THROWS_WITH(parse_kernel(""), Catch::Contains("empty filter name"));
  CHECK_THROWS_WITH(parse_kernel("cardinal:b=1"), Catch::Contains("unknown parameter 'b'"));
  const std::string text = report_text(analyse(parse_kernel("catmull-rom")));
  CHECK(text.find("continuity: C1\n") != std::string::npos);
  CHECK(text.find("mitchell_netravali: B=0 C=0.5") != std::string::npos);
  CHECK(text.find("interpolating: yes\n") != std::string::npos);
}
