#pragma once
// The one way anything reaches the canvas: Porter-Duff over, px = paint * c + px * (1 - alpha * c),
// for a paint (a premultiplied colour) at coverage c in [0, 1]. Shapes, text, filtered shapes,
// raster images and the background all go through it.
//
// The blend space decides in which values "over" is computed. Linear light (the default) is
// physically right: half coverage of white over black is half the light. sRGB blending is what
// AGG, browsers and most 2-D libraries do: the same arithmetic on sRGB-encoded values, so that
// a PNG matches what those draw (and the SVG or PDF a viewer composites that way). The canvas
// holds premultiplied values of its blend space throughout (for sRGB: the encoded straight colour
// times alpha, Encoding::srgb of image.hpp), and is handed out in that encoding: no decoding and
// re-encoding between the last composite and the file.
//
// Exactness: in either space each channel is two float products and one sum, rounded as written
// (the SSE lanes perform the same IEEE operations as the scalar form, in the same order), so the
// bytes do not depend on the path taken or on the thread that drew the band.
#include <splinefig/image/srgb.hpp>
#include <splinefig/renderer/renderer.hpp>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define SPLINEFIG_COMPOSITOR_SSE 1
#endif

namespace splinefig::render::detail {

// A colour ready to composite: premultiplied, in the canvas's blend space.
struct alignas(16) Paint {
  float v[4]{};
  float alpha() const { return v[3]; }
};

// px = paint * c + px * (1 - paint.alpha * c): the only blend the canvas sees.
inline void over(float* px, const Paint& p, float c) {
  const float k = 1.0f - p.v[3] * c;
#if SPLINEFIG_COMPOSITOR_SSE
  const __m128 d = _mm_loadu_ps(px);
  _mm_storeu_ps(px, _mm_add_ps(_mm_mul_ps(_mm_load_ps(p.v), _mm_set1_ps(c)), _mm_mul_ps(d, _mm_set1_ps(k))));
#else
  for (int ch = 0; ch < 4; ++ch) px[ch] = p.v[ch] * c + px[ch] * k;
#endif
}

class Compositor {
 public:
  explicit Compositor(BlendSpace space) : space_(space) {}
  BlendSpace space() const { return space_; }
  Encoding encoding() const { return space_ == BlendSpace::srgb ? Encoding::srgb : Encoding::linear; }

  // A straight-alpha linear colour (the API's Color) as a paint.
  Paint paint(Color c) const {
    const float a = c.a;
    if (space_ == BlendSpace::linear) return Paint{{c.r * a, c.g * a, c.b * a, a}};
    return Paint{{linear_to_srgb(c.r) * a, linear_to_srgb(c.g) * a, linear_to_srgb(c.b) * a, a}};
  }
  // A premultiplied RGBA sample (a raster item's pixel) in `from` (linear light, or
  // sRGB-encoded values) as a paint.
  Paint paint_premultiplied(const float* s, Encoding from = Encoding::linear) const {
    if (from == encoding() || !(s[3] > 0)) return Paint{{s[0], s[1], s[2], s[3]}};
    const float a = s[3];
    if (from == Encoding::srgb)
      return Paint{{srgb_to_linear(s[0] / a) * a, srgb_to_linear(s[1] / a) * a, srgb_to_linear(s[2] / a) * a, a}};
    return Paint{{linear_to_srgb(s[0] / a) * a, linear_to_srgb(s[1] / a) * a, linear_to_srgb(s[2] / a) * a, a}};
  }

 private:
  BlendSpace space_;
};

}  // namespace splinefig::render::detail
