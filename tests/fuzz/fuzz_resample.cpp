// libFuzzer harness: an image file read in linear light and resampled as `splinefig resample`
// does, up and down, with each edge mode. Any input must resample to finite values or end in
// one UnreadableImage line (no libpng error past the PNG check) or in one line refusing values
// that would overflow a float; anything else is a finding.
#include "fuzz_image_input.hpp"

#include <splinefig/image/io.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace splinefig;
  if (size > 1 << 16 || size < 1) return 0;
  const Edge edge = static_cast<Edge>(data[0] % 4);
  const std::string path = fuzz::image_file("in", data + 1, size - 1);
  try {
    const Image im = read_image(path, ReadMode::linear);
    if (std::uint64_t(im.width) * std::uint64_t(im.height) <= (1u << 20)) {
      static const Kernel k = parse_kernel("catmull-rom");
      ResampleOptions o;
      o.edge = edge;
      o.threads = 1;
      const int w = im.width > 1 ? im.width / 2 : 3, h = im.height * 2 < 4096 ? im.height * 2 : 1;
      const Image out = resample(im, w, h, k, o);
      bool finite_in = true;
      for (float v : im.pixels) finite_in = finite_in && std::isfinite(v);
      for (float v : out.pixels)
        if (finite_in && !std::isfinite(v)) {
          std::fprintf(stderr, "fuzz_resample: a non-finite output value from finite input\n");
          std::abort();
        }
    }
  } catch (const std::invalid_argument& e) {  // values that would overflow a float: resample's refusal
    if (std::string(e.what()).find('\n') != std::string::npos) {
      std::fprintf(stderr, "fuzz_resample: a message of more than one line: %s\n", e.what());
      std::abort();
    }
  } catch (const UnreadableImage& e) {
    if (const char* what = fuzz::bad_message(e.what())) {
      std::fprintf(stderr, "fuzz_resample: %s: %s\n", what, e.what());
      std::abort();
    }
  }
  std::remove(path.c_str());
  return 0;
}
