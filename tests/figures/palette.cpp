// The series palettes against white: every colour a family of curves takes from `viridis` or
// `grey` has a contrast ratio of at least 3:1 with the white background (WCAG 2's contrast
// ratio (L1 + 0.05) / (L2 + 0.05) of relative luminances, the level it asks of graphics),
// computed here from the "#rrggbb" the index reports, with WCAG's own formula.
#include <catch2/catch.hpp>

#include <splinefig/figures/palette.hpp>

#include <cmath>
#include <string>

using namespace splinefig::figures;

namespace {

double wcag_channel(int v8) {
  const double c = v8 / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double contrast_on_white(const std::string& hex) {
  const int r = std::stoi(hex.substr(1, 2), nullptr, 16), g = std::stoi(hex.substr(3, 2), nullptr, 16),
            b = std::stoi(hex.substr(5, 2), nullptr, 16);
  const double L = 0.2126 * wcag_channel(r) + 0.7152 * wcag_channel(g) + 0.0722 * wcag_channel(b);
  return 1.05 / (L + 0.05);
}

}  // namespace

TEST_CASE("palette colours for lines have at least 3:1 contrast on white") {
  CHECK(contrast_on_white("#ffffff") == Approx(1));
  CHECK(contrast_on_white("#000000") == Approx(21));
  for (const char* name : {"viridis", "grey"})
    for (int n = 1; n <= 12; ++n)
      for (int i = 0; i < n; ++i) {
        const std::string hex = to_hex(palette_color(name, i, n));
        INFO(name << " colour " << i << " of " << n << ": " << hex);
        CHECK(contrast_on_white(hex) >= 3.0);
      }
}

TEST_CASE("viridis families run from its dark purple end in order") {
  CHECK(to_hex(palette_color("viridis", 0, 5)) == "#440154");  // the colormap's first sample
  // Darker to lighter: relative luminance rises along the family.
  for (int i = 0; i + 1 < 5; ++i)
    CHECK(contrast_on_white(to_hex(palette_color("viridis", i, 5))) > contrast_on_white(to_hex(palette_color("viridis", i + 1, 5))));
}
