// idiff's numbers (see idiff.hpp). The work is split into fixed chunks of rows whose partial
// sums are combined in chunk order, so the result does not depend on the thread count. Images
// holding a non-finite value take one sequential pass that follows ImageBufAlgo::compare value
// by value (its handling of NaN and Inf depends on the order the values come in).
#include <splinefig/compare/idiff.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "splinefig/base/parallel.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SPLINEFIG_HAVE_AVX2_PATH 1
#endif

namespace splinefig::compare {
namespace {

struct Partial {
  double sum = 0.0, sumsq = 0.0;
  float maxerr = 0.0f;
  float maxval = 1.0f;
  std::uint64_t nwarn = 0, nfail = 0, nvalues = 0, npels_a = 0;
  bool nonfinite = false;
};

// Both images on the same window with the same channel count; everything else optional.
struct Layout {
  const float* a;
  const float* b;
  const float* err;         // tolerated error per value, or nullptr
  const float* mask;        // one value per pixel, or nullptr
  const Image* first;       // the first image as given (for idiff's npels)
  int x0, y0, width, height, nch;
};

bool in_first(const Layout& L, std::size_t p) {
  const int px = L.x0 + int(p % std::size_t(L.width)), py = L.y0 + int(p / std::size_t(L.width));
  const Image& f = *L.first;
  return px >= f.x && py >= f.y && px < f.x + f.width && py < f.y + f.height;
}

// Generic chunk: any channel count, mask and tolerated error allowed.
void chunk_generic(const Layout& L, std::size_t p0, std::size_t p1, float warn, float fail, Partial& r) {
  const int n = L.nch;
  for (std::size_t p = p0; p < p1; ++p) {
    if (L.mask && L.mask[p] == 0.0f) continue;
    const float* a = L.a + p * std::size_t(n);
    const float* b = L.b + p * std::size_t(n);
    const float* e = L.err ? L.err + p * std::size_t(n) : nullptr;
    float m = 0.0f;
    for (int c = 0; c < n; ++c) {
      const float f = e ? e[c] : std::fabs(a[c] - b[c]);
      if (!(std::fabs(a[c] - b[c]) <= FLT_MAX) || !(f <= FLT_MAX)) r.nonfinite = true;
      r.sum += double(f);
      r.sumsq += double(f) * double(f);
      m = std::max(m, f);
      r.maxval = std::max(r.maxval, std::max(a[c], b[c]));
    }
    r.maxerr = std::max(r.maxerr, m);
    r.nwarn += m > warn;
    r.nfail += m > fail;
    r.nvalues += std::uint64_t(n);
  }
}

#if defined(__SSE2__)
// RGBA without mask or tolerated error: the throughput path.
void chunk_rgba(const Layout& L, std::size_t p0, std::size_t p1, float warn, float fail, Partial& r) {
  const __m128 absmask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const __m128 vwarn = _mm_set1_ps(warn), vfail = _mm_set1_ps(fail), vbig = _mm_set1_ps(FLT_MAX);
  __m128d s0 = _mm_setzero_pd(), s1 = _mm_setzero_pd(), s2 = _mm_setzero_pd(), s3 = _mm_setzero_pd();
  __m128d q0 = _mm_setzero_pd(), q1 = _mm_setzero_pd(), q2 = _mm_setzero_pd(), q3 = _mm_setzero_pd();
  __m128 vmax = _mm_setzero_ps(), vval = _mm_set1_ps(r.maxval), vbad = _mm_setzero_ps();
  std::uint64_t nwarn = 0, nfail = 0;
  const float* a = L.a + p0 * 4;
  const float* b = L.b + p0 * 4;
  std::size_t p = p0;
  for (; p + 2 <= p1; p += 2, a += 8, b += 8) {
    const __m128 a0 = _mm_loadu_ps(a), b0 = _mm_loadu_ps(b);
    const __m128 a1 = _mm_loadu_ps(a + 4), b1 = _mm_loadu_ps(b + 4);
    const __m128 d0 = _mm_and_ps(_mm_sub_ps(a0, b0), absmask);
    const __m128 d1 = _mm_and_ps(_mm_sub_ps(a1, b1), absmask);
    const __m128d l0 = _mm_cvtps_pd(d0), h0 = _mm_cvtps_pd(_mm_movehl_ps(d0, d0));
    const __m128d l1 = _mm_cvtps_pd(d1), h1 = _mm_cvtps_pd(_mm_movehl_ps(d1, d1));
    s0 = _mm_add_pd(s0, l0);
    s1 = _mm_add_pd(s1, h0);
    s2 = _mm_add_pd(s2, l1);
    s3 = _mm_add_pd(s3, h1);
    q0 = _mm_add_pd(q0, _mm_mul_pd(l0, l0));
    q1 = _mm_add_pd(q1, _mm_mul_pd(h0, h0));
    q2 = _mm_add_pd(q2, _mm_mul_pd(l1, l1));
    q3 = _mm_add_pd(q3, _mm_mul_pd(h1, h1));
    vmax = _mm_max_ps(vmax, _mm_max_ps(d0, d1));
    vval = _mm_max_ps(vval, _mm_max_ps(_mm_max_ps(a0, b0), _mm_max_ps(a1, b1)));
    vbad = _mm_or_ps(vbad, _mm_or_ps(_mm_cmpnle_ps(d0, vbig), _mm_cmpnle_ps(d1, vbig)));
    nwarn += (_mm_movemask_ps(_mm_cmpgt_ps(d0, vwarn)) != 0) + (_mm_movemask_ps(_mm_cmpgt_ps(d1, vwarn)) != 0);
    nfail += (_mm_movemask_ps(_mm_cmpgt_ps(d0, vfail)) != 0) + (_mm_movemask_ps(_mm_cmpgt_ps(d1, vfail)) != 0);
  }
  alignas(16) double ds[2], dq[2];
  _mm_store_pd(ds, _mm_add_pd(_mm_add_pd(s0, s1), _mm_add_pd(s2, s3)));
  _mm_store_pd(dq, _mm_add_pd(_mm_add_pd(q0, q1), _mm_add_pd(q2, q3)));
  r.sum += ds[0] + ds[1];
  r.sumsq += dq[0] + dq[1];
  alignas(16) float fm[4], fv[4], fb[4];
  _mm_store_ps(fm, vmax);
  _mm_store_ps(fv, vval);
  _mm_store_ps(fb, vbad);
  for (int c = 0; c < 4; ++c) {
    r.maxerr = std::max(r.maxerr, fm[c]);
    r.maxval = std::max(r.maxval, fv[c]);
    if (fb[c] != 0.0f) r.nonfinite = true;
  }
  r.nwarn += nwarn;
  r.nfail += nfail;
  r.nvalues += std::uint64_t(p - p0) * 4;
  if (p < p1) chunk_generic(L, p, p1, warn, fail, r);
}
#endif

#if defined(SPLINEFIG_HAVE_AVX2_PATH)
// The same with AVX2 and FMA, four pixels a step (chosen at run time). f * f is exact in
// double (24-bit mantissas), so fma(f, f, sum) rounds exactly as sum + f * f does.
__attribute__((target("avx2,fma"))) void chunk_rgba_avx2(const Layout& L, std::size_t p0, std::size_t p1, float warn,
                                                          float fail, Partial& r) {
  const __m256 absmask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
  const __m256 vwarn = _mm256_set1_ps(warn), vfail = _mm256_set1_ps(fail), vbig = _mm256_set1_ps(FLT_MAX);
  __m256d s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd(), s2 = _mm256_setzero_pd(), s3 = _mm256_setzero_pd();
  __m256d q0 = _mm256_setzero_pd(), q1 = _mm256_setzero_pd(), q2 = _mm256_setzero_pd(), q3 = _mm256_setzero_pd();
  __m256 vmax = _mm256_setzero_ps(), vval = _mm256_set1_ps(r.maxval), vbad = _mm256_setzero_ps();
  std::uint64_t nwarn = 0, nfail = 0;
  const float* a = L.a + p0 * 4;
  const float* b = L.b + p0 * 4;
  std::size_t p = p0;
  auto pixels_over = [](int mask) { return int((mask & 0xf) != 0) + int((mask >> 4) != 0); };
  for (; p + 4 <= p1; p += 4, a += 16, b += 16) {
    const __m256 a0 = _mm256_loadu_ps(a), b0 = _mm256_loadu_ps(b);
    const __m256 a1 = _mm256_loadu_ps(a + 8), b1 = _mm256_loadu_ps(b + 8);
    const __m256 d0 = _mm256_and_ps(_mm256_sub_ps(a0, b0), absmask);
    const __m256 d1 = _mm256_and_ps(_mm256_sub_ps(a1, b1), absmask);
    const __m256d l0 = _mm256_cvtps_pd(_mm256_castps256_ps128(d0)), h0 = _mm256_cvtps_pd(_mm256_extractf128_ps(d0, 1));
    const __m256d l1 = _mm256_cvtps_pd(_mm256_castps256_ps128(d1)), h1 = _mm256_cvtps_pd(_mm256_extractf128_ps(d1, 1));
    s0 = _mm256_add_pd(s0, l0);
    s1 = _mm256_add_pd(s1, h0);
    s2 = _mm256_add_pd(s2, l1);
    s3 = _mm256_add_pd(s3, h1);
    q0 = _mm256_fmadd_pd(l0, l0, q0);
    q1 = _mm256_fmadd_pd(h0, h0, q1);
    q2 = _mm256_fmadd_pd(l1, l1, q2);
    q3 = _mm256_fmadd_pd(h1, h1, q3);
    vmax = _mm256_max_ps(vmax, _mm256_max_ps(d0, d1));
    vval = _mm256_max_ps(vval, _mm256_max_ps(_mm256_max_ps(a0, b0), _mm256_max_ps(a1, b1)));
    vbad = _mm256_or_ps(vbad, _mm256_or_ps(_mm256_cmp_ps(d0, vbig, _CMP_NLE_UQ), _mm256_cmp_ps(d1, vbig, _CMP_NLE_UQ)));
    nwarn += std::uint64_t(pixels_over(_mm256_movemask_ps(_mm256_cmp_ps(d0, vwarn, _CMP_GT_OQ))) +
                           pixels_over(_mm256_movemask_ps(_mm256_cmp_ps(d1, vwarn, _CMP_GT_OQ))));
    nfail += std::uint64_t(pixels_over(_mm256_movemask_ps(_mm256_cmp_ps(d0, vfail, _CMP_GT_OQ))) +
                           pixels_over(_mm256_movemask_ps(_mm256_cmp_ps(d1, vfail, _CMP_GT_OQ))));
  }
  alignas(32) double ds[4], dq[4];
  _mm256_store_pd(ds, _mm256_add_pd(_mm256_add_pd(s0, s1), _mm256_add_pd(s2, s3)));
  _mm256_store_pd(dq, _mm256_add_pd(_mm256_add_pd(q0, q1), _mm256_add_pd(q2, q3)));
  r.sum += (ds[0] + ds[1]) + (ds[2] + ds[3]);
  r.sumsq += (dq[0] + dq[1]) + (dq[2] + dq[3]);
  alignas(32) float fm[8], fv[8], fb[8];
  _mm256_store_ps(fm, vmax);
  _mm256_store_ps(fv, vval);
  _mm256_store_ps(fb, vbad);
  for (int c = 0; c < 8; ++c) {
    r.maxerr = std::max(r.maxerr, fm[c]);
    r.maxval = std::max(r.maxval, fv[c]);
    if (fb[c] != 0.0f) r.nonfinite = true;
  }
  r.nwarn += nwarn;
  r.nfail += nfail;
  r.nvalues += std::uint64_t(p - p0) * 4;
  if (p < p1) chunk_generic(L, p, p1, warn, fail, r);
}

bool cpu_has_avx2_fma() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}
#endif

// First (pixel, channel) in [p0, p1) whose error equals `target`.
bool locate(const Layout& L, std::size_t p0, std::size_t p1, float target, std::size_t& where, int& channel) {
  for (std::size_t p = p0; p < p1; ++p) {
    if (L.mask && L.mask[p] == 0.0f) continue;
    for (int c = 0; c < L.nch; ++c) {
      const std::size_t k = p * std::size_t(L.nch) + std::size_t(c);
      const float f = L.err ? L.err[k] : std::fabs(L.a[k] - L.b[k]);
      if (f == target) {
        where = p;
        channel = c;
        return true;
      }
    }
  }
  return false;
}

// ImageBufAlgo::compare's compare_value (OpenImageIO 2.4), value by value, in scanline order:
// a pair with exactly one NaN or one Inf (or Inf against NaN) sets the max error to Inf the first
// time and is not counted; once the max error is Inf such pairs fall through, add NaN or Inf to
// the sums and may make the running maximum NaN; a NaN error is never over a threshold.
Metrics exact_pass(const Layout& L, float fail, float warn) {
  Metrics m;
  double total = 0.0, totalsq = 0.0;
  float maxval = 1.0f;
  const std::size_t npix = std::size_t(L.width) * std::size_t(L.height);
  for (std::size_t p = 0; p < npix; ++p) {
    if (L.mask && L.mask[p] == 0.0f) continue;
    bool warned = false, failed = false;
    for (int c = 0; c < L.nch; ++c) {
      const std::size_t k = p * std::size_t(L.nch) + std::size_t(c);
      const float av = L.a[k], bv = L.b[k];
      const int px = L.x0 + int(p % std::size_t(L.width)), py = L.y0 + int(p / std::size_t(L.width));
      if (!std::isfinite(av) || !std::isfinite(bv)) {
        if (std::isnan(av) == std::isnan(bv) && std::isinf(av) == std::isinf(bv)) continue;
        if (std::isfinite(m.max_error)) {
          m.max_error = std::numeric_limits<float>::infinity();
          m.max_x = px, m.max_y = py, m.max_c = c;
          continue;
        }
      }
      maxval = std::max(maxval, std::max(av, bv));
      const double f = L.err && std::isfinite(av) && std::isfinite(bv) ? double(L.err[k]) : double(std::fabs(av - bv));
      total += f;
      totalsq += f * f;
      if (!(f <= m.max_error)) {
        m.max_error = float(f);
        m.max_x = px, m.max_y = py, m.max_c = c;
      }
      if (!warned && f > warn) {
        ++m.nwarn;
        warned = true;
      }
      if (!failed && f > fail) {
        ++m.nfail;
        failed = true;
      }
    }
    m.nvalues += std::uint64_t(L.nch);
  }
  // idiff 2.4 merges per-block results with '>', so a block whose running maximum became NaN
  // (a NaN pair after an infinite error) contributes no maximum: the whole image is one block.
  if (std::isnan(m.max_error)) m.max_error = 0.0f, m.max_x = 0, m.max_y = 0, m.max_c = 0;
  m.mean_error = total / double(m.nvalues ? m.nvalues : 1);
  m.rms_error = std::sqrt(totalsq / double(m.nvalues ? m.nvalues : 1));
  m.psnr = 20.0 * std::log10(double(maxval) / m.rms_error);
  return m;
}

}  // namespace

