// Every threshold exactly at its boundary: a value whose difference equals --fail or --warn is
// not over it, one float above is, and a count or maximum equal to --failpercent, --warnpercent,
// --hardfail, --hardwarn or --allowfailures is within it. Checked for 1 to 4 channels, with and
// without a mask and a shift tolerance, on every inner loop of idiff_metrics (portable, SSE2,
// AVX2 + FMA, forced through MetricOptions::loop, and the sequential pass that images holding a
// NaN take), against counts worked out here and against the real idiff on the same files.
//
// The differences are exact in float: A is 0.5 everywhere and B = 0.5 +- d with d one of
// F = 1/4, W = 1/8 and the floats next to them (0.5 +- d lies in [1/4, 1), where the step is at
// most 2^-24, and |A - B| is then exact by Sterbenz's lemma).
#include "skip.hpp"
#include "support.hpp"

#include <splinefig/compare/compare.hpp>
#include <splinefig/image/io.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <regex>

using namespace splinefig;
using namespace splinefig::compare;
using namespace test_support;

namespace {

constexpr float kFail = 0.25f, kWarn = 0.125f;
const float kUlp = std::ldexp(1.0f, -24);  // the float step in [1/2, 1)

// A threshold as the command line takes it: the float's exact decimal expansion.
std::string exact(float v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.40g", double(v));
  return buf;
}

std::string q(const std::string& p) { return "'" + p + "'"; }

struct Loop {
  InnerLoop loop;
  const char* name;
};
constexpr Loop kLoops[] = {{InnerLoop::portable, "portable"}, {InnerLoop::sse2, "SSE2"}, {InnerLoop::avx2, "AVX2"},
                           {InnerLoop::fastest, "fastest"}};

// A pair of images and where they were written.
struct Pair {
  int w = 0, h = 0, nch = 0;
  std::vector<float> va, vb;
  std::string fa, fb;
  Image a, b;
};

Pair make_pair(const std::string& name, int w, int h, int nch) {
  Pair p;
  p.w = w, p.h = h, p.nch = nch;
  p.va.assign(std::size_t(w * h * nch), 0.5f);
  p.vb = p.va;
  p.fa = scratch(name + "_a.exr");
  p.fb = scratch(name + "_b.exr");
  return p;
}

void write(Pair& p) {
  write_raw(p.fa, p.w, p.h, p.nch, p.va, OIIO::TypeFloat);
  write_raw(p.fb, p.w, p.h, p.nch, p.vb, OIIO::TypeFloat);
  p.a = read_image(p.fa);
  p.b = read_image(p.fb);
}

// B's value at (pixel, channel) differs from A's 0.5 by d, upward or downward.
void set_diff(Pair& p, int pixel, int c, float d, bool up) {
  float& v = p.vb[std::size_t(pixel * p.nch + c)];
  v = up ? 0.5f + d : 0.5f - d;
  REQUIRE(std::fabs(0.5f - v) == d);  // the difference is exact
}

// The boundary pattern for `nch` channels on 11 x 5 pixels (55: the AVX2 loop takes 52 in
// groups of four and leaves 3 to the portable tail, SSE2 54 in pairs and 1), spread over the
// image so that boundary values fall in every lane position and in the tails. For each channel
// c, one pixel each with only channel c at F, W, F + step, W + step and W - step; and one pixel
// with every channel at F. Counted by hand: per channel, F, F + step and W + step are over W
// (3) and only F + step is over F (1); the all-F pixel is one more over W and none over F.
struct Expected {
  std::uint64_t nwarn = 0, nfail = 0;
  float max_error = 0.0f;
  std::vector<int> pattern_pixels;
};

Expected boundary_pattern(Pair& p) {
  const int npix = p.w * p.h;
  const int count = 5 * p.nch + 1;
  Expected e;
  int k = 0;
  auto next_pixel = [&] {
    const int px = int((long long)(k) * (npix - 1) / (count - 1));  // 0 ... npix - 1, evenly
    ++k;
    e.pattern_pixels.push_back(px);
    return px;
  };
  for (int c = 0; c < p.nch; ++c) {
    const bool up = c % 2 == 0;
    set_diff(p, next_pixel(), c, kFail, up);
    set_diff(p, next_pixel(), c, kWarn, !up);
    set_diff(p, next_pixel(), c, kFail + kUlp, up);
    set_diff(p, next_pixel(), c, kWarn + kUlp, up);
    set_diff(p, next_pixel(), c, kWarn - kUlp, !up);
  }
  const int all_f = next_pixel();
  for (int c = 0; c < p.nch; ++c) set_diff(p, all_f, c, kFail, c % 2 == 1);
  REQUIRE(k == count);
  e.nwarn = std::uint64_t(3 * p.nch + 1);
  e.nfail = std::uint64_t(p.nch);
  e.max_error = kFail + kUlp;
  return e;
}

// idiff's counts from its -v report: the line over --warn comes first, then the one over --fail.
struct PeerCounts {
  bool ran = false;
  std::uint64_t nwarn = 0, nfail = 0;
  int code = -1;
  std::string out;
};

PeerCounts run_idiff(const std::string& flags, const std::string& fa, const std::string& fb) {
  PeerCounts r;
  if (!have_idiff()) return r;
  const Run run = idiff("-v " + flags + " " + q(fa) + " " + q(fb));
  r.ran = true;
  r.code = run.code;
  r.out = run.out;
  const std::regex over(R"(^  (\d+) pixels \([^)]*\) over )");
  std::vector<std::uint64_t> counts;
  std::istringstream in(run.out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, over)) counts.push_back(std::stoull(m[1].str()));
  }
  REQUIRE(counts.size() == 2);
  r.nwarn = counts[0];
  r.nfail = counts[1];
  return r;
}

