#pragma once
// Internal: the caption's computed fields (docs/spec.md, "Caption fields"), as the loader reads
// them. A caption states values of its figure's data only through `{=name}` fields, each
// declared by a [[caption_field]] table naming one plot element and a value of it (a point, a
// derivative, an extremum, a control point, a count); the value is worked out from the
// element's own generated data when the figure is laid out (layout/caption_text.hpp), so the
// caption cannot disagree with the drawing.
#include <splinefig/figures/spec.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace splinefig::figures::detail {

class TableReader;

// Reads the top level's [[caption_field]] tables and checks them against the caption: every
// `{=name}` in it must be declared, every declared field used. `caption_key` is the caption's
// location, for messages.
std::vector<CaptionField> parse_caption_fields(TableReader& r, const std::string& caption,
                                               const SpecLocation& caption_key);

// Each `{=name}` of the caption, in order, with where it starts and ends. A field that is not
// written {=NAME} sets `problem` and gives none.
struct Ref {
  std::size_t begin, end;
  std::string name;
};
std::vector<Ref> references(const std::string& caption, std::string& problem);

}  // namespace splinefig::figures::detail
