// idiff's numbers, verdicts and report lines, pinned two ways: values derived by hand for
// pairs built so that the arithmetic is exact, and (when openimageio-tools is installed, as
// scripts/deps does) the real idiff run on the same files, whose stdout and exit code must
// equal ours line for line (apart from our "Images differ" lines).
#include "skip.hpp"
#include "support.hpp"

#include <splinefig/compare/compare.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/compare/report.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace splinefig;
using namespace splinefig::compare;
using namespace test_support;

namespace {

std::vector<float> filled(int w, int h, int nch, float v) { return std::vector<float>(std::size_t(w * h * nch), v); }

// Our report without the lines idiff does not print.
std::string without_our_lines(const std::string& s) {
  std::string out, line;
  std::istringstream in(s);
  while (std::getline(in, line))
    if (line.rfind("Images differ", 0) != 0) out += line + "\n";
  return out;
}

// Runs both tools on the same arguments; our stdout (less our extra lines) and exit code must
// equal idiff's. Returns our run.
Run check_against_idiff(const std::string& args, const std::string& our_extra = "") {
  const Run ours = run_splinefig("diff " + our_extra + " " + args);
  if (have_idiff()) {
    std::string idiff_args = args;
    for (const char* flag : {"--failpercent", "--warnpercent", "--hardfail", "--hardwarn", "--allowfailures",
                             "--fail", "--warn"}) {
      std::string f(flag);
      for (std::size_t p = idiff_args.find(f); p != std::string::npos; p = idiff_args.find(f, p + 1))
        if (p == 0 || idiff_args[p - 1] == ' ') idiff_args.erase(p, 1);  // --fail -> -fail
    }
    const Run peer = idiff(idiff_args);
    INFO("idiff " << idiff_args << "\n--- idiff:\n" << peer.out << "--- splinefig:\n" << ours.out);
    CHECK(without_our_lines(ours.out) == peer.out);
    CHECK(ours.code == peer.code);
  } else {
    splinefig::testing_support::skip("idiff is not installed: only the hand-derived values were checked");
  }
  return ours;
}

std::string q(const std::string& p) { return "'" + p + "'"; }

}  // namespace

TEST_CASE("identical images: zero error, infinite PSNR, PASS and exit 0") {
  const std::string a = scratch("ident_a.png");
  std::vector<float> v(16 * 12 * 3);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(i % 256) / 255.0f;
  write_raw(a, 16, 12, 3, v, OIIO::TypeUInt8);
  const Image im = read_image(a);
  const Metrics m = idiff_metrics(im, im, 1e-6f, 1e-6f);
  CHECK(m.mean_error == 0.0);
  CHECK(m.rms_error == 0.0);
  CHECK(std::isinf(m.psnr));
  CHECK(m.max_error == 0.0f);
  CHECK(m.nfail == 0);
  const Run r = check_against_idiff(q(a) + " " + q(a));
  CHECK(r.code == 0);
  CHECK(r.out == "Comparing \"" + a + "\" and \"" + a + "\"\nPASS\n");
  const Run v2 = check_against_idiff("-v " + q(a) + " " + q(a));
  CHECK(v2.out.find("  Peak SNR = inf\n") != std::string::npos);
  CHECK(v2.out.find("  Max error  = 0\n") != std::string::npos);
}