// "--fail X" for ours, "-fail X" for idiff.
std::string our_flags(const std::string& idiff_flags) {
  std::string s;
  std::istringstream in(idiff_flags);
  for (std::string word; in >> word;) s += (word[0] == '-' && !std::isdigit(word[1]) ? "-" + word : word) + " ";
  return s;
}

void skip_without_idiff() {
  if (!have_idiff())
    splinefig::testing_support::skip("idiff is not installed: only the hand-derived counts were checked");
}

}  // namespace

TEST_CASE("a difference equal to --fail or --warn is not over it on every inner loop for 1 to 4 channels") {
  const std::string flags = "-fail " + exact(kFail) + " -warn " + exact(kWarn);
  for (int nch = 1; nch <= 4; ++nch) {
    for (const bool with_nan : {false, true}) {
      // With a NaN against a NaN (skipped by idiff, so the counts are the same) every loop hands
      // the image to the sequential pass that follows ImageBufAlgo::compare value by value.
      Pair p = make_pair("boundary" + std::to_string(nch) + (with_nan ? "n" : ""), 11, 5, nch);
      const Expected e = boundary_pattern(p);
      if (with_nan) {
        int free_pixel = 0;
        while (std::find(e.pattern_pixels.begin(), e.pattern_pixels.end(), free_pixel) != e.pattern_pixels.end())
          ++free_pixel;
        p.va[std::size_t(free_pixel * nch)] = p.vb[std::size_t(free_pixel * nch)] =
            std::numeric_limits<float>::quiet_NaN();
      }
      write(p);
      const PeerCounts peer = run_idiff(flags, p.fa, p.fb);
      for (const Loop& loop : kLoops) {
        INFO(nch << " channel(s), " << loop.name << " loop" << (with_nan ? ", with a NaN pair" : ""));
        if (!inner_loop_available(loop.loop)) {
          splinefig::testing_support::skip(std::string("this CPU lacks the ") + loop.name + " loop");
          continue;
        }
        MetricOptions o;
        o.loop = loop.loop;
        o.threads = 1;
        const Metrics m = idiff_metrics(p.a, p.b, kFail, kWarn, o);
        CHECK(m.nwarn == e.nwarn);
        CHECK(m.nfail == e.nfail);
        CHECK(m.max_error == e.max_error);
        if (peer.ran) {
          CHECK(m.nwarn == peer.nwarn);
          CHECK(m.nfail == peer.nfail);
        }
      }
      // The command line (the fastest loop) prints idiff's report and exits as it does.
      const Run ours = run_splinefig("diff -v " + our_flags(flags) + q(p.fa) + " " + q(p.fb));
      CHECK(ours.code == 2);  // nch pixels over F, 0% allowed
      if (peer.ran) {
        INFO("idiff:\n" << peer.out << "splinefig:\n" << ours.out);
        CHECK(ours.out == peer.out);
        CHECK(ours.code == peer.code);
      }
    }
  }
  skip_without_idiff();
}

