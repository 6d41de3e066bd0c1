// libFuzzer harness: two image files compared as `splinefig diff` does (as stored and in
// linear light, with SSIM and FLIP). Input: a 2-byte big-endian length, the first file, the
// second file (images whose windows span over 2^18 pixels are only read). Any input must
// compare or end in one UnreadableImage line (and no libpng error past the PNG check) or one
// length_error line (data windows too far apart, as diff refuses them); anything else is a
// finding.
#include "fuzz_image_input.hpp"

#include <splinefig/compare/compare.hpp>
#include <splinefig/image/io.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace splinefig;
  std::size_t first = 0;
  if (size > 1 << 16 || !fuzz::split_pair(data, size, first)) return 0;
  const std::string a = fuzz::image_file("a", data + 2, first);
  const std::string b = fuzz::image_file("b", data + 2 + first, size - 2 - first);
  for (const ReadMode mode : {ReadMode::as_stored, ReadMode::linear}) {
    try {
      const Image ia = read_image(a, mode), ib = read_image(b, mode);
      // The pixels compared: the union of the two data windows. Past 2^18 of them the
      // comparison is only longer, not different (linear in the pixels: 2800 x 2800 greys from
      // 15 KB of PNG took 35 s under the sanitizers, 0.9 s in a release build, as idiff takes
      // 0.7 s; a 4 x 4 PNG at oFFs x = 131072 beside a 6 x 4 EXR, 45 s with SSIM and FLIP over
      // their 131076 x 4 union, 0.6 s in a release build, and still 8 s without them, about
      // 8 us a pixel in each read mode): such images are only read, as fuzz_resample reads
      // large ones.
      const std::int64_t x0 = std::min<std::int64_t>(ia.x, ib.x), y0 = std::min<std::int64_t>(ia.y, ib.y);
      const std::int64_t x1 = std::max<std::int64_t>(std::int64_t(ia.x) + ia.width, std::int64_t(ib.x) + ib.width);
      const std::int64_t y1 = std::max<std::int64_t>(std::int64_t(ia.y) + ia.height, std::int64_t(ib.y) + ib.height);
      const std::int64_t compared = (x1 - x0) * (y1 - y0);
      if (compared > (std::int64_t(1) << 18)) continue;
      compare::Options o;
      o.threads = 1;
      o.perceptual = compared <= 4096;
      o.shift = 1;
      const compare::Comparison c = compare::compare_images(ia, ib, o);
      (void)compare::text_report(c, o, a, b);
      (void)compare::json_report(c, o, a, b);
    } catch (const std::length_error& e) {  // windows too far apart to compare: diff's one-line refusal
      if (const char* what = fuzz::bad_message(e.what())) {
        std::fprintf(stderr, "fuzz_compare: %s: %s\n", what, e.what());
        std::abort();
      }
    } catch (const UnreadableImage& e) {
      if (const char* what = fuzz::bad_message(e.what())) {
        std::fprintf(stderr, "fuzz_compare: %s: %s\n", what, e.what());
        std::abort();
      }
    }
  }
  std::remove(a.c_str());
  std::remove(b.c_str());
  return 0;
}