bool inner_loop_available(InnerLoop loop) {
  switch (loop) {
    case InnerLoop::fastest:
    case InnerLoop::portable: return true;
#if defined(__SSE2__)
    case InnerLoop::sse2: return true;
#endif
#if defined(SPLINEFIG_HAVE_AVX2_PATH)
    case InnerLoop::avx2: return cpu_has_avx2_fma();
#endif
    default: return false;
  }
}

Metrics idiff_metrics(const Image& a_in, const Image& b_in, float failthresh, float warnthresh,
                      const MetricOptions& options) {
  const Window w = union_window(window_of(a_in), window_of(b_in));
  const int nch = std::max(a_in.channels, b_in.channels);
  // Bring both onto the union window and channel count only when they differ.
  Image a_pad, b_pad;
  const bool a_fits = window_of(a_in) == w && a_in.channels == nch;
  const bool b_fits = window_of(b_in) == w && b_in.channels == nch;
  if (!a_fits) a_pad = pad_to(a_in, w, nch);
  if (!b_fits) b_pad = pad_to(b_in, w, nch);
  const Image& A = a_fits ? a_in : a_pad;
  const Image& B = b_fits ? b_in : b_pad;

  Layout L{A.pixels.data(), B.pixels.data(), options.error ? options.error->pixels.data() : nullptr,
           options.mask ? options.mask->pixels.data() : nullptr, &a_in, w.x, w.y, w.width, w.height, nch};
  const std::size_t npix = std::size_t(w.width) * std::size_t(w.height);

  // idiff's npels: the first image's pixels (those the mask keeps), at least 1.
  std::uint64_t npels = 0;
  if (L.mask) {
    for (std::size_t p = 0; p < npix; ++p)
      if (L.mask[p] != 0.0f && in_first(L, p)) ++npels;
  } else {
    npels = std::uint64_t(a_in.width) * std::uint64_t(a_in.height);
  }

  // Fixed chunks, independent of the thread count.
  const std::size_t chunk = std::size_t(1) << 15;
  const std::size_t nchunks = (npix + chunk - 1) / chunk;
  std::vector<Partial> parts(nchunks);
  if (!inner_loop_available(options.loop))
    throw CompareError("idiff_metrics: this build or CPU lacks the requested inner loop");
  const bool fast = nch == 4 && !L.mask && !L.err && options.loop != InnerLoop::portable;
  auto run = [&](std::size_t i) {
    const std::size_t p0 = i * chunk, p1 = std::min(npix, p0 + chunk);
#if defined(SPLINEFIG_HAVE_AVX2_PATH)
    if (fast && options.loop != InnerLoop::sse2 && cpu_has_avx2_fma())
      return chunk_rgba_avx2(L, p0, p1, warnthresh, failthresh, parts[i]);
#endif
#if defined(__SSE2__)
    if (fast) return chunk_rgba(L, p0, p1, warnthresh, failthresh, parts[i]);
#endif
    chunk_generic(L, p0, p1, warnthresh, failthresh, parts[i]);
  };
  parallel_for(nchunks, options.threads, [&](std::size_t i, int) { run(i); });  // each chunk sums alone

  Partial total;
  for (const Partial& p : parts) {
    if (p.nonfinite) {
      Metrics m = exact_pass(L, failthresh, warnthresh);
      m.npels = npels ? npels : 1;
      return m;
    }
    total.sum += p.sum;
    total.sumsq += p.sumsq;
    total.maxerr = std::max(total.maxerr, p.maxerr);
    total.maxval = std::max(total.maxval, p.maxval);
    total.nwarn += p.nwarn;
    total.nfail += p.nfail;
    total.nvalues += p.nvalues;
  }

  Metrics m;
  const double nvals = double(total.nvalues ? total.nvalues : 1);
  m.mean_error = total.sum / nvals;
  m.rms_error = std::sqrt(total.sumsq / nvals);
  m.psnr = 20.0 * std::log10(double(total.maxval) / m.rms_error);
  m.max_error = total.maxerr;
  m.nwarn = total.nwarn;
  m.nfail = total.nfail;
  m.nvalues = total.nvalues;
  m.npels = npels ? npels : 1;
  if (m.max_error > 0.0f) {
    for (std::size_t i = 0; i < nchunks; ++i) {
      if (parts[i].maxerr != m.max_error) continue;
      std::size_t where = 0;
      int channel = 0;
      if (locate(L, i * chunk, std::min(npix, (i + 1) * chunk), m.max_error, where, channel)) {
        m.max_x = w.x + int(where % std::size_t(w.width));
        m.max_y = w.y + int(where / std::size_t(w.width));
        m.max_c = channel;
      }
      break;
    }
  }
  return m;
}

Verdict idiff_verdict(const Metrics& m, const Thresholds& t) {
  const double npels = double(m.npels);
  if (t.allowfailures >= 0 && m.nfail <= std::uint64_t(t.allowfailures)) return Verdict::match;
  if (double(m.nfail) > t.failpercent / 100.0 * npels || m.max_error > t.hardfail) return Verdict::failure;
  if (double(m.nwarn) > t.warnpercent / 100.0 * npels || m.max_error > t.hardwarn) return Verdict::warning;
  return Verdict::match;
}

}  // namespace splinefig::compare