TEST_CASE("a mask leaves boundary pixels out of the counts and of the percentage's pixel count") {
  // The boundary pattern under a mask that drops every other pattern pixel and keeps 32 pixels
  // in all (so that k failures are exactly k * 3.125% of idiff's pixel count). The counts are
  // those of the kept pattern pixels, worked out from which kind each one is. A masked image
  // always takes the portable loop (or, holding a NaN, the sequential pass).
  constexpr int kKept = 32;
  for (int nch = 1; nch <= 4; ++nch) {
    Pair p = make_pair("masked" + std::to_string(nch), 11, 5, nch);
    const Expected e = boundary_pattern(p);
    Image mask = Image::zeros(p.w, p.h, 1);
    std::uint64_t nwarn = 0, nfail = 0;
    int kept = 0;
    for (std::size_t k = 0; k < e.pattern_pixels.size(); k += 2) {
      mask.pixels[std::size_t(e.pattern_pixels[k])] = 1.0f;
      ++kept;
      // Pattern order per channel: F, W, F + step, W + step, W - step; then the all-F pixel.
      const std::size_t kind = k < std::size_t(5 * nch) ? k % 5 : 0;
      nwarn += kind == 0 || kind == 2 || kind == 3;
      nfail += kind == 2;
    }
    int nan_pixel = -1;
    for (int px = 0; px < p.w * p.h && kept < kKept; ++px) {
      if (std::find(e.pattern_pixels.begin(), e.pattern_pixels.end(), px) != e.pattern_pixels.end()) continue;
      mask.pixels[std::size_t(px)] = 1.0f;
      ++kept;
      nan_pixel = px;
    }
    REQUIRE(kept == kKept);
    REQUIRE(nfail > 0);
    write(p);
    for (const bool with_nan : {false, true}) {
      Image a = p.a, b = p.b;
      if (with_nan)  // a NaN pair in a kept pixel: the sequential pass, same counts
        a.pixels[std::size_t(nan_pixel * nch)] = b.pixels[std::size_t(nan_pixel * nch)] =
            std::numeric_limits<float>::quiet_NaN();
      INFO(nch << " channel(s)" << (with_nan ? ", with a NaN pair" : ""));
      MetricOptions o;
      o.mask = &mask;
      const Metrics m = idiff_metrics(a, b, kFail, kWarn, o);
      CHECK(m.nwarn == nwarn);
      CHECK(m.nfail == nfail);
      CHECK(m.npels == std::uint64_t(kKept));
    }
    // Through compare_images and the command line: --failpercent at exactly nfail of the kept
    // pixels is within it (then the warnings decide), the float below is a failure.
    const std::string fm = scratch("mask" + std::to_string(nch) + ".exr");
    write_raw(fm, p.w, p.h, 1, std::vector<float>(mask.pixels.begin(), mask.pixels.end()), OIIO::TypeFloat);
    const float pct = 3.125f * float(nfail);
    REQUIRE(double(nfail) == pct / 100.0 * kKept);  // exactly at the boundary, as idiff computes it
    const std::string args = " --mask " + q(fm) + " " + q(p.fa) + " " + q(p.fb);
    for (const float percent : {pct, std::nextafter(pct, 0.0f)}) {
      Options opt;
      opt.thresholds.fail = kFail;
      opt.thresholds.warn = kWarn;
      opt.thresholds.failpercent = percent;
      const Verdict expected = percent == pct ? Verdict::warning : Verdict::failure;
      INFO(nch << " channel(s), --failpercent " << exact(percent));
      CHECK(compare_images(p.a, p.b, opt, &mask).verdict == expected);
      CHECK(run_splinefig("diff --fail 0.25 --warn 0.125 --failpercent " + exact(percent) + args).code ==
            int(expected));
    }
  }
}

TEST_CASE("a tolerated error (--shift) equal to --fail is not over it") {
  // Constant images: the shift-tolerant error is |A - B| everywhere, so idiff without a shift
  // is the peer for the verdict.
  for (int nch = 1; nch <= 4; ++nch) {
    for (const float d : {kFail, kFail + kUlp}) {
      Pair p = make_pair("shift" + std::to_string(nch) + (d == kFail ? "eq" : "up"), 6, 5, nch);
      for (float& v : p.vb) v = 0.5f + d;
      write(p);
      Options opt;
      opt.thresholds.fail = kFail;
      opt.thresholds.warn = kFail;
      opt.shift = 1;
      const Comparison c = compare_images(p.a, p.b, opt);
      INFO(nch << " channel(s), d = " << exact(d));
      CHECK(c.metrics.nfail == (d == kFail ? 0u : 30u));
      CHECK(c.metrics.nwarn == (d == kFail ? 0u : 30u));
      const Run ours = run_splinefig("diff --shift 1 --fail 0.25 --warn 0.25 " + q(p.fa) + " " + q(p.fb));
      CHECK(ours.code == (d == kFail ? 0 : 2));
      if (have_idiff()) CHECK(ours.code == idiff("-fail 0.25 -warn 0.25 " + q(p.fa) + " " + q(p.fb)).code);
    }
  }
  skip_without_idiff();
}

