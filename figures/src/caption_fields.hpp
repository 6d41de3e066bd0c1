#pragma once
// Internal: the caption's computed fields (docs/spec.md, "Caption fields"). A caption states
// values of its figure's data only through `{=name}` fields, each declared by a
// [[caption_field]] table naming one plot element and a value of it (a point, a derivative,
// an extremum, a control point, a count); the value is worked out from the element's own
// generated data when the figure is built, so the caption cannot disagree with the drawing.
#include "toml_reader.hpp"

#include <splinefig/figures/spec.hpp>

#include <string>
#include <vector>

namespace splinefig::figures::detail {

// Reads the top level's [[caption_field]] tables and checks them against the caption: every
// `{=name}` in it must be declared, every declared field used. `caption_key` is the caption's
// "FILE:LINE: caption" for messages.
std::vector<CaptionField> parse_caption_fields(TableReader& r, const std::string& caption,
                                               const std::string& caption_key);

// The caption with every field replaced by its value in its number format. Throws
// SpecFileError naming the field's table when its element is missing or the value does not
// apply to it (a derivative of a curve that is not made of cubic pieces, t outside the curve).
std::string caption_text(const FigureSpec& spec);

// One value formatted as captions print it: fixed `decimals`, the minus sign U+2212, no "−0".
std::string caption_number(double v, int decimals);

}  // namespace splinefig::figures::detail
