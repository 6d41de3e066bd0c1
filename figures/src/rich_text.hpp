#pragma once
// Internal: labels with subscripts and superscripts, set as runs of plain text.
//
// Markup: `_x` or `_{...}` is a subscript, `^x` or `^{...}` a superscript, `\_`, `\^`, `\{`,
// `\}` and `\\` are the characters themselves. Runs are measured with the renderer's
// measure_text and placed one after the other on a shared baseline; sub- and superscripts
// are set at 70% size, 0.22 em below and 0.40 em above the baseline.
#include <splinefig/renderer/renderer.hpp>

#include <functional>
#include <string>
#include <vector>

namespace splinefig::figures::detail {

struct Run {
  std::string text;
  double size;    // font size
  double dx, dy;  // pen origin relative to the label's origin (dy > 0 is down)
};

struct RichText {
  std::vector<Run> runs;
  double width = 0, ascent = 0, descent = 0;
};

// `measure` gives the extent of plain text at a size; its units are the layout's.
using Measure = std::function<render::TextExtent(const std::string&, double size)>;
RichText set_text(const std::string& markup, double size, const Measure& measure);

// Why a label cannot be set (empty if it can): unbalanced braces, a dangling _ or ^,
// or characters outside ASCII (OpenImageIO 2.4's render_text truncates code points to
// 8 bits, so they would print as wrong glyphs).
std::string markup_problem(const std::string& markup);

}  // namespace splinefig::figures::detail
