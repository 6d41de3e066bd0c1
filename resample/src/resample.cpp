// The separable two-pass resampler (contract in resample.hpp).
//
// Two orders, chosen per call by counting multiply-adds: a horizontal tap costs about one
// 4-wide vector operation per pixel, a vertical tap C/8 of one (it runs along whole rows).
//   horizontal first: each thread takes a band of output rows, filters the source rows the band
//     needs horizontally into a ring of rows (each once), and combines them vertically;
//   vertical first: each output row combines whole source rows vertically into one extended
//     row, which is then filtered horizontally (better when reducing).
// The loops use the compiler's generic vector types, so they build on any architecture. Chosen
// at compile time where available: on x86-64 each hot loop is also compiled for x86-64-v3 (AVX2)
// and picked at load time, and very large outputs are written with SSE streaming stores; neither
// changes a result (the same operations in the same order, only wider or stored differently).
#include <splinefig/resample/prefilter.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/base/parallel.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <cstdio>
#include <cmath>
#include <limits>

#if defined(__SSE__)
#include <xmmintrin.h>
#define SPLINEFIG_STREAMING_STORES 1
#endif

namespace splinefig {
namespace {

typedef float v4 __attribute__((vector_size(16)));
typedef float v8 __attribute__((vector_size(32)));

#if defined(__x86_64__) && defined(__SSE__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define SPLINEFIG_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
#endif
#ifndef SPLINEFIG_CLONES
#define SPLINEFIG_CLONES
#endif

// Non-temporal stores (they skip reading the destination into the cache first), where the
// architecture has them; elsewhere ordinary stores.
#ifdef SPLINEFIG_STREAMING_STORES
constexpr bool kStreamingStores = true;
inline void stream_store4(float* out, const float* v4f) {
  __m128 v;
  std::memcpy(&v, v4f, sizeof v);
  _mm_stream_ps(out, v);
}
inline void stream_fence() { _mm_sfence(); }  // order the weakly ordered streaming stores
#else
constexpr bool kStreamingStores = false;
inline void stream_store4(float* out, const float* v4f) { std::memcpy(out, v4f, 4 * sizeof(float)); }
inline void stream_fence() {}
#endif

// out[i*C + c] = sum_t w[i*T + t] ext[(first[i] - lo + t)*C + c] for C = 3 or 4. `ext` has 4
// floats of slack at its end; all but the last pixel are stored with one 4-wide store (for C = 3
// its fourth lane is overwritten by the next pixel). TAPS > 0 fixes the tap count at compile time.
template <int TAPS>
inline void horizontal_v4_impl(const float* ext, const long* first, long lo, const float* w, int taps, int dst,
                               int C, float* out) {
  if (TAPS > 0) taps = TAPS;
  auto pixel = [&](int i) {
    const float* base = ext + (first[i] - lo) * C;
    const float* wi = w + static_cast<long>(i) * taps;
    v4 acc = {0, 0, 0, 0};
    for (int t = 0; t < taps; ++t) {
      v4 v;
      std::memcpy(&v, base + t * C, sizeof v);
      acc += wi[t] * v;
    }
    return acc;
  };
  for (int i = 0; i + 1 < dst; ++i) {
    const v4 acc = pixel(i);
    std::memcpy(out + static_cast<long>(i) * C, &acc, sizeof acc);
  }
  const v4 last = pixel(dst - 1);
  std::memcpy(out + static_cast<long>(dst - 1) * C, &last, static_cast<size_t>(C) * sizeof(float));
}

SPLINEFIG_CLONES
void horizontal_v4(const float* ext, const long* first, long lo, const float* w, int taps, int dst, int C,
                   float* out) {
  if (taps == 4)
    horizontal_v4_impl<4>(ext, first, lo, w, taps, dst, C, out);
  else
    horizontal_v4_impl<0>(ext, first, lo, w, taps, dst, C, out);
}

// Two rows at once through horizontal_v4's loop: lanes 0-3 hold row a, lanes 4-7 row b (same
// taps, same weights), so one 8-wide multiply-add does the work of two 4-wide ones. Per lane
// the arithmetic is horizontal_v4's, so a row comes out the same whether paired or not.
template <int TAPS>
inline void horizontal_pair_impl(const float* a, const float* b, const long* first, long lo, const float* w,
                                 int taps, int dst, int C, float* outa, float* outb) {
  if (TAPS > 0) taps = TAPS;
  // Four output pixels per step: four independent chains of multiply-adds hide their latency;
  // each pixel still sums its taps in order, so the grouping does not change its value.
  constexpr int G = 4;
  int i = 0;
  for (; i + G < dst; i += G) {
    v8 acc[G];
    for (int g = 0; g < G; ++g) acc[g] = v8{0, 0, 0, 0, 0, 0, 0, 0};
    for (int t = 0; t < taps; ++t)
      for (int g = 0; g < G; ++g) {
        const long off = (first[i + g] - lo + t) * C;
        v4 va, vb;
        std::memcpy(&va, a + off, sizeof va);
        std::memcpy(&vb, b + off, sizeof vb);
        acc[g] += w[static_cast<long>(i + g) * taps + t] * __builtin_shufflevector(va, vb, 0, 1, 2, 3, 4, 5, 6, 7);
      }
    for (int g = 0; g < G; ++g) {
      const v4 ra = __builtin_shufflevector(acc[g], acc[g], 0, 1, 2, 3);
      const v4 rb = __builtin_shufflevector(acc[g], acc[g], 4, 5, 6, 7);
      std::memcpy(outa + static_cast<long>(i + g) * C, &ra, sizeof ra);
      std::memcpy(outb + static_cast<long>(i + g) * C, &rb, sizeof rb);
    }
  }
  for (; i < dst; ++i) {
    v8 acc = {0, 0, 0, 0, 0, 0, 0, 0};
    for (int t = 0; t < taps; ++t) {
      const long off = (first[i] - lo + t) * C;
      v4 va, vb;
      std::memcpy(&va, a + off, sizeof va);
      std::memcpy(&vb, b + off, sizeof vb);
      acc += w[static_cast<long>(i) * taps + t] * __builtin_shufflevector(va, vb, 0, 1, 2, 3, 4, 5, 6, 7);
    }
    const v4 ra = __builtin_shufflevector(acc, acc, 0, 1, 2, 3), rb = __builtin_shufflevector(acc, acc, 4, 5, 6, 7);
    const size_t bytes = (i + 1 < dst ? 4 : C) * sizeof(float);
    std::memcpy(outa + static_cast<long>(i) * C, &ra, bytes);
    std::memcpy(outb + static_cast<long>(i) * C, &rb, bytes);
  }
}

SPLINEFIG_CLONES
void horizontal_pair(const float* a, const float* b, const long* first, long lo, const float* w, int taps, int dst,
                     int C, float* outa, float* outb) {
  if (taps == 4)
    horizontal_pair_impl<4>(a, b, first, lo, w, taps, dst, C, outa, outb);
  else
    horizontal_pair_impl<0>(a, b, first, lo, w, taps, dst, C, outa, outb);
}

SPLINEFIG_CLONES
void horizontal_any(const float* ext, const long* first, long lo, const float* w, int taps, int dst,
                    int C, float* out) {
  for (int i = 0; i < dst; ++i) {
    const float* base = ext + (first[i] - lo) * C;
    const float* wi = w + static_cast<long>(i) * taps;
    float* o = out + static_cast<long>(i) * C;
    for (int c = 0; c < C; ++c) o[c] = 0;
    for (int t = 0; t < taps; ++t)
      for (int c = 0; c < C; ++c) o[c] += wi[t] * base[t * C + c];
  }
}

// out[k] = sum_t w[t] rows[t][k] for k < n (black rows already left out). Four 8-wide
// accumulators stay in registers across the taps; `stream` writes the output with
// non-temporal stores (worth it only for outputs far larger than the cache).
SPLINEFIG_CLONES
void vertical(const float* const* rows, const float* w, int taps, size_t n, float* __restrict out, bool stream) {
  size_t k = 0;
  if (stream)  // align the output to 16 bytes for the streaming stores
    for (; k < n && (reinterpret_cast<uintptr_t>(out + k) & 15) != 0; ++k) {
      float acc = 0;
      for (int t = 0; t < taps; ++t) acc += w[t] * rows[t][k];
      out[k] = acc;
    }
  for (; k + 32 <= n; k += 32) {
    v8 a0 = {}, a1 = {}, a2 = {}, a3 = {};
    for (int t = 0; t < taps; ++t) {
      const float* r = rows[t] + k;
      const float wt = w[t];
      v8 x0, x1, x2, x3;
      std::memcpy(&x0, r, sizeof x0);
      std::memcpy(&x1, r + 8, sizeof x1);
      std::memcpy(&x2, r + 16, sizeof x2);
      std::memcpy(&x3, r + 24, sizeof x3);
      a0 += wt * x0;
      a1 += wt * x1;
      a2 += wt * x2;
      a3 += wt * x3;
    }
    if (stream) {
      const v8 acc[4] = {a0, a1, a2, a3};
      for (int q = 0; q < 8; ++q) stream_store4(out + k + 4 * q, reinterpret_cast<const float*>(acc) + 4 * q);
    } else {
      std::memcpy(out + k, &a0, sizeof a0);
      std::memcpy(out + k + 8, &a1, sizeof a1);
      std::memcpy(out + k + 16, &a2, sizeof a2);
      std::memcpy(out + k + 24, &a3, sizeof a3);
    }
  }
  for (; k < n; ++k) {
    float acc = 0;
    for (int t = 0; t < taps; ++t) acc += w[t] * rows[t][k];
    out[k] = acc;
  }
  if (stream) stream_fence();
}

// Outputs [i0, i1) of the row, reading extended positions from `base`, which holds position
// base_lo at base[0].
void horizontal(const float* base, long base_lo, const AxisWeights& ax, int i0, int i1, int C, float* out) {
  if (i1 <= i0) return;
  const long* first = ax.first.data() + i0;
  const float* w = ax.w.data() + static_cast<size_t>(i0) * ax.taps;
  float* o = out + static_cast<long>(i0) * C;
  if (C == 3 || C == 4)
    horizontal_v4(base, first, base_lo, w, ax.taps, i1 - i0, C, o);
  else
    horizontal_any(base, first, base_lo, w, ax.taps, i1 - i0, C, o);
}

// Positions lo..hi of a row extended by the edge mode, into buf (4 floats of slack after).
void fill_extended(const float* row, long lo, long hi, int S, int C, Edge e, float* buf) {
  for (long p = lo; p <= hi; ++p) {
    float* d = buf + (p - lo) * C;
    const long q = edge_index(p, S, e);
    if (q < 0)
      std::fill(d, d + C, 0.0f);
    else
      std::memcpy(d, row + q * C, static_cast<size_t>(C) * sizeof(float));
  }
}

// Fills the extension positions lo..-1 and S..hi of a full extended row `ext` (position p at
// ext[(p - lo)*C]) whose positions 0..S-1 already hold the row.
void extend(float* ext, long lo, long hi, int S, int C, Edge e) {
  auto fill = [&](long p) {
    float* d = ext + (p - lo) * C;
    const long q = edge_index(p, S, e);
    if (q < 0)
      std::fill(d, d + C, 0.0f);
    else
      std::memcpy(d, ext + (q - lo) * C, static_cast<size_t>(C) * sizeof(float));
  };
  for (long p = lo; p < 0 && p <= hi; ++p) fill(p);
  for (long p = std::max<long>(S, lo); p <= hi; ++p) fill(p);
}

// Which outputs of a row can read the source row in place: those whose taps (and, for the
// 4-wide loads of C = 3, one float more) lie inside it. first[] is close to monotone, so they
// normally form one run [i0, i1), the few outputs at each end reading small extended copies of
// positions [left_lo, left_hi] and [right_lo, right_hi]; otherwise the whole row is copied.
struct RowSplit {
  bool direct = false;
  int i0 = 0, i1 = 0;
  long left_lo = 0, left_hi = -1, right_lo = 0, right_hi = -1;
};

RowSplit split_row(const AxisWeights& ax, int C) {
  RowSplit r;
  const long slack = C == 3 ? 1 : 0;
  auto inside = [&](int i) {
    const long f = ax.first[static_cast<size_t>(i)];
    return f >= 0 && f + ax.taps + slack <= ax.src;
  };
  int i = 0;
  while (i < ax.dst && !inside(i)) ++i;
  r.i0 = i;
  while (i < ax.dst && inside(i)) ++i;
  r.i1 = i;
  for (; i < ax.dst; ++i)
    if (inside(i)) return r;  // not one run
  if (r.i1 == r.i0) return r;
  r.direct = true;
  auto range = [&](int a, int b, long& lo, long& hi) {
    for (int k = a; k < b; ++k) {
      lo = k == a ? ax.first[static_cast<size_t>(k)] : std::min(lo, ax.first[static_cast<size_t>(k)]);
      hi = k == a ? ax.first[static_cast<size_t>(k)] + ax.taps - 1
                  : std::max(hi, ax.first[static_cast<size_t>(k)] + ax.taps - 1);
    }
  };
  range(0, r.i0, r.left_lo, r.left_hi);
  range(r.i1, ax.dst, r.right_lo, r.right_hi);
  return r;
}

template <class F>
void parallel_chunks(int chunks, int threads, F&& work) {
  parallel_for(static_cast<std::size_t>(chunks), threads, [&](std::size_t c, int) { work(static_cast<int>(c)); });
}

struct Plan {
  ImageView src;
  Image& dst;
  AxisWeights ax, ay;
  Edge edge;
  int C;
  bool stream;  // the output is far larger than the caches
  RowSplit split;
  // The extended row holds positions ext_lo() .. ext_hi(), plus 4 floats of slack.
  long ext_lo() const { return std::min(ax.lo, 0L); }
  long ext_hi() const { return std::max(ax.hi, static_cast<long>(src.width) - 1); }
  size_t ext_len() const { return static_cast<size_t>(ext_hi() - ext_lo() + 1) * C + 4; }
};

// The source rows output row y reads, black ones left out, with their weights.
struct Taps {
  std::vector<const float*> rows;
  std::vector<float> w;
  std::vector<long> pos;  // extended positions
  void gather(const Plan& p, int y) {
    rows.clear();
    w.clear();
    pos.clear();
    const int Ty = p.ay.taps;
    for (int t = 0; t < Ty; ++t) {
      const long at = p.ay.first[static_cast<size_t>(y)] + t;
      const float wt = p.ay.w[static_cast<size_t>(y) * Ty + t];
      const long r = edge_index(at, p.src.height, p.edge);
      if (r < 0 || wt == 0) continue;
      rows.push_back(p.src.row(static_cast<int>(r)));
      w.push_back(wt);
      pos.push_back(at);
    }
  }
};

// One source row filtered horizontally into out (dst.width pixels); ext is scratch of ext_len().
void filter_row(const Plan& p, const float* row, float* ext, float* out) {
  const int C = p.C, S = p.src.width;
  const RowSplit& r = p.split;
  if (!r.direct) {
    const long lo = p.ext_lo();
    std::memcpy(ext + (0 - lo) * C, row, p.src.row_length() * sizeof(float));
    extend(ext, lo, p.ext_hi(), S, C, p.edge);
    horizontal(ext, lo, p.ax, 0, p.ax.dst, C, out);
    return;
  }
  // The interior reads the row in place; each end reads its own small extended copy. Each
  // call stores its last pixel with exactly C floats, so the three runs never overlap.
  if (r.i0 > 0) {
    fill_extended(row, r.left_lo, r.left_hi, S, C, p.edge, ext);
    horizontal(ext, r.left_lo, p.ax, 0, r.i0, C, out);
  }
  if (r.i1 < p.ax.dst) {
    fill_extended(row, r.right_lo, r.right_hi, S, C, p.edge, ext);
    horizontal(ext, r.right_lo, p.ax, r.i1, p.ax.dst, C, out);
  }
  horizontal(row, 0, p.ax, r.i0, r.i1, C, out);
}

// Source rows a and b (b may be null) filtered horizontally into outa and outb. With 3 or 4
// channels the interior runs go through the paired loop, a lone row paired with itself (its
// twin written to `spare`): every row then takes the same instructions whether it was paired
// or not, which keeps results independent of how threads cut the image into bands (a separate
// single-row loop may contract multiply-adds differently).
void filter_rows(const Plan& p, const float* a, const float* b, float* ext, float* outa, float* outb, float* spare) {
  const RowSplit& r = p.split;
  if (!r.direct || !(p.C == 3 || p.C == 4)) {
    filter_row(p, a, ext, outa);
    if (b) filter_row(p, b, ext, outb);
    return;
  }
  const int C = p.C, S = p.src.width;
  for (auto [row, out] : {std::pair{a, outa}, std::pair{b, outb}}) {
    if (!row) continue;
    if (r.i0 > 0) {
      fill_extended(row, r.left_lo, r.left_hi, S, C, p.edge, ext);
      horizontal(ext, r.left_lo, p.ax, 0, r.i0, C, out);
    }
    if (r.i1 < p.ax.dst) {
      fill_extended(row, r.right_lo, r.right_hi, S, C, p.edge, ext);
      horizontal(ext, r.right_lo, p.ax, r.i1, p.ax.dst, C, out);
    }
  }
  const size_t off = static_cast<size_t>(r.i0);
  horizontal_pair(a, b ? b : a, p.ax.first.data() + off, 0, p.ax.w.data() + off * p.ax.taps, p.ax.taps,
                  r.i1 - r.i0, C, outa + off * C, (b ? outb : spare) + off * C);
}

void horizontal_first(const Plan& p, int threads) {
  const int Dy = p.dst.height, Ty = p.ay.taps;
  const size_t drow = p.dst.row_stride();
  const int chunks = threads == 1 ? 1 : static_cast<int>(std::min<long long>(Dy, threads * 4LL));
  parallel_chunks(chunks, threads, [&](int chunk) {
    const int y0 = static_cast<int>(static_cast<long>(Dy) * chunk / chunks);
    const int y1 = static_cast<int>(static_cast<long>(Dy) * (chunk + 1) / chunks);
    std::vector<float> ext(p.ext_len());
    // Slots are keyed by extended row position, which is consecutive within a window of Ty
    // rows; with one slot more than a window, filtering the row after a missing one as well
    // (a pair, see filter_rows) evicts only a row the window has passed. (Keying by source
    // row would not do: under wrap the rows S-2 and 0 can share a slot.)
    const long R = Ty + 1;
    std::vector<float> ring(static_cast<size_t>(R) * (drow + 4));
    std::vector<long> held(static_cast<size_t>(R), std::numeric_limits<long>::min());
    std::vector<float> spare(drow + 4);
    auto slot_of = [&](long pos) { return static_cast<size_t>(((pos % R) + R) % R); };
    auto ring_row = [&](size_t slot) { return ring.data() + slot * (drow + 4); };
    const long last = p.ay.first[static_cast<size_t>(y1 - 1)] + Ty - 1;  // the chunk's last row
    Taps taps;
    for (int y = y0; y < y1; ++y) {
      taps.gather(p, y);
      for (size_t t = 0; t < taps.rows.size(); ++t) {
        const long pos = taps.pos[t];
        const size_t slot = slot_of(pos);
        if (held[slot] != pos) {
          const long next = edge_index(pos + 1, p.src.height, p.edge);
          const size_t slot2 = slot_of(pos + 1);
          if (pos + 1 <= last && next >= 0 && held[slot2] != pos + 1) {
            filter_rows(p, taps.rows[t], p.src.row(static_cast<int>(next)), ext.data(), ring_row(slot),
                        ring_row(slot2), spare.data());
            held[slot2] = pos + 1;
          } else {
            filter_rows(p, taps.rows[t], nullptr, ext.data(), ring_row(slot), nullptr, spare.data());
          }
          held[slot] = pos;
        }
        taps.rows[t] = ring_row(slot);
      }
      vertical(taps.rows.data(), taps.w.data(), static_cast<int>(taps.rows.size()), drow, p.dst.row(y), p.stream);
    }
  });
}

void vertical_first(const Plan& p, int threads) {
  const int C = p.C, Dy = p.dst.height;
  const int chunks = threads == 1 ? 1 : static_cast<int>(std::min<long long>(Dy, threads * 4LL));
  parallel_chunks(chunks, threads, [&](int chunk) {
    const int y0 = static_cast<int>(static_cast<long>(Dy) * chunk / chunks);
    const int y1 = static_cast<int>(static_cast<long>(Dy) * (chunk + 1) / chunks);
    std::vector<float> ext(p.ext_len());
    Taps taps;
    const long lo = p.ext_lo();
    for (int y = y0; y < y1; ++y) {
      taps.gather(p, y);
      vertical(taps.rows.data(), taps.w.data(), static_cast<int>(taps.rows.size()), p.src.row_length(),
               ext.data() + (0 - lo) * C, false);
      extend(ext.data(), lo, p.ext_hi(), p.src.width, C, p.edge);
      horizontal(ext.data(), lo, p.ax, 0, p.ax.dst, C, p.dst.row(y));
    }
  });
}

bool all_finite(const ImageView& im) {
  for (int j = 0; j < im.height; ++j) {
    const float* r = im.row(j);
    for (std::size_t k = 0; k < im.row_length(); ++k)
      if (!std::isfinite(r[k])) return false;
  }
  return true;
}

// The largest sum of |weights| over an axis's outputs: how far a weighted sum of values of
// magnitude m can reach (m times this), the negative lobes included.
double largest_abs_sum(const AxisWeights& a) {
  double most = 0;
  for (std::size_t i = 0; i < std::size_t(a.dst); ++i) {
    double sum = 0;
    for (int t = 0; t < a.taps; ++t) sum += std::abs(double(a.w[i * std::size_t(a.taps) + std::size_t(t)]));
    most = std::max(most, sum);
  }
  return most;
}

// Finite values large enough that a float sum of weighted taps could overflow to infinity are
// refused: the largest finite |value| times both axes' largest sums of |weights| must stay
// within FLT_MAX (with a margin of 2^-16 for the rounding of up to 256 partial sums, 2^-24 each).
// Non-finite values pass through as they are.
void check_range(const ImageView& src, const AxisWeights& ax, const AxisWeights& ay, const char* what) {
  float peak = 0;
  for (int j = 0; j < src.height; ++j) {
    const float* r = src.row(j);
    for (std::size_t k = 0; k < src.row_length(); ++k)
      if (std::isfinite(r[k])) peak = std::max(peak, std::abs(r[k]));
  }
  const double gain = largest_abs_sum(ax) * largest_abs_sum(ay);
  const double limit = double(std::numeric_limits<float>::max()) / (gain * (1 + 1.0 / 65536));
  if (double(peak) <= limit) return;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "resample: %s values up to %.9g would overflow a float through the filter's weights (their absolute "
                "sums reach %.6g x %.6g); at most %.3g can be resampled",
                what, double(peak), largest_abs_sum(ax), largest_abs_sum(ay), limit);
  throw ResampleError(buf);
}

}  // namespace

