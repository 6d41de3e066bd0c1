// libFuzzer harness: basis and kernel specs ("cardinal:a=0.25", "beta:b1=2,b2=0", "lanczos3",
// ...), then the basis evaluated across its support. Any input must give a basis with finite
// values or one SpecError; anything else is a finding.
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  using namespace splinefig;
  try {
    const Kernel k = parse_kernel(text);
    const Support s = k.support();
    if (!std::isfinite(s.lo) || !std::isfinite(s.hi) || !(s.lo < s.hi)) {
      std::fprintf(stderr, "fuzz_basis: support [%g, %g] for \"%.*s\"\n", s.lo, s.hi, int(size), text.data());
      std::abort();
    }
    for (int i = 0; i <= 128; ++i) {
      const double x = s.lo + (s.hi - s.lo) * i / 128.0;
      const double v = k(x);
      if (!std::isfinite(v)) {
        std::fprintf(stderr, "fuzz_basis: k(%g) = %g for \"%.*s\"\n", x, v, int(size), text.data());
        std::abort();
      }
    }
    if (!std::isfinite(k.integral())) {
      std::fprintf(stderr, "fuzz_basis: integral not finite for \"%.*s\"\n", int(size), text.data());
      std::abort();
    }
  } catch (const SpecError&) {
  }
  return 0;
}
