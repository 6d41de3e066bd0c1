// The compositor's blend space: Porter-Duff over in linear light (the default) or on
// sRGB-encoded values (as AGG and browsers blend). Expected values come from the IEC 61966-2-1
// curve written out here in double precision, not from the library's tables.
#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include <unistd.h>

namespace sr = splinefig::render;
namespace fs = std::filesystem;
using splinefig::Encoding;

namespace {
double encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

std::vector<sr::Vec2> box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

sr::Scene half_covered(sr::BlendSpace space) {
  // White over opaque black, covering the left half of pixel (0, 0) and all of pixel (1, 0).
  sr::Scene s(2, 1, {0, 0, 0, 1});
  s.set_blend_space(space);
  s.fill_polygon({box(0, 0, 0.5, 1)}, sr::FillRule::NonZero, {1, 1, 1, 1});
  s.fill_polygon({box(1, 0, 2, 1)}, sr::FillRule::NonZero, {1, 1, 1, 1});
  return s;
}
}  // namespace

TEST_CASE("half coverage is half the light in linear blending and half the code in sRGB blending") {
  const sr::Scene lin = half_covered(sr::BlendSpace::linear);
  CHECK(sr::Scene(1, 1).blend_space() == sr::BlendSpace::linear);
  const auto a = sr::rasterize(lin, 1);
  CHECK(a.encoding == Encoding::linear);
  CHECK(a.pixel(0, 0)[0] == Approx(0.5).margin(1e-6));
  CHECK(a.pixel(0, 0)[3] == 1.0f);
  CHECK(a.pixel(1, 0)[0] == 1.0f);

  const auto b = sr::rasterize(half_covered(sr::BlendSpace::srgb), 1);
  CHECK(b.encoding == Encoding::srgb);
  CHECK(b.pixel(0, 0)[0] == Approx(0.5).margin(1e-6));  // encoded value: 0.5 of code 255
  CHECK(b.pixel(1, 0)[0] == 1.0f);
  // Decoded, the sRGB blend is darker than the linear one: srgb^-1(0.5) = 0.214.
  const auto b_lin = splinefig::to_linear(b);
  CHECK(b_lin.pixel(0, 0)[0] == Approx(std::pow((0.5 + 0.055) / 1.055, 2.4)).margin(1e-6));
}

TEST_CASE("a translucent colour over a background blends the encoded values in sRGB space") {
  const sr::Color bg{1.0f, 0.5f, 0.1f, 1.0f}, c{0.2f, 0.6f, 0.9f, 0.4f};
  for (auto space : {sr::BlendSpace::linear, sr::BlendSpace::srgb}) {
    sr::Scene s(3, 2, bg);
    s.set_blend_space(space);
    s.fill_polygon({box(0, 0, 3, 2)}, sr::FillRule::NonZero, c);
    const auto im = sr::rasterize(s, 1);
    const float bgc[3] = {bg.r, bg.g, bg.b}, cc[3] = {c.r, c.g, c.b};
    for (int ch = 0; ch < 3; ++ch) {
      INFO("channel " << ch << (space == sr::BlendSpace::srgb ? " sRGB" : " linear"));
      const double want = space == sr::BlendSpace::srgb ? encode(cc[ch]) * c.a + encode(bgc[ch]) * (1 - c.a)
                                                        : cc[ch] * double(c.a) + bgc[ch] * (1 - double(c.a));
      CHECK(im.pixel(2, 1)[ch] == Approx(want).margin(2e-6));
    }
    CHECK(im.pixel(2, 1)[3] == 1.0f);
  }
}

TEST_CASE("a raster item is composited in the blend space, from its linear premultiplied pixels") {
  auto tile = std::make_shared<splinefig::Image>(1, 1, 4);
  const float src[4] = {0.25f, 0.1f, 0.0f, 0.5f};  // straight linear (0.5, 0.2, 0), alpha 0.5
  std::memcpy(tile->pixel(0, 0), src, sizeof src);
  sr::Scene s(2, 2, {1, 1, 1, 1});
  s.set_blend_space(sr::BlendSpace::srgb);
  s.image(tile, {0, 0}, {2, 2}, sr::Scene::Sampling::Nearest);
  const auto im = sr::rasterize(s, 1);
  REQUIRE(im.encoding == Encoding::srgb);
  const double straight[3] = {0.5, 0.2, 0.0};
  for (int ch = 0; ch < 3; ++ch) CHECK(im.pixel(1, 1)[ch] == Approx(encode(straight[ch]) * 0.5 + 1.0 * 0.5).margin(2e-6));
  CHECK(im.pixel(1, 1)[3] == 1.0f);
}