TEST_CASE("a few far-off pixels: hand-derived numbers and the verdict thresholds") {
  // 32 x 32 RGB float, all 0.5; three pixels' R is 1.5: f = 1 on 3 of 3072 values.
  const std::string a = scratch("few_a.exr"), b = scratch("few_b.exr");
  std::vector<float> va = filled(32, 32, 3, 0.5f), vb = va;
  for (int p : {5 * 32 + 7, 9 * 32 + 2, 20 * 32 + 31}) vb[std::size_t(p * 3)] = 1.5f;
  write_raw(a, 32, 32, 3, va, OIIO::TypeFloat);
  write_raw(b, 32, 32, 3, vb, OIIO::TypeFloat);
  const Metrics m = idiff_metrics(read_image(a), read_image(b), 1e-6f, 1e-6f);
  CHECK(m.mean_error == 3.0 / 3072.0);
  CHECK(m.rms_error == Approx(std::sqrt(3.0 / 3072.0)).epsilon(1e-15));  // 0.03125
  CHECK(m.psnr == Approx(20.0 * std::log10(1.5 / 0.03125)).epsilon(1e-12));  // maxval = 1.5
  CHECK(m.max_error == 1.0f);
  CHECK(m.max_x == 7);  // the first in scanline order
  CHECK(m.max_y == 5);
  CHECK(m.max_c == 0);
  CHECK(m.nfail == 3);
  CHECK(m.nwarn == 3);

  const Run r = check_against_idiff(q(a) + " " + q(b));
  CHECK(r.code == 2);
  CHECK(r.out == "Comparing \"" + a + "\" and \"" + b + "\"\n"
                 "  Mean error = 0.000976562\n"
                 "  RMS error = 0.03125\n"
                 "  Peak SNR = 33.6248\n"
                 "  Max error  = 1 @ (7, 5, R)  values are 0.5, 0.5, 0.5 vs 1.5, 0.5, 0.5\n"
                 "  3 pixels (0.293%) over 1e-06\n"
                 "  3 pixels (0.293%) over 1e-06\n"
                 "FAILURE\n");
  // The verdict thresholds, through the library; idiff (exit code only) as the peer.
  const Image ia = read_image(a), ib = read_image(b);
  auto verdict = [&](const std::string& flags, Thresholds t) {
    const Verdict v = idiff_verdict(idiff_metrics(ia, ib, t.fail, t.warn), t);
    if (have_idiff()) {
      INFO("idiff " << flags);
      CHECK(idiff(flags + " " + q(a) + " " + q(b)).code == int(v));
    }
    return v;
  };
  Thresholds t;
  t.failpercent = 0.3f;  // 3 failures are within 0.3% of 1024 pixels (3.072)...
  CHECK(verdict("-failpercent 0.3", t) == Verdict::warning);  // ...but 3 warnings are over 0%
  t.warnpercent = 0.3f;
  CHECK(verdict("-failpercent 0.3 -warnpercent 0.3", t) == Verdict::match);
  t.hardfail = 0.9f;
  CHECK(verdict("-failpercent 0.3 -warnpercent 0.3 -hardfail 0.9", t) == Verdict::failure);
  t.hardfail = std::numeric_limits<float>::infinity();
  t.hardwarn = 0.9f;
  CHECK(verdict("-failpercent 0.3 -warnpercent 0.3 -hardwarn 0.9", t) == Verdict::warning);
  Thresholds u;
  u.failpercent = 0.29f;
  u.warnpercent = 0.3f;
  CHECK(verdict("-failpercent 0.29 -warnpercent 0.3", u) == Verdict::failure);
  Thresholds allow;
  allow.allowfailures = 3;
  allow.hardfail = 0.5f;
  CHECK(verdict("-allowfailures 3 -hardfail 0.5", allow) == Verdict::match);
  // idiff 2.4 passes whenever nothing is over --fail, even with pixels over --warn.
  Thresholds warn_only;
  warn_only.fail = 2.0f;
  warn_only.warn = 0.1f;
  CHECK(verdict("-fail 2 -warn 0.1", warn_only) == Verdict::match);
  // The command line reaches the same verdict (exit 1: warning).
  CHECK(run_splinefig("diff --failpercent 0.3 " + q(a) + " " + q(b)).code == 1);
}

TEST_CASE("noise under the thresholds passes, and idiff's mean and RMS from an in-test sum") {
  const std::string a = scratch("noise_a.exr"), b = scratch("noise_b.exr");
  const int w = 40, h = 30, n = 4;  // RGBA: the vectorised path
  std::vector<float> va(std::size_t(w * h * n)), vb(va.size());
  unsigned s = 12345u;
  for (std::size_t i = 0; i < va.size(); ++i) {
    s = s * 1664525u + 1013904223u;  // Numerical Recipes LCG
    va[i] = float(i % 97) / 97.0f;
    vb[i] = va[i] + (float(s >> 8) / float(1u << 24) - 0.5f) * 0.0018f;  // |noise| <= 0.0009
  }
  write_raw(a, w, h, n, va, OIIO::TypeFloat);
  write_raw(b, w, h, n, vb, OIIO::TypeFloat);
  double sum = 0.0, sumsq = 0.0;
  float mx = 0.0f;
  for (std::size_t i = 0; i < va.size(); ++i) {
    const float f = std::fabs(va[i] - vb[i]);
    sum += f;
    sumsq += double(f) * f;
    mx = std::max(mx, f);
  }
  const Metrics m = idiff_metrics(read_image(a), read_image(b), 0.001f, 0.001f);
  CHECK(m.mean_error == Approx(sum / double(va.size())).epsilon(1e-12));
  CHECK(m.rms_error == Approx(std::sqrt(sumsq / double(va.size()))).epsilon(1e-12));
  CHECK(m.max_error == mx);
  CHECK(m.nfail == 0);
  CHECK(check_against_idiff("--fail 0.001 --warn 0.001 " + q(a) + " " + q(b)).code == 0);
  CHECK(check_against_idiff("-v --fail 0.001 --warn 0.0005 " + q(a) + " " + q(b)).code == 0);
  CHECK(check_against_idiff(q(a) + " " + q(b)).code == 2);
}

