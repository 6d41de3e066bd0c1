// A user's Catch2 v2 image test through splinefig::testing (it brings splinefig::compare and
// Catch2): a 4 x 4 transparent image with pixel (1,1) covered, checked against a reference
// written once from a hand-made image of the same pixels, and an image with pixel (2,2)
// covered instead, which must not match.
#define CATCH_CONFIG_MAIN
#include <splinefig/image/io.hpp>
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/testing.hpp>

#include <filesystem>

namespace sf = splinefig;
using sf::testing::MatchesReference;

namespace {
sf::Image square_at(int x, int y) {
  sf::render::Scene scene(4, 4, {0, 0, 0, 0});
  scene.fill_polygon({{{double(x), double(y)}, {x + 1.0, double(y)}, {x + 1.0, y + 1.0}, {double(x), y + 1.0}}},
                     sf::render::FillRule::NonZero, {1, 1, 1, 1});
  return sf::render::rasterize(scene, 1);
}
}  // namespace

TEST_CASE("a rendered square matches its reference, a moved one does not") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "splinefig-consumer";
  std::filesystem::create_directories(dir);
  const std::string ref = (dir / "square.png").string();
  sf::Image expected = sf::Image::zeros(4, 4, 4);  // linear premultiplied RGBA, pixel (1,1) opaque white
  for (int c = 0; c < 4; ++c) expected.at(1, 1, c) = 1.0f;
  sf::write_image(ref, expected);

  CHECK_THAT(square_at(1, 1), MatchesReference(ref));
  CHECK_THAT(square_at(2, 2), !MatchesReference(ref));
}
