// Fill rules, disks, markers, dashes, colours, text, and image files.
#include "coverage_helpers.hpp"
#include <oracle/union_coverage.hpp>

#include <splinefig/image/io.hpp>

#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <memory>
#include <fstream>

namespace sr = splinefig::render;
namespace fs = std::filesystem;

namespace {
double total(const std::vector<double>& c) {
  double t = 0;
  for (double v : c) t += v;
  return t;
}
oracle::Poly rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
std::vector<sr::Vec2> to_vec(const oracle::Poly& p) {
  std::vector<sr::Vec2> v;
  for (auto q : p) v.push_back({q.x, q.y});
  return v;
}
fs::path temp_dir() {
  fs::path d = fs::temp_directory_path() / ("splinefig-renderer-test-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST_CASE("nonzero fills the union of overlapping contours, even-odd their symmetric difference") {
  auto A = rect(3.3, 4.1, 20.6, 17.7), B = rect(11.2, 9.4, 27.9, 26.2), I = rect(11.2, 9.4, 20.6, 17.7);
  auto uni = oracle::union_coverage({A, B}, 32, 32);
  auto a = oracle::union_coverage({A}, 32, 32), b = oracle::union_coverage({B}, 32, 32), in = oracle::union_coverage({I}, 32, 32);
  auto nonzero = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({to_vec(A), to_vec(B)}, sr::FillRule::NonZero, {1, 1, 1, 1}); });
  auto evenodd = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({to_vec(A), to_vec(B)}, sr::FillRule::EvenOdd, {1, 1, 1, 1}); });
  CHECK(testutil::compare(nonzero, uni).max <= 1e-6);
  std::vector<double> xor_(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) xor_[i] = a[i] + b[i] - 2 * in[i];
  CHECK(testutil::compare(evenodd, xor_).max <= 1e-6);
  // B reversed: nonzero now also leaves the overlap empty (winding +1 - 1 = 0)
  auto Br = to_vec(B);
  std::reverse(Br.begin(), Br.end());
  auto opposite = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({to_vec(A), Br}, sr::FillRule::NonZero, {1, 1, 1, 1}); });
  CHECK(testutil::compare(opposite, xor_).max <= 1e-6);
}

TEST_CASE("a pentagram: nonzero fills the centre, even-odd leaves it empty (exact areas)") {
  std::vector<sr::Vec2> star;
  const double R = 14, pi = 3.141592653589793;
  for (int k = 0; k < 5; ++k) {
    double a = -pi / 2 + k * 4 * pi / 5;
    star.push_back({16 + R * std::cos(a), 16 + R * std::sin(a)});
  }
  // inner pentagon radius r = R cos(72)/cos(36); areas from the regular geometry
  const double r = R * std::cos(2 * pi / 5) / std::cos(pi / 5);
  const double pentagon = 2.5 * r * r * std::sin(2 * pi / 5);
  const double star_area = 5 * R * r * std::sin(pi / 5);  // 10 triangles centre-tip-notch
  auto nz = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({star}, sr::FillRule::NonZero, {1, 1, 1, 1}); });
  auto eo = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({star}, sr::FillRule::EvenOdd, {1, 1, 1, 1}); });
  CHECK(total(nz) == Approx(star_area).epsilon(1e-7));  // float32 pixels
  CHECK(total(eo) == Approx(star_area - pentagon).epsilon(1e-7));
}

TEST_CASE("disks and markers have their exact areas") {
  const double pi = 3.141592653589793;
  auto disk = testutil::rendered_coverage(40, 40, [&](sr::Scene& s) { s.fill_circle({19.3, 20.8}, 13.7, {1, 1, 1, 1}); });
  CHECK(total(disk) == Approx(pi * 13.7 * 13.7).epsilon(2e-5));
  struct M { sr::Marker m; double area; };
  const double sz = 11.5;
  for (M m : {M{sr::Marker::Circle, pi * sz * sz / 4}, M{sr::Marker::Square, sz * sz}, M{sr::Marker::Diamond, sz * sz / 2},
              M{sr::Marker::Plus, 7 * sz * sz / 16},
              M{sr::Marker::Cross, (std::sqrt(0.5) - 1.0 / 16) * sz * sz}}) {  // arms reach the corners
    auto c = testutil::rendered_coverage(24, 24, [&](sr::Scene& s) { s.marker(m.m, {12.2, 11.7}, sz, {1, 1, 1, 1}); });
    INFO("marker " << static_cast<int>(m.m));
    CHECK(total(c) == Approx(m.area).epsilon(1e-4));
  }
}

