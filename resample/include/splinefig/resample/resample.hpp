#pragma once
// Image resampling with a kernel (kernel/kernel.hpp: a spline basis function, box, tent,
// lanczos3) as the reconstruction filter. The contract (docs/resample.md), per axis with S
// source and D destination pixels:
//   output pixel i has its centre at i + 1/2, which maps to the source position x = (i+1/2) S/D;
//   the filter is widened by f = max(1, S/D) (only when reducing);
//   value = sum_j w_j p[j] / sum_j w_j with w_j = k((x - (j + 1/2)) / f)
// (our sign: k(x - centre_j), the kernel convention; OpenImageIO evaluates k(centre_j - x),
// which mirrors an asymmetric Beta kernel). Samples outside [0, S) follow the edge mode:
//   clamp  the nearest edge pixel;
//   mirror ... p1 p0 | p0 p1 ... (half-sample symmetric);
//   wrap   periodic;
//   black  0, still counted in the weight sum.
// Separable: the weights of each axis are computed once, in double precision, and normalised;
// the image is filtered horizontally into a small ring of rows and then vertically, in parallel
// over bands of output rows. Every output value is computed by the same operations whatever the
// thread count, so the result is bit-identical for any number of threads.
#include <splinefig/base/error.hpp>
#include <splinefig/image/image.hpp>
#include <splinefig/kernel/kernel.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig {

// A resampling that cannot be done: an empty source or output, buffers that do not match their
// sizes, weights that sum to zero, a filter the interpolating prefilter cannot invert, values
// that overflow.
struct ResampleError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

enum class Edge { clamp, mirror, wrap, black };
std::optional<Edge> parse_edge(std::string_view name);
const char* edge_name(Edge e);

// Source index for a position j outside [0, size) under an edge mode; -1 for black.
long edge_index(long j, long size, Edge e);

// The weights of one axis; they do not depend on the edge mode (every mode keeps all taps in
// the sum, it only decides what they read). Output i reads the extended source positions
// first[i] .. first[i] + taps - 1 (which may lie outside [0, src)) with weights
// w[i*taps .. i*taps + taps - 1], already divided by their sum.
struct AxisWeights {
  int src = 0, dst = 0, taps = 0;
  std::vector<long> first;
  std::vector<float> w;
  long lo = 0, hi = 0;  // smallest and largest extended position any output reads
};
// Throws ResampleError when the weights of some output sum to zero.
AxisWeights axis_weights(const Kernel& k, int src, int dst);

struct ResampleOptions {
  Edge edge = Edge::clamp;
  bool interpolating = false;  // apply the inverse prefilter first (prefilter.hpp)
  int threads = 0;             // 0: all hardware threads; at most kMaxThreads (base/limits.hpp)
};

// Resamples `src` into `dst`, whose width and height give the new size; dst.channels must
// equal src.channels and dst.pixels must be allocated. Throws ResampleError for bad
// arguments (empty images, channel mismatch, a filter without a stable prefilter inverse).
// The view form reads pixels held elsewhere in place (any row stride); the Image form is the
// same computation on the image's view, so both give the same bits.
void resample_into(const ImageView& src, Image& dst, const Kernel& k, const ResampleOptions& opt = {});
void resample_into(const Image& src, Image& dst, const Kernel& k, const ResampleOptions& opt = {});
Image resample(const Image& src, int width, int height, const Kernel& k, const ResampleOptions& opt = {});

}  // namespace splinefig
