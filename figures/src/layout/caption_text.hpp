#pragma once
// Internal: the caption's computed fields (load/caption_fields.hpp) worked out from the
// elements' own generated data when the figure is laid out.
#include <splinefig/figures/spec.hpp>

#include <string>

namespace splinefig::figures::detail {

// The caption with every field replaced by its value, printed as tick labels are (axes.hpp,
// tick_number: fixed decimals, the minus sign U+2212, no "−0"). Throws
// SpecFileError naming the field's table when its element is missing or the value does not
// apply to it (a derivative of a curve that is not made of cubic pieces, t outside the curve).
std::string caption_text(const FigureSpec& spec);

}  // namespace splinefig::figures::detail