TEST_CASE("the numbers do not depend on the thread count") {
  Image a = Image::zeros(300, 300, 4), b = a;  // 90000 pixels: several chunks
  unsigned s = 7u;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    s = s * 1664525u + 1013904223u;
    a.pixels[i] = float(s >> 8) / float(1u << 24);
    b.pixels[i] = a.pixels[i] + float(int(s & 0xff) - 128) * 1e-5f;
  }
  MetricOptions one, three;
  one.threads = 1;
  three.threads = 3;
  const Metrics m1 = idiff_metrics(a, b, 1e-3f, 1e-4f, one), m3 = idiff_metrics(a, b, 1e-3f, 1e-4f, three);
  CHECK(m1.mean_error == m3.mean_error);
  CHECK(m1.rms_error == m3.rms_error);
  CHECK(m1.max_error == m3.max_error);
  CHECK(m1.max_x == m3.max_x);
  CHECK(m1.max_y == m3.max_y);
  CHECK(m1.nwarn == m3.nwarn);
  CHECK(m1.nfail == m3.nfail);
}

TEST_CASE("a uniform shift of every value by 1/4") {
  const std::string a = scratch("ushift_a.exr"), b = scratch("ushift_b.exr");
  std::vector<float> va(24 * 16 * 4), vb(va.size());
  for (std::size_t i = 0; i < va.size(); ++i) {
    va[i] = float(i % 64) / 64.0f;  // exact in float, and so is + 0.25
    vb[i] = va[i] + 0.25f;
  }
  write_raw(a, 24, 16, 4, va, OIIO::TypeFloat);
  write_raw(b, 24, 16, 4, vb, OIIO::TypeFloat);
  const Metrics m = idiff_metrics(read_image(a), read_image(b), 1e-6f, 1e-6f);
  CHECK(m.mean_error == 0.25);
  CHECK(m.rms_error == 0.25);
  CHECK(m.psnr == Approx(20.0 * std::log10((63.0 / 64.0 + 0.25) / 0.25)).epsilon(1e-12));
  CHECK(m.nfail == 24 * 16);
  CHECK(m.max_x == 0);
  CHECK(m.max_y == 0);
  CHECK(m.max_c == 0);
  CHECK(check_against_idiff(q(a) + " " + q(b)).code == 2);
  CHECK(check_against_idiff("--fail 0.25 --warn 0.2 " + q(a) + " " + q(b)).code == 0);
}

TEST_CASE("different sizes: the union of the windows, missing pixels black, failure") {
  // A is 8 x 8, B is 10 x 6, all 0.5 (RGB). Union 10 x 8 = 80 pixels; 16 only in A and 12
  // only in B differ by 0.5 in each channel; percentages use A's 64 pixels.
  const std::string a = scratch("size_a.png"), b = scratch("size_b.png");
  write_raw(a, 8, 8, 3, filled(8, 8, 3, 128.0f / 255.0f), OIIO::TypeUInt8);
  write_raw(b, 10, 6, 3, filled(10, 6, 3, 128.0f / 255.0f), OIIO::TypeUInt8);
  const Image ia = read_image(a), ib = read_image(b);
  const double v = ia.at(0, 0, 0);
  const Metrics m = idiff_metrics(ia, ib, 1e-6f, 1e-6f);
  CHECK(m.nfail == 28);
  CHECK(m.npels == 64);
  CHECK(m.mean_error == Approx(28.0 * 3.0 * v / 240.0).epsilon(1e-12));
  CHECK(m.rms_error == Approx(std::sqrt(28.0 * 3.0 * v * v / 240.0)).epsilon(1e-12));
  CHECK(m.max_x == 8);  // row 0, first pixel past A's width
  CHECK(m.max_y == 0);
  const Run r = check_against_idiff(q(a) + " " + q(b));
  CHECK(r.code == 2);
  CHECK(r.out.find("Images differ in size: 8 x 8 vs 10 x 6 (compared over their union, 10 x 8, missing pixels as 0)\n") !=
        std::string::npos);
  CHECK(r.out.find("  28 pixels (43.8%) over 1e-06\n") != std::string::npos);
  CHECK(r.out.find("values are 0, 0, 0 vs 0.5019608, 0.5019608, 0.5019608") != std::string::npos);
  // Swapped, idiff's percentage is of the 60 pixels of the first image.
  CHECK(check_against_idiff(q(b) + " " + q(a)).out.find("  28 pixels (46.7%) over 1e-06\n") != std::string::npos);
}

