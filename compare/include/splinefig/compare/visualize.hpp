#pragma once
// Pictures of a difference, for humans: the scaled absolute difference (as idiff -o -abs
// -scale S writes it) and a triptych: expected | actual | heat map of the difference.
#include <splinefig/compare/image.hpp>

namespace splinefig::compare {

// |a - b| * scale for every value; a and b on the same window with the same channels. The
// result holds data, not colour: it is marked sRGB so that an 8-bit file stores the values as
// they are (clamped to [0, 1]) and has no alpha channel: for images with alpha it holds the
// colour channels' difference only (opaque, so that a file shows it), and
// alpha_difference_image() the alpha channel's.
Image difference_image(const Image& a, const Image& b, float scale);
// |alpha of a - alpha of b| * scale, one channel (all 0 if either image has no alpha).
Image alpha_difference_image(const Image& a, const Image& b, float scale);

// Heat-map colour (the magma colour map, piecewise linear through 9 of its samples) of t in [0, 1].
void heat_colour(float t, float rgb[3]);

// expected | actual | heat map, 2-pixel white gaps, RGB ready for display (sRGB-encoded). Images
// are shown over a grey checkerboard where they are transparent. The heat map shows the
// largest channel difference per pixel times `heat_scale` (1 at the top of the colour map).
Image triptych(const Image& expected, const Image& actual, float heat_scale);

}  // namespace splinefig::compare