TEST_CASE("dashes: on-lengths of the pattern, offset applied, continuing across a joint") {
  // Straight line of length 40 from x = 2, pattern {6, 3}, offset 2: dashes [0,4], [7,13],
  // [16,22], [25,31], [34,40] -> on length 28, width 2, butt caps.
  sr::StrokeStyle st;
  st.width = 2;
  st.dashes = {6, 3};
  st.dash_offset = 2;
  auto c = testutil::rendered_coverage(48, 12, [&](sr::Scene& s) { s.stroke_polyline(std::vector<sr::Vec2>{{2, 6}, {42, 6}}, false, st, {1, 1, 1, 1}); });
  CHECK(total(c) == Approx(28 * 2).epsilon(1e-12));
  // An L path (10 right, 10 down), pattern {8, 4}, offset -4: the dashes are [4, 12], which
  // spans the joint (two rectangles and the miter), and [16, 20]; their pieces from the oracle.
  st.dashes = {8, 4};
  st.dash_offset = -4;
  st.width = 3;
  auto got = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) {
    s.stroke_polyline(std::vector<sr::Vec2>{{5.5, 5.5}, {15.5, 5.5}, {15.5, 15.5}}, false, st, {1, 1, 1, 1});
  });
  auto pieces = oracle::stroke_pieces({{9.5, 5.5}, {15.5, 5.5}, {15.5, 7.5}}, false, 3, oracle::Join::Miter, 4, oracle::Cap::Butt);
  auto second = oracle::stroke_pieces({{15.5, 11.5}, {15.5, 15.5}}, false, 3, oracle::Join::Miter, 4, oracle::Cap::Butt);
  pieces.insert(pieces.end(), second.begin(), second.end());
  auto want = oracle::union_coverage(pieces, 32, 32);
  CHECK(testutil::compare(got, want).max <= 1e-6);
}

TEST_CASE("hex colours are sRGB, decoded with the exact sRGB curve") {
  auto c = sr::parse_hex_color("#ff8000");
  REQUIRE(c);
  CHECK(c->r == 1.0f);
  CHECK(c->g == Approx(0.21586050).epsilon(1e-6));  // ((128/255 + 0.055)/1.055)^2.4
  CHECK(c->b == 0.0f);
  CHECK(c->a == 1.0f);
  auto d = sr::parse_hex_color("#0000007F");
  REQUIRE(d);
  CHECK(d->a == Approx(127 / 255.0));
  for (const char* bad : {"ff0000", "#ff00", "#gg0000", "#ff00001", "", "#ff0000 "}) CHECK_FALSE(sr::parse_hex_color(bad));
}

TEST_CASE("PNG is 8-bit sRGB with straight alpha, EXR float linear premultiplied, both with metadata") {
  auto dir = temp_dir();
  splinefig::Image img(2, 1, 4);
  const float values[8] = {0.5f, 0.5f, 0.5f, 1.0f, 0.25f, 0.0f, 0.0f, 0.5f};  // premultiplied
  std::copy(values, values + 8, img.pixels.begin());
  splinefig::write_image((dir / "a.png").string(), img, {.description = "test spec"});
  splinefig::write_image((dir / "a.exr").string(), img);
  OIIO::ImageSpec raw;
  raw.attribute("oiio:UnassociatedAlpha", 1);  // read the stored bytes, do not premultiply
  auto in = OIIO::ImageInput::open((dir / "a.png").string(), &raw);
  REQUIRE(in);
  CHECK(in->spec().format == OIIO::TypeDesc::UINT8);
  CHECK(in->spec().get_string_attribute("Software").find("splinefig") != std::string::npos);
  CHECK(in->spec().get_string_attribute("ImageDescription") == "test spec");
  unsigned char px[8];
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px));
  in->close();
  // linear 0.5 -> sRGB 0.7354 -> 188; straight red 0.25/0.5 = 0.5 -> 188, alpha 128
  CHECK(int(px[0]) == 188);
  CHECK(int(px[3]) == 255);
  CHECK(int(px[4]) == 188);
  CHECK(int(px[5]) == 0);
  CHECK(int(px[7]) == 128);
  auto ex = OIIO::ImageInput::open((dir / "a.exr").string());
  REQUIRE(ex);
  float f[8];
  REQUIRE(ex->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, f));
  CHECK(ex->spec().format == OIIO::TypeDesc::FLOAT);
  ex->close();
  for (int i = 0; i < 8; ++i) CHECK(f[i] == values[i]);
  // no temporary files are left beside the targets
  int files = 0;
  for (auto& e : fs::directory_iterator(dir)) { (void)e; ++files; }
  CHECK(files == 2);
  fs::remove_all(dir);
}

