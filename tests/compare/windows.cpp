// Data windows: the union two images are padded to is computed without overflow and bounded
// before anything is allocated (image.hpp).
#include <splinefig/compare/compare.hpp>
#include <splinefig/compare/image.hpp>

#include <catch2/catch.hpp>

#include <climits>
#include <stdexcept>

using namespace splinefig;
using namespace splinefig::compare;

TEST_CASE("the union of two windows holds both, whatever their order and sign") {
  CHECK(union_window({-3, 2, 4, 5}, {1, -6, 2, 2}) == Window{-3, -6, 6, 13});
  CHECK(union_window({1, -6, 2, 2}, {-3, 2, 4, 5}) == Window{-3, -6, 6, 13});
  CHECK(union_window({0, 0, 0, 0}, {7, 8, 1, 1}) == Window{7, 8, 1, 1});
  // Ending exactly at INT_MAX fits; one past does not (the sum overflowed an int).
  CHECK(union_window({INT_MAX - 23, 0, 23, 5}, {INT_MAX - 23, 0, 23, 5}) == Window{INT_MAX - 23, 0, 23, 5});
  CHECK_THROWS_AS(union_window({0, INT_MAX - 10, 5, 23}, {0, INT_MAX - 10, 5, 23}), std::length_error);
}

TEST_CASE("windows spanning more than 2^28 pixels are refused, not padded") {
  // 16384^2 = 2^28 exactly is allowed; one more row is not.
  CHECK(union_window({0, 0, 1, 1}, {16383, 16383, 1, 1}) == Window{0, 0, 16384, 16384});
  CHECK_THROWS_WITH(union_window({0, 0, 1, 1}, {16383, 16384, 1, 1}),
                    "the data windows [0, 0, 1 x 1] and [16383, 16384, 1 x 1] span 16384 x 16385 pixels, over the "
                    "limit of 2^28 pixels compared");
  CHECK_THROWS_AS(union_window({INT_MIN, INT_MIN, 1, 1}, {INT_MAX - 1, INT_MAX - 1, 1, 1}), std::length_error);
  Image a = Image::zeros(1, 1, 4), b = Image::zeros(1, 1, 4);
  b.x = b.y = 30000;
  CHECK_THROWS_AS(compare_images(a, b, {}), std::length_error);
}

TEST_CASE("a union of over 2^22 pixels is refused when it is more than 16 times the pixels the windows hold") {
  auto at = [](int w, int h, int x, int y) {
    Image im = Image::zeros(w, h, 1);
    im.x = x;
    im.y = y;
    return im;
  };
  // 2048^2 = 2^22: compared, whatever the windows hold (the union's 2^22 - 2 zeros match).
  const Comparison c = compare_images(at(1, 1, 0, 0), at(1, 1, 2047, 2047), {});
  CHECK(c.pa.width == 2048);
  CHECK(c.verdict == Verdict::match);
  // One more column: 2049 x 2048 pixels for the 2 they hold.
  CHECK_THROWS_WITH(compare_images(at(1, 1, 0, 0), at(1, 1, 2048, 2047), {}),
                    "the data windows [0, 0, 1 x 1] and [2048, 2047, 1 x 1] span 2049 x 2048 pixels, more than 16 "
                    "times the 2 pixels they hold (limit: 2^22 pixels, or 16 times the pixels held)");
  // A large image and a small one inside it or near it: the union is about what they hold.
  const Comparison d = compare_images(at(2049, 2048, 0, 0), at(4, 4, 2050, 2050), {});
  CHECK(d.pa.width == 2054);
  CHECK(d.pa.height == 2054);
}