TEST_CASE("different channel counts: missing channels are 0") {
  // RGB 0.5 against RGBA 0.5 with alpha 1: only alpha differs, by 1.
  const std::string a = scratch("chan_a.exr"), b = scratch("chan_b.exr");
  write_raw(a, 6, 5, 3, filled(6, 5, 3, 0.5f), OIIO::TypeFloat);
  std::vector<float> vb = filled(6, 5, 4, 0.5f);
  for (std::size_t p = 0; p < 30; ++p) vb[p * 4 + 3] = 1.0f;
  write_raw(b, 6, 5, 4, vb, OIIO::TypeFloat);
  const Metrics m = idiff_metrics(read_image(a), read_image(b), 1e-6f, 1e-6f);
  CHECK(m.mean_error == 0.25);
  CHECK(m.rms_error == 0.5);
  CHECK(m.psnr == Approx(20.0 * std::log10(2.0)).epsilon(1e-12));
  CHECK(m.max_c == 3);
  const Run r = check_against_idiff(q(a) + " " + q(b));
  CHECK(r.code == 2);
  CHECK(r.out.find("Images differ in channel count: 3 vs 4 (missing channels as 0)\n") != std::string::npos);
  CHECK(r.out.find("  Max error  = 1 @ (0, 0, A)  values are 0.5, 0.5, 0.5 vs 0.5, 0.5, 0.5, 1\n") != std::string::npos);
  // Without alpha the images match.
  CHECK(run_splinefig("diff --ignore-alpha " + q(a) + " " + q(b)).code == 0);
}

TEST_CASE("NaN matches NaN, Inf matches Inf, other non-finite pairs are an infinite error") {
  const std::string a = scratch("nan_a.exr"), b = scratch("nan_b.exr"), c = scratch("nan_c.exr"),
                    d = scratch("nan_d.exr");
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<float> va = filled(4, 4, 1, 0.25f), vb = va, vc = va, vd = va;
  va[3] = vb[3] = nan;
  va[9] = vb[9] = inf;
  vc[3] = 0.5f;  // NaN against 0.5: the max error becomes Inf, the pair is not counted
  vc[9] = inf;   // Inf against Inf: skipped
  vd = vc;
  vd[12] = nan;   // after an Inf error, 0.25 against NaN: NaN sums and a NaN running maximum,
  vd[14] = 1.25f;  // which the next finite error (1) replaces
  write_raw(a, 4, 4, 1, va, OIIO::TypeFloat);
  write_raw(b, 4, 4, 1, vb, OIIO::TypeFloat);
  write_raw(c, 4, 4, 1, vc, OIIO::TypeFloat);
  write_raw(d, 4, 4, 1, vd, OIIO::TypeFloat);
  const Metrics same = idiff_metrics(read_image(a), read_image(b), 1e-6f, 1e-6f);
  CHECK(same.max_error == 0.0f);
  CHECK(same.mean_error == 0.0);
  const Metrics m = idiff_metrics(read_image(a), read_image(c), 1e-6f, 1e-6f);
  CHECK(std::isinf(m.max_error));
  CHECK(m.max_x == 3);
  CHECK(m.nfail == 0);
  CHECK(m.mean_error == 0.0);
  const Metrics n = idiff_metrics(read_image(a), read_image(d), 1e-6f, 1e-6f);
  CHECK(std::isnan(n.mean_error));
  CHECK(n.max_error == 1.0f);
  CHECK(n.max_x == 2);
  CHECK(n.max_y == 3);
  CHECK(n.nfail == 1);  // 0.25 against 1.25; the NaN error is over no threshold
  // With no failing pixel idiff passes, even with an infinite max error.
  CHECK(check_against_idiff("-v " + q(a) + " " + q(b)).code == 0);
  CHECK(check_against_idiff("-v " + q(a) + " " + q(c)).code == 0);
  CHECK(check_against_idiff("-v " + q(a) + " " + q(d)).code == 2);
}

TEST_CASE("report numbers are printed as idiff's {fmt} calls print them") {
  CHECK(format_shortest(1e-6f) == "1e-06");
  CHECK(format_shortest(1e-5f) == "1e-05");
  CHECK(format_shortest(1e-4f) == "0.0001");
  CHECK(format_shortest(0.5f) == "0.5");
  CHECK(format_shortest(1.0f) == "1");
  CHECK(format_shortest(100000.0f) == "100000");
  CHECK(format_shortest(1e15f) == "1000000000000000");
  CHECK(format_shortest(1e16f) == "1e+16");
  CHECK(format_shortest(12345678901234567.0f) == "1.2345678e+16");
  CHECK(format_shortest(51.0f / 255.0f) == "0.2");
  CHECK(format_shortest(0.37254903f) == "0.37254903");
  CHECK(format_g(0.0009765625) == "0.000976562");
  CHECK(format_percent(100.0 * 28 / 64) == "43.8");
  CHECK(format_percent(100.0) == "100");
}
