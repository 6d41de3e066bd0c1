// Label text: math markup, Unicode in specs, font keys, rotated y labels. Expected runs and
// characters are written out by hand from the markup rules (docs/spec.md, "Text").
#include "spec_error_check.hpp"
#include <catch2/catch.hpp>

#include "figures/src/text/rich_text.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <string>
#include <vector>

namespace sf = splinefig::figures;
namespace sfd = splinefig::figures::detail;
namespace sr = splinefig::render;

namespace {

// A stand-in for measure_text: every character (code point) is 10 units wide at size 10, ink
// 7 above and 2 below the baseline; italic runs are recorded.
sr::TextExtent fake_measure(const std::string& s, double size, bool) {
  double n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return {n * size, 0.7 * size, 0.2 * size};
}

}  // namespace

TEST_CASE("markup: TeX names, $...$ math with italic variables and a true minus, sub- and superscripts") {
  // "$b_1$ = 0.2": b italic, 1 a subscript (upright digit), then the rest upright.
  sfd::RichText rt = sfd::set_text("$b_1$ = 0.2 \\alpha", 10, fake_measure);
  REQUIRE(rt.runs.size() == 3);
  CHECK(rt.runs[0].text == "b");
  CHECK(rt.runs[0].italic);
  CHECK(rt.runs[0].size == 10);
  CHECK(rt.runs[1].text == "1");
  CHECK_FALSE(rt.runs[1].italic);
  CHECK(rt.runs[1].size == Approx(7));    // 70% of the size
  CHECK(rt.runs[1].dy == Approx(2.2));    // 0.22 em below the baseline
  CHECK(rt.runs[1].dx == Approx(10));     // after b's advance
  CHECK(rt.runs[2].text == " = 0.2 \xce\xb1");  // outside math a name is upright
  CHECK(rt.runs[2].dx == Approx(17));     // b (10) + the subscript 1 (7)
  CHECK(rt.width == Approx(17 + 8 * 10));
  // Superscripts: 0.40 em up; in math '-' is U+2212.
  rt = sfd::set_text("$10^{-3}$", 10, fake_measure);
  REQUIRE(rt.runs.size() == 2);
  CHECK(rt.runs[0].text == "10");
  CHECK(rt.runs[1].text == "\xe2\x88\x92" "3");
  CHECK(rt.runs[1].dy == Approx(-4.0));
  CHECK(rt.ascent == Approx(0.7 * 7 + 4.0));
  // Outside math the hyphen stays a hyphen; escapes give the characters themselves.
  CHECK(sfd::plain_text("a-b \\$ \\_ \\{\\} \\\\") == "a-b $ _ {} \\");
  // Names: Greek (both cases), the symbols, spaces after a name kept, {} ends a name.
  CHECK(sfd::plain_text("\\beta\\Delta\\infty\\le\\ge\\ne\\times\\cdot\\pm\\to\\prime\\approx") ==
        "\xce\xb2\xce\x94\xe2\x88\x9e\xe2\x89\xa4\xe2\x89\xa5\xe2\x89\xa0\xc3\x97\xe2\x8b\x85\xc2\xb1\xe2\x86\x92\xe2\x80\xb2"
        "\xe2\x89\x88");
  CHECK(sfd::plain_text("$\\alpha x$") == "\xce\xb1 x");
  CHECK(sfd::plain_text("$\\alpha{}x$") == "\xce\xb1x");
  // As plain text (index.json, the gallery): Unicode sub- and superscripts where they exist.
  CHECK(sfd::plain_text("bias $b_1$ = 0.2 \u2026 5") == "bias b\u2081 = 0.2 \u2026 5");
  CHECK(sfd::plain_text("$10^{-3}$, x^2, S_i, f_{xy}") == "10\u207b\u00b3, x\u00b2, S\u1d62, f_xy");
  // UTF-8 passes through unchanged.
  CHECK(sfd::plain_text("\xce\xb2\xe2\x82\x81 = 0.2 \xe2\x88\x92 \xce\xb1") == "\xce\xb2\xe2\x82\x81 = 0.2 \xe2\x88\x92 \xce\xb1");
}

TEST_CASE("markup: every Greek letter name is a character a DejaVu face has") {
  const char* greek[] = {"alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta",
                         "iota", "kappa", "lambda", "mu", "nu", "xi", "omicron", "pi", "varpi", "rho", "varrho", "sigma",
                         "varsigma", "tau", "upsilon", "phi", "varphi", "chi", "psi", "omega", "Alpha", "Beta", "Gamma",
                         "Delta", "Epsilon", "Zeta", "Eta", "Theta", "Iota", "Kappa", "Lambda", "Mu", "Nu", "Xi",
                         "Omicron", "Pi", "Rho", "Sigma", "Tau", "Upsilon", "Phi", "Chi", "Psi", "Omega"};
  sr::TextStyle st;
  for (const char* g : greek) {
    INFO(g);
    const std::string s = sfd::tex_symbol(g);
    REQUIRE(s.size() == 2);  // U+0391..U+03F5: two UTF-8 bytes
    CHECK(static_cast<unsigned char>(s[0]) >= 0xCE);
    CHECK(sr::measure_text(s, st).width > 0);
    st.italic = true;
    CHECK(sr::measure_text(s, st).width > 0);
    st.italic = false;
  }
  CHECK(sfd::tex_symbol("beta") == "\xce\xb2");
  CHECK(sfd::tex_symbol("Omega") == "\xce\xa9");
  CHECK(sfd::tex_symbol("bogus").empty());
}