TEST_CASE("a failed write names the path and leaves no file") {
  auto dir = temp_dir();
  splinefig::Image img = splinefig::Image::zeros(1, 1, 4);
  img.pixels[3] = 1;
  auto target = dir / "missing" / "x.png";
  REQUIRE_THROWS_WITH(splinefig::write_image(target.string(), img), Catch::Contains(target.string()));
  REQUIRE_THROWS_WITH(splinefig::write_image((dir / "x.jpg").string(), img), Catch::Contains("x.jpg"));
  // an existing file is replaced only by a complete one: writing over it keeps it readable
  auto good = dir / "y.png";
  splinefig::write_image(good.string(), img);
  splinefig::Image bad;  // no pixels: rejected before anything is written
  REQUIRE_THROWS(splinefig::write_image(good.string(), bad));
  REQUIRE(OIIO::ImageInput::open(good.string()));
  int files = 0;
  for (auto& e : fs::directory_iterator(dir)) { (void)e; ++files; }
  CHECK(files == 1);
  fs::remove_all(dir);
}

TEST_CASE("text: measure_text grows with the string, render_text draws at the anchor") {
  sr::TextStyle st;
  st.size = 16;
  auto a = sr::measure_text("M", st), b = sr::measure_text("MMMM", st);
  CHECK(a.width > 5);
  CHECK(b.width > 3 * a.width);
  CHECK(a.ascent > 8);
  CHECK(a.ascent < 16);
  CHECK(sr::measure_text("", st).width == 0);
  auto blank = testutil::rendered_coverage(8, 8, [&](sr::Scene& s) { s.text("", {4, 4}, st); s.text("  ", {4, 4}, st); });
  for (double c : blank) CHECK(c == 0);
  for (auto [h, v] : {std::pair{sr::HAlign::Left, sr::VAlign::Baseline}, {sr::HAlign::Center, sr::VAlign::Middle},
                      {sr::HAlign::Right, sr::VAlign::Top}}) {
    st.halign = h;
    st.valign = v;
    st.color = {1, 1, 1, 1};
    auto c = testutil::rendered_coverage(80, 40, [&](sr::Scene& s) { s.text("Hm", {40, 20}, st); });
    // ink box relative to the anchor
    int x0 = 80, x1 = -1, y0 = 40, y1 = -1;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 80; ++x)
        if (c[y * 80 + x] > 0.5) { x0 = std::min(x0, x); x1 = std::max(x1, x); y0 = std::min(y0, y); y1 = std::max(y1, y); }
    REQUIRE(x1 >= 0);
    INFO("align " << static_cast<int>(h) << "," << static_cast<int>(v) << " ink " << x0 << ".." << x1 << " x " << y0 << ".." << y1);
    if (h == sr::HAlign::Left) { CHECK(std::abs(x0 - 40) <= 2); CHECK(std::abs(y1 - 19) <= 1); }
    if (h == sr::HAlign::Center) { CHECK(std::abs((x0 + x1) / 2 - 40) <= 2); CHECK(std::abs((y0 + y1) / 2 - 20) <= 2); }
    if (h == sr::HAlign::Right) { CHECK(std::abs(x1 - 39) <= 2); CHECK(std::abs(y0 - 20) <= 1); }
  }
}

namespace {

std::shared_ptr<const splinefig::Image> two_by_two() {
  auto im = std::make_shared<splinefig::Image>(2, 2, 4);
  // Premultiplied: red, green at half alpha, blue, transparent.
  const float v[16] = {1, 0, 0, 1, 0, 0.5f, 0, 0.5f, 0, 0, 1, 1, 0, 0, 0, 0};
  std::copy(v, v + 16, im->pixels.begin());
  return im;
}

}  // namespace

