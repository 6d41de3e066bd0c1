// Resampling through a view of pixels held elsewhere: the same bytes as resampling an Image
// holding the same values, whatever the row stride and the buffer's alignment, and nothing but
// the rows' values is read.
#include <catch2/catch.hpp>

#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace splinefig;

namespace {

Image random_image(int w, int h, int c, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<float> u(-0.25f, 1.25f);
  Image im(w, h, c);
  for (float& v : im.pixels) v = u(gen);
  return im;
}

// The pixels of `im` in a larger buffer: rows `pad` floats apart beyond their values, the
// first value `offset` floats in, every other float NaN (a read of one would show in the result).
std::vector<float> padded_copy(const Image& im, std::size_t pad, std::size_t offset, ImageView& view) {
  const std::size_t stride = im.row_stride() + pad;
  std::vector<float> buf(offset + stride * std::size_t(im.height), std::numeric_limits<float>::quiet_NaN());
  for (int j = 0; j < im.height; ++j)
    std::memcpy(buf.data() + offset + std::size_t(j) * stride, im.row(j), im.row_stride() * sizeof(float));
  view = ImageView{buf.data() + offset, im.width, im.height, im.channels, stride};
  return buf;
}

bool same_bytes(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("a view with any row stride resamples to the bytes of the packed image") {
  unsigned seed = 1;
  for (int C : {1, 3, 4, 5})
    for (auto [dw, dh] : {std::pair{41, 29}, std::pair{9, 7}, std::pair{23, 40}}) {
      const Image src = random_image(23, 17, C, seed++);
      for (auto [pad, offset] : {std::pair<std::size_t, std::size_t>{0, 0}, {7, 1}, {1, 3}}) {
        ImageView view;
        const std::vector<float> buf = padded_copy(src, pad, offset, view);
        for (const char* filter : {"catmull-rom", "bspline", "lanczos3"})
          for (Edge e : {Edge::clamp, Edge::mirror, Edge::wrap, Edge::black})
            for (bool interpolating : {false, true}) {
              if (interpolating && std::string(filter) == "lanczos3") continue;  // no 3-tap prefilter
              INFO(C << " channels to " << dw << "x" << dh << ", pad " << pad << ", offset " << offset << ", "
                     << filter << ", " << edge_name(e) << (interpolating ? ", interpolating" : ""));
              ResampleOptions opt;
              opt.edge = e;
              opt.interpolating = interpolating;
              opt.threads = 2;
              const Kernel k = parse_kernel(filter);
              const Image want = resample(src, dw, dh, k, opt);
              Image got(dw, dh, C);
              resample_into(view, got, k, opt);
              CHECK(same_bytes(got, want));
              for (float v : got.pixels) REQUIRE(std::isfinite(v));
            }
      }
    }
}

TEST_CASE("a view whose rows are shorter than its width or without data is refused") {
  const Image src = random_image(8, 6, 3, 3);
  Image out(4, 4, 3);
  ImageView v = src.view();
  v.row_stride = 8 * 3 - 1;
  CHECK_THROWS_WITH(resample_into(v, out, parse_kernel("tent")), "resample: the source's rows are shorter than its width");
  v = src.view();
  v.data = nullptr;
  CHECK_THROWS_AS(resample_into(v, out, parse_kernel("tent")), std::invalid_argument);
  v = src.view();
  v.height = 0;
  CHECK_THROWS_WITH(resample_into(v, out, parse_kernel("tent")), "resample: the source image is empty");
}