TEST_CASE("markup: malformed labels are named") {
  CHECK(sfd::markup_problem("\\betta") == "unknown name \\betta (write \\\\ for a backslash)");
  CHECK(sfd::markup_problem("$x") == "an unclosed $");
  CHECK(sfd::markup_problem("a_") == "a dangling _ at the end");
  CHECK(sfd::markup_problem("x^{2") == "an unclosed { after ^");
  CHECK(sfd::markup_problem("a}") == "an unescaped } (write \\})");
  CHECK(sfd::markup_problem("ab\xff") == "invalid UTF-8 at byte 2");
  CHECK(sfd::markup_problem("$b_1$ = 0.2 \\alpha, \xce\xb2\xe2\x82\x81 \xe2\x88\x92 1").empty());
}

TEST_CASE("spec text: invalid UTF-8, unknown names and bad font keys name file, line and key") {
  struct Case {
    std::string text, expect;
  } cases[] = {
      {"title = \"ok\"\n[[text]]\nat = [1, 2]\ntext = \"b\xff\"\n", "bad.toml:4: text[0].text: invalid UTF-8 (byte 0xFF at column 10)"},
      {"[axes]\nx_label = \"a\xce\"\n", "bad.toml:2: axes.x_label: invalid UTF-8 (byte 0xCE at column 13)"},
      {"caption = \"\xed\xa0\x80\"\n", "bad.toml:1: caption: invalid UTF-8"},
      {"[[axes]]\n[[axes.series]]\n[[axes]]\n[[axes.series]]\n[[axes.series]]\nlabel = \"\xc0\xaf\"\n",
       "bad.toml:6: axes[1].series[1].label: invalid UTF-8 (byte 0xC0 at column 10)"},
      {"title = '\\betta'\n", "bad.toml:1: title: \"\\betta\": unknown name \\betta"},
      {"font_family = \"comic\"\n", "bad.toml:1: font_family: unknown value \"comic\" (expected sans | serif | mono)"},
      {"[[text]]\nat = [1, 2]\ntext = \"a\"\nfont_family = 3\n", "bad.toml:4: text[0].font_family: expected a string"},
      {"[axes]\ny_label = \"y\"\ny_label_rotated = \"yes\"\n", "bad.toml:3: axes.y_label_rotated: expected true or false"},
      {"[axes]\nx_label_rotated = true\n", "bad.toml:2: axes.x_label_rotated: unknown key"},
  };
  figtest::check_spec_errors(cases, "bad.toml");
  const sf::FigureSpec spec = sf::parse_spec(
      "font_family = \"serif\"\n[[text]]\nat = [1, 2]\ntext = \"a\"\nfont_family = \"mono\"\n[[text]]\nat = [1, 2]\ntext = \"b\"\n",
      "good.toml");
  CHECK(spec.font_family == sr::FontFamily::Serif);
  CHECK(std::get<sf::TextItem>(spec.items[0]).font.family == sr::FontFamily::Mono);
  CHECK_FALSE(std::get<sf::TextItem>(spec.items[1]).font.family.has_value());
}

TEST_CASE("spec text: a rotated y label reads upwards in a strip left of the tick labels") {
  // The label "yyyyyyyy" is 8 glyphs long: upright it would be a wide, short patch of ink;
  // turned, its ink is tall and narrow, centred on the box's height, left of the tick labels.
  const std::string text = std::string("[canvas]\nwidth = 300\nheight = 240\nbackground = \"#ffffff\"\n") +
                           "[axes]\nx_range = [0, 1]\ny_range = [0, 1]\ny_label = \"yyyyyyyy\"\ny_label_rotated = true\n";
  const sf::FigureSpec spec = sf::parse_spec(text, "rot.toml");
  const sf::RenderedFigure f = sf::render_figure(spec, {1, 1});
  const auto& box = f.info.axes.at(0).pixel_box;  // left, top, right, bottom
  int x0 = 1 << 30, x1 = -1, y0 = 1 << 30, y1 = -1;
  // Ink in the strip left of the tick labels (the ticks' digits are within 40 px of the box).
  for (int y = 0; y < f.image.height; ++y)
    for (int x = 0; x < static_cast<int>(box[0]) - 40; ++x)
      if (f.image.pixel(x, y)[0] < 0.5f) {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
  REQUIRE(x1 >= 0);
  CHECK(y1 - y0 > 3 * (x1 - x0));  // tall and narrow
  CHECK(0.5 * (y0 + y1 + 1) == Approx(0.5 * (box[1] + box[3])).margin(1.5));
  CHECK(x0 >= 16);  // not clipped at the canvas edge: inside the figure margin
}

TEST_CASE("spec text: \"β₁ = 0.2 − α\" in a spec is drawn, in the title as in a label") {
  const std::string label = "\xce\xb2\xe2\x82\x81 = 0.2 \xe2\x88\x92 \xce\xb1";
  const std::string text = "title = \"" + label + "\"\n[canvas]\nwidth = 300\nheight = 120\n[[text]]\nat = [20, 90]\ntext = \"" +
                           label + "\"\n";
  const sf::FigureSpec spec = sf::parse_spec(text, "beta.toml");
  CHECK(spec.title == label);
  const sf::RenderedFigure f = sf::render_figure(spec, {1, 1});
  // Both rows have ink: the title near the top, the label around y = 90.
  auto ink = [&](int ya, int yb) {
    int n = 0;
    for (int y = ya; y < yb; ++y)
      for (int x = 0; x < f.image.width; ++x) n += f.image.pixel(x, y)[0] < 0.5f;
    return n;
  };
  CHECK(ink(0, 45) > 50);
  CHECK(ink(70, 100) > 50);
}