TEST_CASE("a raster item of sRGB-encoded pixels is composited without a trip through linear light") {
  // One picture placed pixel for pixel at a whole-pixel offset: premultiplied encoded values
  // (0.25, 0.1, 0, alpha 0.5), that is straight encoded (0.5, 0.2, 0).
  auto tile = std::make_shared<splinefig::Image>(2, 1, 4, Encoding::srgb);
  const float src[8] = {0.25f, 0.1f, 0.0f, 0.5f, 0, 0, 0, 0};  // the second pixel is empty
  std::memcpy(tile->pixel(0, 0), src, sizeof src);
  auto decode = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
  const double straight[3] = {0.5, 0.2, 0.0};
  for (const auto space : {sr::BlendSpace::srgb, sr::BlendSpace::linear}) {
    sr::Scene s(4, 3, {1, 1, 1, 1});
    s.set_blend_space(space);
    s.image(tile, {1, 1}, {3, 2}, sr::Scene::Sampling::Nearest);
    const auto im = sr::rasterize(s, 1);
    for (int ch = 0; ch < 3; ++ch) {
      // Over white: in sRGB the encoded values blend; in linear light the decoded ones.
      const double want = space == sr::BlendSpace::srgb ? straight[ch] * 0.5 + 0.5 : decode(straight[ch]) * 0.5 + 0.5;
      CHECK(im.pixel(1, 1)[ch] == Approx(want).margin(2e-6));
      CHECK(im.pixel(2, 1)[ch] == 1.0f);  // the empty pixel leaves white
      CHECK(im.pixel(0, 1)[ch] == 1.0f);  // outside the rectangle
      CHECK(im.pixel(1, 0)[ch] == 1.0f);
    }
  }
}

TEST_CASE("sRGB blending gives the same bytes for every thread count") {
  sr::Scene s(97, 61, {0.9f, 0.95f, 1.0f, 1.0f});
  s.set_blend_space(sr::BlendSpace::srgb);
  sr::StrokeStyle st;
  st.width = 2.5;
  for (int k = 0; k < 40; ++k) {
    std::vector<sr::Vec2> pts;
    for (int i = 0; i < 12; ++i) pts.push_back({3 + 7.7 * i + 0.37 * k, 5 + 50 * std::abs(std::sin(0.31 * i + 0.7 * k))});
    s.stroke_polyline(std::move(pts), false, st, {float(k % 3) / 2, 0.3f, float(k % 5) / 4, 0.55f});
  }
  const auto one = sr::rasterize(s, 1);
  for (int t : {2, 3, 8}) {
    const auto many = sr::rasterize(s, t);
    INFO(t << " threads");
    CHECK(std::memcmp(one.pixels.data(), many.pixels.data(), one.pixels.size() * sizeof(float)) == 0);
  }
}

TEST_CASE("a PNG of an sRGB-blended canvas holds its encoded values, read back by OpenImageIO") {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-blend-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  sr::Scene s(16, 4, {0, 0, 0, 1});
  s.set_blend_space(sr::BlendSpace::srgb);
  // A ramp of coverages: pixel x covered over [0, x / 16] of its width.
  for (int x = 1; x < 16; ++x) s.fill_polygon({box(x, 0, x + x / 16.0, 4)}, sr::FillRule::NonZero, {1, 1, 1, 1});
  const auto im = sr::rasterize(s, 1);
  const std::string path = (dir / "ramp.png").string();
  splinefig::write_image(path, im);
  auto in = OIIO::ImageInput::open(path);
  REQUIRE(in);
  std::vector<unsigned char> px(16 * 4 * 4);
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data()));
  for (int x = 0; x < 16; ++x) {
    INFO("x = " << x);
    CHECK(int(px[std::size_t(x) * 4]) == int(std::lround(255 * (x / 16.0))));
  }
  fs::remove_all(dir);
}