void resample_into(const ImageView& src_in, Image& dst, const Kernel& k, const ResampleOptions& opt) {
  if (src_in.width < 1 || src_in.height < 1 || src_in.channels < 1)
    throw ResampleError("resample: the source image is empty");
  if (!src_in.data || src_in.row_stride < src_in.row_length())
    throw ResampleError("resample: the source's rows are shorter than its width");
  if (dst.width < 1 || dst.height < 1) throw ResampleError("resample: the output size is zero");
  if (dst.channels != src_in.channels)
    throw ResampleError("resample: the output must have the source's channel count");
  if (dst.pixels.size() != static_cast<size_t>(dst.height) * dst.row_stride())
    throw ResampleError("resample: pixel buffer size does not match the image size");
  const int threads = worker_count(opt.threads);
  Image coefficients;
  ImageView src = src_in;
  if (opt.interpolating) {  // the prefilter works in place, on a packed copy
    coefficients = Image(src_in.width, src_in.height, src_in.channels);
    for (int j = 0; j < src_in.height; ++j)
      std::memcpy(coefficients.row(j), src_in.row(j), src_in.row_length() * sizeof(float));
    const bool finite = all_finite(src_in);
    prefilter(coefficients, k, opt.edge, threads);
    src = coefficients.view();
    if (finite && !all_finite(src))
      throw ResampleError("resample: source values this large overflow a float in the interpolating prefilter");
  }
  Plan p{src, dst, axis_weights(k, src.width, dst.width), axis_weights(k, src.height, dst.height), opt.edge, src.channels,
         kStreamingStores && dst.pixels.size() * sizeof(float) > (size_t(32) << 20), {}};
  check_range(src, p.ax, p.ay, opt.interpolating ? "the interpolating prefilter's" : "source");
  p.split = split_row(p.ax, p.C);
  // Multiply-adds, in units of a 4-wide horizontal tap (see the top of this file).
  const double C = p.C, hx = p.ax.taps * (C <= 4 ? 1.0 : C / 4), vy = p.ay.taps * C / 8;
  const double used_rows = std::min<double>(src.height, double(p.ay.hi - p.ay.lo + 1));
  const double h_first = used_rows * dst.width * hx + double(dst.height) * dst.width * vy;
  const double v_first = double(dst.height) * src.width * vy + double(dst.height) * dst.width * hx;
  if (h_first <= v_first)
    horizontal_first(p, threads);
  else
    vertical_first(p, threads);
}

void resample_into(const Image& src, Image& dst, const Kernel& k, const ResampleOptions& opt) {
  if (src.pixels.size() != static_cast<size_t>(src.height) * src.row_stride())
    throw ResampleError("resample: pixel buffer size does not match the image size");
  resample_into(src.view(), dst, k, opt);
}

Image resample(const Image& src, int width, int height, const Kernel& k, const ResampleOptions& opt) {
  if (width < 1 || height < 1) throw ResampleError("resample: the output size is zero");
  Image dst(width, height, src.channels);
  dst.copy_metadata_from(src);
  resample_into(src, dst, k, opt);
  return dst;
}

}  // namespace splinefig
