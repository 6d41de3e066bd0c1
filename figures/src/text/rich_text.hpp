#pragma once
// Internal: labels with math markup, set as runs of plain UTF-8 text.
//
// Markup (docs/spec.md, "Text"):
//   `_x` or `_{...}` a subscript, `^x` or `^{...}` a superscript (x one character or one \name);
//   `\name` a TeX name for a Greek letter or symbol (`\beta` β, `\Delta` Δ, `\infty` ∞, `\le` ≤,
//   `\times` ×, ...: the table in rich_text.cpp); a space after it is kept, `{}` ends it
//   without one (`\alpha{}x` is αx);
//   `$...$` math: Latin and lower-case Greek letters are set in the italic (Oblique) face and
//   `-` becomes the minus sign U+2212;
//   `\_`, `\^`, `\{`, `\}`, `\$` and `\\` are the characters themselves.
// Runs are measured with the renderer's measure_text (advance widths from shaping) and placed
// one after the other on a shared baseline. Sub- and superscripts are set at 70% of the size,
// their baselines 0.22 em below and 0.40 em above the main baseline (fixed fractions of the em,
// for every glyph alike).
#include <splinefig/renderer/renderer.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig::figures::detail {

struct Run {
  std::string text;  // UTF-8, markup resolved
  double size;       // font size
  double dx, dy;     // pen origin relative to the label's origin (dy > 0 is down)
  bool italic = false;
};

struct RichText {
  std::vector<Run> runs;
  double width = 0, ascent = 0, descent = 0;
};

// `measure` gives the extent of plain text at a size; its units are the layout's.
using Measure = std::function<render::TextExtent(const std::string&, double size, bool italic)>;
RichText set_text(const std::string& markup, double size, const Measure& measure);

// Why a label cannot be set (empty if it can): invalid UTF-8, unbalanced braces or $, a
// dangling _ or ^, an unknown \name.
std::string markup_problem(const std::string& markup);

// The UTF-8 character of a TeX name without its backslash ("beta" -> "β"); empty if unknown.
std::string tex_symbol(std::string_view name);

// The label with its markup resolved to plain UTF-8 (for index.json, the gallery, searches):
// sub- and superscripts as Unicode sub/superscript characters where they all have one
// ("$b_1$" -> "b₁", "10^{-3}" -> "10⁻³"), else written "_x" / "^x".
std::string plain_text(const std::string& markup);

}  // namespace splinefig::figures::detail
