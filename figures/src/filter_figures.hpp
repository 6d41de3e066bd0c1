#pragma once
// Internal: plot elements for the filter figures (docs/resample.md, docs/figures.md "Filter
// figures"). Each expands, when the spec is loaded, into ordinary series or images computed by
// the filter analysis and the resampler, so drawing needs nothing new:
//   [[axes.filter]]    k(s) of any filter spec (basis specs, box, tent, lanczos3)
//   [[axes.response]]  |K(f)| of a filter over f in cycles per sample
//   [[axes.step]]      a filter's reconstruction of step samples, optionally prefiltered
//   [[axes.zoneplate]] a zone plate resampled with a filter, as an image
// The keys are documented in docs/resample.md ("Figure elements").
#include "spec_parse.hpp"
#include "toml_reader.hpp"

#include <utility>
#include <vector>

namespace splinefig::figures::detail {

// Parses every filter element of one [axes] table (reader `r`), appending each generated
// element with the source line of its table (for document order).
void parse_filter_elements(TableReader& r, const ParseContext& ctx,
                           std::vector<std::pair<size_t, PlotElement>>& elements);

}  // namespace splinefig::figures::detail