TEST_CASE("the verdict at the boundary of --allowfailures --failpercent --hardfail --warnpercent and --hardwarn") {
  // 4 x 4 pixels (npels 16, so k pixels are exactly k * 6.25%): two pixels over F (one at
  // F + step, one at F + 3 steps: the max error), two more over W only (at F), the rest equal.
  // nfail = 2 (12.5%), nwarn = 4 (25%), max error F + 3 * 2^-24.
  const float max_error = kFail + 3 * kUlp;
  for (int nch = 1; nch <= 4; ++nch) {
    Pair p = make_pair("verdict" + std::to_string(nch), 4, 4, nch);
    set_diff(p, 5, 0, kFail + kUlp, true);
    set_diff(p, 10, nch - 1, max_error, false);
    set_diff(p, 3, (nch - 1) / 2, kFail, true);
    set_diff(p, 15, nch - 1, kFail, false);
    write(p);
    struct Case {
      std::string flags;
      Verdict expected;
    };
    const std::string base = "-fail " + exact(kFail) + " -warn " + exact(kWarn) + " ";
    const std::vector<Case> cases = {
        {"-allowfailures 2", Verdict::match},                  // nfail = allowed: pass
        {"-allowfailures 1", Verdict::failure},                // one more than allowed
        {"-failpercent 12.5", Verdict::warning},               // 2 of 16 = 12.5%: within; 25% warn > 0%
        {"-failpercent " + exact(std::nextafter(12.5f, 0.0f)), Verdict::failure},
        {"-failpercent 100 -warnpercent 25", Verdict::match},  // 4 of 16 = 25%: within
        {"-failpercent 100 -warnpercent " + exact(std::nextafter(25.0f, 0.0f)), Verdict::warning},
        {"-failpercent 100 -warnpercent 100 -hardfail " + exact(max_error), Verdict::match},
        {"-failpercent 100 -warnpercent 100 -hardfail " + exact(std::nextafter(max_error, 0.0f)), Verdict::failure},
        {"-failpercent 100 -warnpercent 100 -hardwarn " + exact(max_error), Verdict::match},
        {"-failpercent 100 -warnpercent 100 -hardwarn " + exact(std::nextafter(max_error, 0.0f)), Verdict::warning},
    };
    for (const Case& k : cases) {
      Thresholds t;
      t.fail = kFail;
      t.warn = kWarn;
      std::istringstream in(k.flags);
      for (std::string flag, value; in >> flag >> value;) {
        const float v = std::stof(value);
        if (flag == "-allowfailures") t.allowfailures = std::stoll(value);
        if (flag == "-failpercent") t.failpercent = v;
        if (flag == "-warnpercent") t.warnpercent = v;
        if (flag == "-hardfail") t.hardfail = v;
        if (flag == "-hardwarn") t.hardwarn = v;
      }
      for (const Loop& loop : kLoops) {
        if (!inner_loop_available(loop.loop)) continue;
        MetricOptions o;
        o.loop = loop.loop;
        const Metrics m = idiff_metrics(p.a, p.b, t.fail, t.warn, o);
        INFO(nch << " channel(s), " << loop.name << " loop, " << k.flags);
        REQUIRE(m.nfail == 2);
        REQUIRE(m.nwarn == 4);
        REQUIRE(m.max_error == max_error);
        CHECK(idiff_verdict(m, t) == k.expected);
      }
      // The command line and idiff (half a second a run) for the portable and the vectorised
      // channel counts; the verdict does not look at channels.
      if (nch != 1 && nch != 4) continue;
      INFO(nch << " channel(s), " << k.flags);
      const Run ours = run_splinefig("diff " + our_flags(base + k.flags) + q(p.fa) + " " + q(p.fb));
      CHECK(ours.code == int(k.expected));
      if (have_idiff()) CHECK(idiff(base + k.flags + " " + q(p.fa) + " " + q(p.fb)).code == int(k.expected));
    }
  }
  skip_without_idiff();
}