TEST_CASE("image items: nearest sampling at pixel centres, composited over what is below") {
  sr::Scene scene(20, 20, {1, 1, 1, 1});
  scene.image(two_by_two(), {10, 10}, {14, 14}, sr::Scene::Sampling::Nearest);
  const splinefig::Image img = sr::rasterize(scene, 1);
  auto px = [&](int x, int y) { return std::array<float, 4>{img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2), img.at(x, y, 3)}; };
  CHECK(px(10, 10) == std::array<float, 4>{1, 0, 0, 1});
  CHECK(px(11, 11) == std::array<float, 4>{1, 0, 0, 1});
  CHECK(px(12, 10) == std::array<float, 4>{0.5f, 1.0f, 0.5f, 1});  // green 0.5 + white * 0.5
  CHECK(px(10, 13) == std::array<float, 4>{0, 0, 1, 1});
  CHECK(px(13, 13) == std::array<float, 4>{1, 1, 1, 1});  // transparent: the background
  CHECK(px(9, 10) == std::array<float, 4>{1, 1, 1, 1});   // outside the rectangle
  CHECK(px(14, 12) == std::array<float, 4>{1, 1, 1, 1});
}

TEST_CASE("image items: bilinear sampling, a flipped rectangle, order with vector items") {
  sr::Scene scene(8, 4, {0, 0, 0, 0});
  auto ramp = std::make_shared<splinefig::Image>(2, 1, 4);
  const float v[8] = {0, 0, 0, 1, 1, 1, 1, 1};
  std::copy(v, v + 8, ramp->pixels.begin());
  // x in [0, 8): source x = (cx / 8) * 2, sampled at sx - 0.5 between the two pixels.
  scene.image(ramp, {0, 0}, {8, 2}, sr::Scene::Sampling::Bilinear);
  scene.image(ramp, {8, 2}, {0, 4}, sr::Scene::Sampling::Nearest);  // mirrored in x
  scene.fill_polygon({{{6, 0}, {8, 0}, {8, 1}, {6, 1}}}, sr::FillRule::NonZero, {0, 0, 1, 1});
  const splinefig::Image img = sr::rasterize(scene, 1);
  const float expected[8] = {0, 0, 0.125f, 0.375f, 0.625f, 0.875f, 1, 1};
  for (int x = 0; x < 8; ++x) CHECK(img.at(x, 1, 0) == Approx(expected[x]).margin(1e-7));
  CHECK(img.at(0, 3, 0) == 1.0f);  // mirrored: the white pixel on the left
  CHECK(img.at(7, 3, 0) == 0.0f);
  CHECK(img.at(7, 0, 0) == 0.0f);  // the later blue fill covers the image
  CHECK(img.at(7, 0, 2) == 1.0f);
}

TEST_CASE("image items: identical bytes for any thread count and pixel filter, bad input rejected") {
  auto build = [](splinefig::Kernel f) {
    sr::Scene scene(300, 700, {1, 1, 1, 1}, f);
    scene.fill_circle({150, 350}, 120, {0.2f, 0.4f, 0.6f, 0.7f});
    scene.image(two_by_two(), {20.3, 15.7}, {280.9, 690.2}, sr::Scene::Sampling::Bilinear);
    scene.fill_circle({150, 350}, 60, {0.8f, 0.1f, 0.1f, 0.5f});
    return scene;
  };
  for (const auto& f : {splinefig::Kernel::box(), splinefig::Kernel::tent()}) {
    const sr::Scene scene = build(f);
    const splinefig::Image one = sr::rasterize(scene, 1);
    for (int threads : {2, 3, 8}) {
      const splinefig::Image many = sr::rasterize(scene, threads);
      REQUIRE(many.pixels.size() == one.pixels.size());
      CHECK(std::memcmp(many.pixels.data(), one.pixels.data(), one.pixels.size() * sizeof(float)) == 0);
    }
  }
  sr::Scene scene(4, 4);
  CHECK_THROWS_WITH(scene.image(nullptr, {0, 0}, {1, 1}, sr::Scene::Sampling::Nearest), Catch::Contains("image"));
  CHECK_THROWS_AS(scene.image(std::make_shared<splinefig::Image>(1, 1, 3), {0, 0}, {1, 1}, sr::Scene::Sampling::Nearest),
                  std::invalid_argument);
  CHECK_THROWS_WITH(scene.image(two_by_two(), {0, std::nan("")}, {1, 1}, sr::Scene::Sampling::Nearest),
                    Catch::Contains("image: corner point 0 is not finite"));
}
