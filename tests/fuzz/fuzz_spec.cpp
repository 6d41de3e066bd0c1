// libFuzzer harness: the figure spec loader, layout and render on a small canvas.
// Any input must end in a figure or in one SpecFileError line "fuzz.toml:LINE: KEY: ..." (or,
// for an [[image]] file, an UnreadableImage line); anything else (another exception, a
// sanitizer report, a hang, running out of memory) is a finding.
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

[[noreturn]] void finding(const char* kind, const char* what) {
  std::fprintf(stderr, "fuzz_spec: %s: %s\n", kind, what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1 << 16) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  using namespace splinefig::figures;
  try {
    FigureSpec spec = parse_spec(text, "fuzz.toml", "/nonexistent");
    // A small canvas keeps each run short; the layout adapts to it.
    spec.canvas.width = std::min(spec.canvas.width, 96);
    spec.canvas.height = std::min(spec.canvas.height, 64);
    RenderOptions options;
    options.threads = 1;
    (void)render_figure(spec, options);
  } catch (const SpecFileError& e) {
    const std::string m = e.what();
    if (m.rfind("fuzz.toml", 0) != 0 || m.find('\n') != std::string::npos) finding("badly formed spec error", e.what());
  } catch (const splinefig::UnreadableImage&) {
  } catch (const std::exception& e) {
    finding("unexpected exception", e.what());
  }
  return 0;
}
