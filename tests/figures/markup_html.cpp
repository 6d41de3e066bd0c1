// Captions in the gallery: label markup as HTML.
#include <splinefig/figures/catalog.hpp>

#include <catch2/catch.hpp>

using splinefig::figures::markup_html;

TEST_CASE("markup_html: sub- and superscripts, TeX names, math italics, escaping") {
  CHECK(markup_html("b_2 = 0") == "b<sub>2</sub> = 0");
  CHECK(markup_html("10^{-3}") == "10<sup>-3</sup>");
  CHECK(markup_html("\\beta-spline") == "β-spline");
  CHECK(markup_html("a < b & c") == "a &lt; b &amp; c");
  CHECK(markup_html("$x$").find("<i>x</i>") != std::string::npos);
  CHECK(markup_html("unbalanced {") == "unbalanced {");
}
