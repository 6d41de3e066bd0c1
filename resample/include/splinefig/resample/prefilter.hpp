#pragma once
// The exact inverse prefilter that makes an approximating spline interpolate its samples.
//
// Reconstructing coefficients c with a kernel k gives at the sample positions
//   p_i = sum_j c_j k(i - j) = k(1) c_{i-1} + k(0) c_i + k(-1) c_{i+1}
// for the cubic bases (their kernels vanish at every other integer); for the B-spline this is
// the 1-4-1 system (c_{i-1} + 4 c_i + c_{i+1}) / 6 = p_i of seed 003. Solving it along every row
// and then every column, with c extended beyond the image by the same edge mode the resampler
// uses, makes resampling to the same size return the samples (Unser, Aldroubi and Eden,
// "B-spline signal processing", 1993).
//
// The inverse of the sampled kernel H(z) = k(-1) z + k(0) + k(1) z^-1 is stable when
// z H(z) = k(-1) z^2 + k(0) z + k(1) has one root z1 inside the unit circle and one outside
// (z2): then H(z) = -k(-1) z2 (1 - z1 z^-1)(1 - z / z2), a causal recursion with pole z1 followed
// by an anticausal one with pole 1/z2 (for the B-spline z1 = 1/z2 = sqrt(3) - 2). For a positive
// kernel that is a partition of unity the condition is k(0) > 1/2; a Beta-spline with b2 = 0
// meets it for (3 - sqrt 5)/2 < b1 < (3 + sqrt 5)/2. Otherwise the inverse grows geometrically
// and there is no stable prefilter: that is an error.
//
// Boundaries: clamp and mirror both extend c by c_{-1} = c_0, c_N = c_{N-1} (the same for three
// taps); black by zeros; these give tridiagonal systems, solved by the forward and backward
// sweeps of Gaussian elimination, whose pivots converge to the steady recursions above (the
// first few differ: that is the exact boundary handling). wrap gives a circulant system, solved by
// the two recursions started from their exact periodic sums.
#include <splinefig/image/image.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/kernel/kernel.hpp>

namespace splinefig {

// k(-1), k(0), k(1) normalised by their sum. Throws ResampleError when k is non-zero at
// another integer (a wider prefilter is not implemented) or the inverse is not stable.
struct SampledKernel {
  double left = 0, centre = 1, right = 0;  // coefficients of c_{i+1}, c_i, c_{i-1}
};
SampledKernel sampled_kernel(const Kernel& k);

// Solves sum_j c_j k(i-j) = p_i along one line of n values (stride `stride`), in place.
void prefilter_line(float* p, long n, long stride, const SampledKernel& h, Edge edge);

// Applies the prefilter along every row and every column of `img`, in place.
void prefilter(Image& img, const Kernel& k, Edge edge, int threads = 0);

}  // namespace splinefig
