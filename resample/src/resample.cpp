// The separable two-pass resampler (contract in resample.hpp).
//
// Two orders, chosen per call by counting multiply-adds: a horizontal tap costs about one
// 4-wide vector operation per pixel, a vertical tap C/8 of one (it runs along whole rows).
//   horizontal first: each thread takes a band of output rows, filters the source rows the band
//     needs horizontally into a ring of rows (each once), and combines them vertically;
//   vertical first: each output row combines whole source rows vertically into one extended
//     row, which is then filtered horizontally (better when reducing).
#include <splinefig/resample/prefilter.hpp>
#include <splinefig/resample/resample.hpp>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>
#include <thread>

namespace splinefig {
namespace {

typedef float v4 __attribute__((vector_size(16)));

#define SPLINEFIG_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))

// out[i*C + c] = sum_t w[i*T + t] ext[(first[i] - lo + t)*C + c] for C = 3 or 4. `ext` has 4
// floats of slack at its end; all but the last pixel are stored with one 4-wide store (for C = 3
// its fourth lane is overwritten by the next pixel).
SPLINEFIG_CLONES
void horizontal_v4(const float* ext, const long* first, long lo, const float* w, int taps, int dst,
                   int C, float* out) {
  for (int i = 0; i < dst; ++i) {
    const float* base = ext + (first[i] - lo) * C;
    const float* wi = w + static_cast<long>(i) * taps;
    v4 acc = {0, 0, 0, 0};
    for (int t = 0; t < taps; ++t) {
      v4 v;
      std::memcpy(&v, base + t * C, sizeof v);
      acc += wi[t] * v;
    }
    std::memcpy(out + static_cast<long>(i) * C, &acc, (i + 1 < dst ? 4 : C) * sizeof(float));
  }
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

// out[k] = sum_t w[t] rows[t][k] for k < n; a null row is black and adds nothing.
SPLINEFIG_CLONES
void vertical(const float* const* rows, const float* w, int taps, size_t n, float* __restrict out) {
  constexpr size_t block = 512;
  float acc[block];
  for (size_t k0 = 0; k0 < n; k0 += block) {
    const size_t len = std::min(block, n - k0);
    for (size_t k = 0; k < len; ++k) acc[k] = 0;
    for (int t = 0; t < taps; ++t) {
      const float* __restrict r = rows[t];
      if (!r) continue;
      const float wt = w[t];
      for (size_t k = 0; k < len; ++k) acc[k] += wt * r[k0 + k];
    }
    std::memcpy(out + k0, acc, len * sizeof(float));
  }
}

void horizontal(const float* ext, const AxisWeights& ax, int C, float* out) {
  if (C == 3 || C == 4)
    horizontal_v4(ext, ax.first.data(), ax.lo, ax.w.data(), ax.taps, ax.dst, C, out);
  else
    horizontal_any(ext, ax.first.data(), ax.lo, ax.w.data(), ax.taps, ax.dst, C, out);
}

// Fills the extension positions lo..-1 and S..hi of `ext` (position p at ext[(p - lo)*C]),
// whose positions 0..S-1 already hold the row.
void extend(float* ext, long lo, long hi, int S, int C, Edge e) {
  for (long p = lo; p <= hi; ++p) {
    if (p >= 0 && p < S) continue;
    float* d = ext + (p - lo) * C;
    const long q = edge_index(p, S, e);
    if (q < 0)
      std::fill(d, d + C, 0.0f);
    else
      std::memcpy(d, ext + (q - lo) * C, static_cast<size_t>(C) * sizeof(float));
  }
}

template <class F>
void parallel_chunks(int chunks, int threads, F&& work) {
  std::atomic<int> next{0};
  auto run = [&] {
    for (int c; (c = next.fetch_add(1)) < chunks;) work(c);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(threads, chunks); ++t) pool.emplace_back(run);
  run();
  for (auto& t : pool) t.join();
}

struct Plan {
  const Image& src;
  Image& dst;
  AxisWeights ax, ay;
  Edge edge;
  int C;
  // The extended row holds positions ext_lo() .. ext_hi(), plus 4 floats of slack.
  long ext_lo() const { return std::min(ax.lo, 0L); }
  long ext_hi() const { return std::max(ax.hi, static_cast<long>(src.width) - 1); }
  size_t ext_len() const { return static_cast<size_t>(ext_hi() - ext_lo() + 1) * C + 4; }
};

void horizontal_first(const Plan& p, int threads) {
  const int C = p.C, Dy = p.dst.height, Ty = p.ay.taps;
  const size_t drow = p.dst.row_stride();
  const int chunks = threads == 1 ? 1 : std::min(Dy, threads * 4);
  parallel_chunks(chunks, threads, [&](int chunk) {
    const int y0 = static_cast<int>(static_cast<long>(Dy) * chunk / chunks);
    const int y1 = static_cast<int>(static_cast<long>(Dy) * (chunk + 1) / chunks);
    std::vector<float> ext(p.ext_len());
    std::vector<float> ring(static_cast<size_t>(Ty) * (drow + 4));
    // Slots are keyed by extended row position, which is consecutive within a window of Ty
    // rows, so a window never evicts its own rows (keying by source row would: under wrap the
    // rows S-2 and 0 can share a slot).
    std::vector<long> held(static_cast<size_t>(Ty), std::numeric_limits<long>::min());
    std::vector<const float*> rows(static_cast<size_t>(Ty));
    const long lo = p.ext_lo();
    for (int y = y0; y < y1; ++y) {
      for (int t = 0; t < Ty; ++t) {
        const long pos = p.ay.first[static_cast<size_t>(y)] + t;
        const long r = edge_index(pos, p.src.height, p.edge);
        if (r < 0) {
          rows[static_cast<size_t>(t)] = nullptr;
          continue;
        }
        const size_t slot = static_cast<size_t>(((pos % Ty) + Ty) % Ty);
        float* h = ring.data() + slot * (drow + 4);
        if (held[slot] != pos) {
          std::memcpy(ext.data() + (0 - lo) * C, p.src.row(static_cast<int>(r)), p.src.row_stride() * sizeof(float));
          extend(ext.data(), lo, p.ext_hi(), p.src.width, C, p.edge);
          horizontal(ext.data() + (p.ax.lo - lo) * C, p.ax, C, h);
          held[slot] = pos;
        }
        rows[static_cast<size_t>(t)] = h;
      }
      vertical(rows.data(), p.ay.w.data() + static_cast<size_t>(y) * Ty, Ty, drow, p.dst.row(y));
    }
  });
}

void vertical_first(const Plan& p, int threads) {
  const int C = p.C, Dy = p.dst.height, Ty = p.ay.taps;
  const int chunks = threads == 1 ? 1 : std::min(Dy, threads * 4);
  parallel_chunks(chunks, threads, [&](int chunk) {
    const int y0 = static_cast<int>(static_cast<long>(Dy) * chunk / chunks);
    const int y1 = static_cast<int>(static_cast<long>(Dy) * (chunk + 1) / chunks);
    std::vector<float> ext(p.ext_len());
    std::vector<const float*> rows(static_cast<size_t>(Ty));
    const long lo = p.ext_lo();
    for (int y = y0; y < y1; ++y) {
      for (int t = 0; t < Ty; ++t) {
        const long r = edge_index(p.ay.first[static_cast<size_t>(y)] + t, p.src.height, p.edge);
        rows[static_cast<size_t>(t)] = r < 0 ? nullptr : p.src.row(static_cast<int>(r));
      }
      vertical(rows.data(), p.ay.w.data() + static_cast<size_t>(y) * Ty, Ty, p.src.row_stride(),
               ext.data() + (0 - lo) * C);
      extend(ext.data(), lo, p.ext_hi(), p.src.width, C, p.edge);
      horizontal(ext.data() + (p.ax.lo - lo) * C, p.ax, C, p.dst.row(y));
    }
  });
}

}  // namespace

int resolve_threads(int threads) {
  if (threads > 0) return threads;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

void resample_into(const Image& src_in, Image& dst, const Filter& f, const ResampleOptions& opt) {
  if (src_in.width < 1 || src_in.height < 1 || src_in.channels < 1)
    throw std::invalid_argument("resample: the source image is empty");
  if (dst.width < 1 || dst.height < 1) throw std::invalid_argument("resample: the output size is zero");
  if (dst.channels != src_in.channels)
    throw std::invalid_argument("resample: the output must have the source's channel count");
  if (src_in.pixels.size() != static_cast<size_t>(src_in.height) * src_in.row_stride() ||
      dst.pixels.size() != static_cast<size_t>(dst.height) * dst.row_stride())
    throw std::invalid_argument("resample: pixel buffer size does not match the image size");
  const int threads = resolve_threads(opt.threads);
  Image coefficients;
  const Image* src = &src_in;
  if (opt.interpolating) {
    coefficients = src_in;
    prefilter(coefficients, f, opt.edge, threads);
    src = &coefficients;
  }
  Plan p{*src, dst, axis_weights(f, src->width, dst.width, opt.edge),
         axis_weights(f, src->height, dst.height, opt.edge), opt.edge, src->channels};
  // Multiply-adds, in units of a 4-wide horizontal tap (see the top of this file).
  const double C = p.C, hx = p.ax.taps * (C <= 4 ? 1.0 : C / 4), vy = p.ay.taps * C / 8;
  const double used_rows = std::min<double>(src->height, double(p.ay.hi - p.ay.lo + 1));
  const double h_first = used_rows * dst.width * hx + double(dst.height) * dst.width * vy;
  const double v_first = double(dst.height) * src->width * vy + double(dst.height) * dst.width * hx;
  if (h_first <= v_first)
    horizontal_first(p, threads);
  else
    vertical_first(p, threads);
}

Image resample(const Image& src, int width, int height, const Filter& f, const ResampleOptions& opt) {
  if (width < 1 || height < 1) throw std::invalid_argument("resample: the output size is zero");
  Image dst(width, height, src.channels);
  resample_into(src, dst, f, opt);
  return dst;
}

}  // namespace splinefig
