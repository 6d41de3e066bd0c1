// docs/limits.md states the limits the code enforces: each row of its table that has a public
// constant says that constant's value (the refusal messages are checked by the other cases).
#include <splinefig/base/limits.hpp>
#include <splinefig/figures/axes.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/resample/resample.hpp>

#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace {

// The table's rows: first cell -> second cell.
std::map<std::string, std::string> limits_table() {
  std::ifstream f(std::string(SPLINEFIG_SOURCE_DIR) + "/docs/limits.md");
  REQUIRE(f);
  std::map<std::string, std::string> rows;
  for (std::string line; std::getline(f, line);) {
    if (line.rfind("| ", 0) != 0) continue;
    const auto a = line.find(" | ", 2);
    if (a == std::string::npos) continue;
    const auto b = line.find(" | ", a + 3);
    rows[line.substr(2, a - 2)] = line.substr(a + 3, b == std::string::npos ? std::string::npos : b - a - 3);
  }
  return rows;
}

std::string power_of_two(long long v) {
  int k = 0;
  while ((1LL << k) < v) ++k;
  return (1LL << k) == v ? "2^" + std::to_string(k) : std::to_string(v);
}

}  // namespace

TEST_CASE("docs/limits.md states the values of the limits the code enforces") {
  namespace f = splinefig;  // base/limits.hpp
  const auto rows = limits_table();
  const std::map<std::string, std::string> expected{
      {"canvas side, at 1x and after `--scale`", std::to_string(f::kMaxCanvasSide) + " px"},
      {"canvas pixels, at 1x and after `--scale`", power_of_two(f::kMaxCanvasPixels)},
      {"spec file size", std::to_string(f::kMaxSpecBytes >> 20) + " MiB"},
      {"parts of a dotted key or table header (`a.b.c`), checked by a scan before the TOML parser runs", std::to_string(f::kMaxKeyParts)},
      {"arrays and inline tables nested in each other (`[[[`, `{a = {`), checked by the same scan", std::to_string(f::kMaxValueNesting)},
      {"text and title font sizes, at 1x and after `--scale`", std::to_string(int(f::kMaxFontSize)) + " px"},
      {"text of one item (a title, a label, a `[[text]]`, `Scene::text`, `measure_text`), in UTF-8 bytes",
       power_of_two((long long)(f::kMaxTextBytes))},
      {"ticks per axis (explicit, or from `*_tick_step`)", std::to_string(f::kMaxTicks)},
      {"`x_marks`, `y_marks`, curve `marks`", std::to_string(f::kMaxMarks)},
      {"`--threads` (every command) and the resampler's library thread count", std::to_string(splinefig::kMaxThreads)},
      {"image read: either side declared in the header", std::to_string(splinefig::kMaxImageSide) + " px"},
      {"image read (`diff`, `resample`, `[[image]]` files): pixels declared in the header", power_of_two((long long)(f::kMaxImagePixels))},
      {"image read: values (pixels x channels)", power_of_two((long long)(f::kMaxImageValues))},
      {"image read: data window origin (EXR data window, PNG `oFFs`)", power_of_two(f::kMaxImageOrigin) + " either way"},
      {"dash work of one stroke: dashes near the canvas x (1 + width / period)^2", power_of_two((long long)(f::kMaxDashWork))},
      {"outline vertices of one item, and of all a scene's items together: stroke joins and caps, dashes, circles, markers, "
       "flattened paths, glyphs, clip paths, estimated from above before any is built",
       power_of_two((long long)(f::kMaxOutlineVertices))},
      {"the exact union's work for one drawn item: crossings of its outline with itself on the canvas",
       power_of_two((long long)(f::kMaxSweepCrossings)) + " (`Scene::set_max_crossings` changes it)"},
      {"`[[axes.bezier]]` control points", std::to_string(f::kMaxBezierPoints) + " (degree " + std::to_string(f::kMaxBezierPoints - 1) + ")"},
      {"`[[axes.inbetween]]` filmstrip frames (`steps` x keyframe intervals + 1)", std::to_string(f::kMaxFilmstripFrames)},
      {"`[animation]` frames", std::to_string(f::kMaxAnimationFrames)},
      {"`[animation]` pixels over all frames (frames x width x height), at 1x and after `--scale`", power_of_two((long long)(f::kMaxAnimationPixels))},
      {"`[animation]` side", std::to_string(f::kMaxAnimationSide) + " px"},
      {"`[animation]` `delay`, `key_delay`", std::to_string(f::kMinFrameDelayMs) + " to " + std::to_string(f::kMaxFrameDelayMs) + " ms"},
  };
  for (const auto& [quantity, limit] : expected) {
    INFO(quantity);
    REQUIRE(rows.count(quantity) == 1);
    CHECK(rows.at(quantity) == limit);
  }
  // The span row names both minima.
  REQUIRE(rows.count("axis range span") == 1);
  std::ostringstream span;
  span << "finite, >= " << f::kMinAxisSpan << " and >= " << f::kMinRelativeAxisSpan << " of the larger end";
  CHECK(rows.at("axis range span") == span.str());
}
