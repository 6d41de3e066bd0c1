// Hex colours (sRGB, decoded with the curve of image/srgb.hpp).
#include <splinefig/image/srgb.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <cmath>

namespace splinefig::render {

std::optional<Color> parse_hex_color(std::string_view hex) {
  if (hex.size() != 7 && hex.size() != 9) return std::nullopt;
  if (hex[0] != '#') return std::nullopt;
  auto nibble = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  float ch[4] = {0, 0, 0, 1};
  for (std::size_t i = 1, k = 0; i < hex.size(); i += 2, ++k) {
    int hi = nibble(hex[i]), lo = nibble(hex[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    ch[k] = static_cast<float>(hi * 16 + lo) / 255.0f;
  }
  // Alpha is not a light intensity: it stays linear as written.
  return Color{srgb_to_linear(ch[0]), srgb_to_linear(ch[1]), srgb_to_linear(ch[2]), ch[3]};
}

}  // namespace splinefig::render
