// libFuzzer harness: two image files compared as `splinefig diff` does (as stored and in
// linear light, with SSIM and FLIP). Input: a 2-byte big-endian length, the first file, the
// second file (images over 2^20 pixels are only read). Any input must compare or end in one
// UnreadableImage line (and no libpng error past the PNG check) or one length_error line (data
// windows too far apart, as diff refuses them); anything else is a finding.
#include "fuzz_image_input.hpp"

#include <splinefig/compare/compare.hpp>
#include <splinefig/image/io.hpp>

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
      // Past 2^20 pixels the comparison is only longer, not different (linear in the pixels:
      // 2800 x 2800 greys from 15 KB of PNG took 35 s under the sanitizers, 0.9 s in a release
      // build, as idiff takes 0.7 s): large images are read, as fuzz_resample reads them.
      if (std::uint64_t(ia.width) * std::uint64_t(ia.height) > (1u << 20) ||
          std::uint64_t(ib.width) * std::uint64_t(ib.height) > (1u << 20))
        continue;
      compare::Options o;
      o.threads = 1;
      o.perceptual = ia.width * ia.height <= 4096;
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
