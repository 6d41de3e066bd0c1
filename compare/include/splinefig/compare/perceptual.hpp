#pragma once
// Perceptual metrics.
//
// SSIM (Wang, Bovik, Sheikh, Simoncelli, "Image quality assessment: from error visibility to
// structural similarity", IEEE TIP 13(4), 2004): on luminance Y = 0.2126 R + 0.7152 G +
// 0.0722 B of the values as compared (encoded values by default, linear light when the images
// were decoded), an 11x11 Gaussian window with sigma 1.5 normalised to sum 1, K1 = 0.01,
// K2 = 0.03, dynamic range L = 1, population (not sample) statistics, averaged over the
// positions where the whole window lies inside the image ("valid", as the paper's reference
// code does). Images smaller than 11 x 11 have no SSIM.
//
// LDR-FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom, Fairchild, "FLIP: A
// Difference Evaluator for Alternating Images", HPG 2020): sRGB in [0, 1] -> linear RGB -> XYZ ->
// YCxCz; colour pipeline: per-channel contrast-sensitivity Gaussians (the paper's a1, b1, a2, b2),
// clamp in linear RGB, CIELAB with Hunt adjustment, HyAB distance, exponent qc = 0.7,
// redistribution with pc = 0.4, pt = 0.95; feature pipeline: edge and point detectors
// (first and second Gaussian derivatives, w = 0.082 degrees) on (Y + 16) / 116, exponent
// qf = 0.5; FLIP = dE_c ^ (1 - dE_f). Borders replicate the edge pixels. Default observer:
// 67.02 pixels per degree (0.7 m wide 4K display at 0.7 m).
#include <splinefig/compare/image.hpp>

#include <optional>

namespace splinefig::compare {

// One-channel luminance (1 channel: itself; 2: the first; otherwise Rec. 709 weights of the
// first three non-alpha channels).
Image luminance(const Image& im);

// Mean SSIM of two images on the same window; nullopt when smaller than 11 x 11.
std::optional<double> ssim(const Image& a, const Image& b);

inline constexpr double flip_default_ppd = 67.02064327658226;  // 3840 * pi / 180

struct FlipResult {
  double mean = 0.0;
  double max = 0.0;
  Image map;  // one channel, the per-pixel FLIP error in [0, 1]
};

// LDR-FLIP of `test` against `reference`, same window. Colour is taken in linear light (sRGB
// images are decoded) and clamped to [0, 1]; alpha is ignored (colour is premultiplied, i.e.
// over black); one- and two-channel images are grey.
FlipResult flip(const Image& reference, const Image& test, double pixels_per_degree = flip_default_ppd);

}  // namespace splinefig::compare
