// Text as glyph outlines: checked against FreeType and HarfBuzz used directly (an independent
// reading of the same font files), not against the renderer's own path code.
#include "coverage_helpers.hpp"

#include "renderer/src/text_layout.hpp"

#include <splinefig/renderer/text_outlines.hpp>

#include <catch2/catch.hpp>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_ADVANCES_H

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace sr = splinefig::render;

namespace {

// One face opened with FreeType, independently of the renderer's font cache.
struct FtFace {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  explicit FtFace(const std::string& file) {
    REQUIRE(FT_Init_FreeType(&lib) == 0);
    const std::string path = sr::find_font(file);
    REQUIRE_FALSE(path.empty());
    REQUIRE(FT_New_Face(lib, path.c_str(), 0, &face) == 0);
  }
  ~FtFace() {
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
  }
  FtFace(const FtFace&) = delete;
  FtFace& operator=(const FtFace&) = delete;
};

// The signed area of a glyph's outline in font units^2 (y up: positive for TrueType's
// clockwise outer contours once negated), by the shoelace formula on the outline flattened
// into 256 chords per Bezier segment (its error is far below the checks' tolerance).
double outline_area(FT_Face face, FT_ULong ch) {
  const FT_UInt id = FT_Get_Char_Index(face, ch);
  REQUIRE(id != 0);
  REQUIRE(FT_Load_Glyph(face, id, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
  struct Acc {
    double area = 0, x = 0, y = 0, sx = 0, sy = 0;
    void to(double nx, double ny) {
      area += x * ny - nx * y;
      x = nx;
      y = ny;
    }
    void close() { to(sx, sy); }
  } acc;
  FT_Outline_Funcs f{};
  f.move_to = [](const FT_Vector* p, void* u) {
    auto* a = static_cast<Acc*>(u);
    if (a->area != 0 || a->x != 0 || a->y != 0) a->close();
    a->x = a->sx = static_cast<double>(p->x);
    a->y = a->sy = static_cast<double>(p->y);
    return 0;
  };
  f.line_to = [](const FT_Vector* p, void* u) {
    static_cast<Acc*>(u)->to(static_cast<double>(p->x), static_cast<double>(p->y));
    return 0;
  };
  f.conic_to = [](const FT_Vector* c, const FT_Vector* p, void* u) {
    auto* a = static_cast<Acc*>(u);
    const double x0 = a->x, y0 = a->y;
    for (int i = 1; i <= 256; ++i) {
      const double t = i / 256.0, s = 1 - t;
      a->to(s * s * x0 + 2 * s * t * c->x + t * t * p->x, s * s * y0 + 2 * s * t * c->y + t * t * p->y);
    }
    return 0;
  };
  f.cubic_to = [](const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* p, void* u) {
    auto* a = static_cast<Acc*>(u);
    const double x0 = a->x, y0 = a->y;
    for (int i = 1; i <= 256; ++i) {
      const double t = i / 256.0, s = 1 - t;
      a->to(s * s * s * x0 + 3 * s * s * t * c1->x + 3 * s * t * t * c2->x + t * t * t * p->x,
            s * s * s * y0 + 3 * s * s * t * c1->y + 3 * s * t * t * c2->y + t * t * t * p->y);
    }
    return 0;
  };
  REQUIRE(FT_Outline_Decompose(&face->glyph->outline, &f, &acc) == 0);
  acc.close();
  return -0.5 * acc.area;  // TrueType outer contours run clockwise (y up)
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

double centroid_x(const std::vector<double>& cov, int w) {
  double m = 0, mx = 0;
  for (std::size_t i = 0; i < cov.size(); ++i) {
    m += cov[i];
    mx += cov[i] * (static_cast<double>(i % static_cast<std::size_t>(w)) + 0.5);
  }
  return mx / m;
}

}  // namespace

TEST_CASE("text: the ink of a glyph equals the area of its FreeType outline") {
  // '8' and 'g' have holes, 'B' straight edges too, U+03B2 (beta) a quadratic-only bowl; at
  // 40 px, so the outline spans hundreds of pixels. Exact-area coverage sums to the area of
  // the outline exactly; the flattening within 1e-4 px and float pixels leave < 1e-4 of it.
  FtFace ft("DejaVuSans.ttf");
  const double size = 40, scale = size / ft.face->units_per_EM;
  for (const char* s : {"8", "g", "B", "\xce\xb2"}) {
    INFO(s);
    sr::TextStyle st;
    st.size = size;
    st.color = {1, 1, 1, 1};
    const auto cov = testutil::rendered_coverage(80, 80, [&](sr::Scene& sc) { sc.text(s, {20.3, 50.6}, st); });
    FT_ULong ch = static_cast<unsigned char>(s[0]);
    if (ch >= 0x80) ch = ((ch & 0x1F) << 6) | (static_cast<unsigned char>(s[1]) & 0x3F);
    const double area = outline_area(ft.face, ch) * scale * scale;
    CHECK(area > 100);
    CHECK(sum(cov) == Approx(area).epsilon(1e-4));
  }
}

TEST_CASE("text: a sub-pixel shift of the anchor moves the ink by the shift") {
  // No rounding of the origin: a quarter-pixel shift moves the ink's centroid by 0.25 px (the
  // box filter's pixel centroid follows the true one to about 0.01 px for a glyph this size),
  // and leaves the ink unchanged.
  sr::TextStyle st;
  st.size = 32;
  st.color = {1, 1, 1, 1};
  const int w = 64;
  double c0 = 0, m0 = 0;
  for (double dx : {0.0, 0.25, 0.5, 0.75}) {
    const auto cov = testutil::rendered_coverage(w, 48, [&](sr::Scene& s) { s.text("o", {20 + dx, 36}, st); });
    if (dx == 0) {
      c0 = centroid_x(cov, w);
      m0 = sum(cov);
      continue;
    }
    CHECK(centroid_x(cov, w) - c0 == Approx(dx).margin(0.01));
    CHECK(sum(cov) == Approx(m0).epsilon(1e-5));
  }
}

TEST_CASE("text: identical bytes for any thread count, under the box and the tent filter") {
  for (bool box : {true, false}) {
    auto draw = [&](int threads) {
      sr::Scene s(300, 200, {1, 1, 1, 1}, box ? splinefig::Kernel::box() : splinefig::Kernel::tent());
      sr::TextStyle st;
      for (int i = 0; i < 40; ++i) {
        st.size = 9 + i * 0.7;
        st.angle = box ? 0 : 7.5 * i;
        st.italic = i % 3 == 0;
        st.weight = i % 2 ? sr::FontWeight::Bold : sr::FontWeight::Normal;
        s.text("Spline \xce\xb2\xe2\x82\x81 = 0.2", {3.3 * i, 5 + 4.7 * i}, st);
      }
      return sr::rasterize(s, threads).pixels;
    };
    const auto one = draw(1);
    CHECK(one == draw(2));
    CHECK(one == draw(5));
  }
}

TEST_CASE("text: \"beta1 = 0.2 - alpha\" is shaped into the font's glyphs for those characters") {
  // U+03B2 U+2081 = 0.2 U+2212 U+03B1: every character is DejaVu Sans's own glyph (no fallback),
  // in order, each advanced by its HarfBuzz advance (no kerning in this string).
  const std::u32string chars = U"\u03b2\u2081 = 0.2 \u2212 \u03b1";
  const std::string text = "\xce\xb2\xe2\x82\x81 = 0.2 \xe2\x88\x92 \xce\xb1";
  FtFace ft("DejaVuSans.ttf");
  sr::TextStyle st;
  st.size = 20;
  const auto lay = sr::detail::layout_text(text, st);
  std::vector<FT_UInt> want;
  for (char32_t c : chars)
    if (c != U' ') want.push_back(FT_Get_Char_Index(ft.face, c));
  REQUIRE(lay.glyphs.size() == want.size());  // spaces have no outline
  for (std::size_t i = 0; i < want.size(); ++i) {
    CHECK(want[i] != 0);
    CHECK(lay.glyphs[i].id == want[i]);
  }
  // The advance: the sum of the glyphs' advances (hmtx, read by FreeType unscaled).
  double adv = 0;
  for (char32_t c : chars) {
    FT_Fixed a = 0;
    REQUIRE(FT_Get_Advance(ft.face, FT_Get_Char_Index(ft.face, c), FT_LOAD_NO_SCALE, &a) == 0);
    adv += static_cast<double>(a);
  }
  CHECK(sr::measure_text(text, st).width == Approx(adv * st.size / ft.face->units_per_EM).epsilon(1e-12));
}

TEST_CASE("text: invalid UTF-8 is an error naming the byte") {
  sr::Scene s(20, 20);
  sr::TextStyle st;
  for (auto [bad, at] : {std::pair<std::string, int>{"ab\xff", 2}, {"a\xce", 1}, {"\xc0\xaf", 0}, {"x\xed\xa0\x80", 1},
                         {"\xf4\x90\x80\x80", 0}}) {
    INFO(at);
    try {
      s.text(bad, {5, 10}, st);
      FAIL("accepted invalid UTF-8");
    } catch (const std::invalid_argument& e) {
      CHECK_THAT(e.what(), Catch::Contains("invalid UTF-8 at byte " + std::to_string(at)));
    }
  }
  CHECK_THROWS_AS(sr::text_path("\xff", {0, 0}, st), std::invalid_argument);
  CHECK_THROWS_AS(sr::measure_text("\xff", st), std::invalid_argument);
}

TEST_CASE("text: a character no DejaVu face has is an error naming it") {
  sr::Scene s(20, 20);
  sr::TextStyle st;
  // U+10FFFD is a private-use character: no font of the DejaVu family defines it.
  try {
    s.text("ok \xf4\x8f\xbf\xbd", {5, 10}, st);
    FAIL("drew a character no face has");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("U+10FFFD"));
  }
}

TEST_CASE("text: a character the style's face lacks comes from the next DejaVu face") {
  // Find a character DejaVu Serif lacks and DejaVu Sans has (read with FreeType directly).
  FtFace serif("DejaVuSerif.ttf"), sans("DejaVuSans.ttf");
  char32_t found = 0;
  for (char32_t c = 0x2190; c < 0x2c00 && !found; ++c)
    if (FT_Get_Char_Index(serif.face, c) == 0 && FT_Get_Char_Index(sans.face, c) != 0) found = c;
  REQUIRE(found != 0);
  std::string utf8;
  utf8 += static_cast<char>(0xE0 | (found >> 12));
  utf8 += static_cast<char>(0x80 | ((found >> 6) & 0x3F));
  utf8 += static_cast<char>(0x80 | (found & 0x3F));
  sr::TextStyle st;
  st.size = 30;
  sr::TextStyle serif_style = st;
  serif_style.family = sr::FontFamily::Serif;
  const sr::Path a = sr::text_path(utf8, {10, 30}, serif_style), b = sr::text_path(utf8, {10, 30}, st);
  REQUIRE_FALSE(a.empty());
  CHECK(a.verbs() == b.verbs());
  REQUIRE(a.points().size() == b.points().size());
  for (std::size_t i = 0; i < a.points().size(); ++i) {
    CHECK(a.points()[i].x == b.points()[i].x);
    CHECK(a.points()[i].y == b.points()[i].y);
  }
  // The fallback chain starts with the style's own face and lists only installed files.
  const auto chain = sr::font_fallback(serif_style);
  REQUIRE_FALSE(chain.empty());
  CHECK(chain[0] == "DejaVuSerif.ttf");
  for (const auto& f : chain) CHECK_FALSE(sr::find_font(f).empty());
  CHECK(sr::font_file_name(sr::FontFamily::Serif, sr::FontWeight::Bold, true) == "DejaVuSerif-BoldItalic.ttf");
  CHECK(sr::font_file_name(sr::FontFamily::Mono, sr::FontWeight::Normal, true) == "DejaVuSansMono-Oblique.ttf");
}

TEST_CASE("text: text_path is the outline Scene::text fills, turned by angle about the anchor") {
  sr::TextStyle st;
  st.size = 24;
  st.halign = sr::HAlign::Center;
  st.valign = sr::VAlign::Middle;
  const sr::Vec2 anchor{40.25, 30.5};
  const sr::Path flat = sr::text_path("k(s)", anchor, st);
  st.angle = 90;  // reads upwards: text-frame (u, v) -> anchor + (v, -u)
  const sr::Path up = sr::text_path("k(s)", anchor, st);
  REQUIRE(flat.points().size() == up.points().size());
  for (std::size_t i = 0; i < flat.points().size(); ++i) {
    const double u = flat.points()[i].x - anchor.x, v = flat.points()[i].y - anchor.y;
    CHECK(up.points()[i].x == Approx(anchor.x + v).margin(1e-12));
    CHECK(up.points()[i].y == Approx(anchor.y - u).margin(1e-12));
  }
  // Filling the path as a polygon gives the same pixels as drawing the text.
  st.angle = 0;
  st.color = {1, 1, 1, 1};
  const auto text = testutil::rendered_coverage(80, 60, [&](sr::Scene& s) { s.text("k(s)", anchor, st); });
  const auto poly = testutil::rendered_coverage(80, 60, [&](sr::Scene& s) {
    s.fill_polygon(flat.flatten(1e-4).contours, sr::FillRule::NonZero, {1, 1, 1, 1});
  });
  CHECK(testutil::compare(text, poly).max < 1e-6);
}

TEST_CASE("text: scenes drawn on several threads at once give the bytes of one drawn alone") {
  // The font caches are shared by every scene: their first use from several threads at once
  // (faces loaded, strings shaped, outlines read) must neither race nor change a pixel.
  auto draw = [](int k) {
    sr::Scene s(160, 60);
    sr::TextStyle st;
    st.size = 11 + k;
    st.family = static_cast<sr::FontFamily>(k % 3);
    st.italic = k % 2 == 1;
    s.text("Thread " + std::to_string(k) + " \xce\xb1\xce\xb2\xce\xb3 \xe2\x88\x9e", {4.5, 30.25}, st);
    return sr::rasterize(s, 1).pixels;
  };
  std::vector<decltype(draw(0))> together(6);
  {
    std::vector<std::thread> pool;
    for (int k = 0; k < 6; ++k) pool.emplace_back([&, k] { together[static_cast<std::size_t>(k)] = draw(k); });
    for (auto& t : pool) t.join();
  }
  for (int k = 0; k < 6; ++k) CHECK(together[static_cast<std::size_t>(k)] == draw(k));
}
