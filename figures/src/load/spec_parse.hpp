#pragma once
// Internal: the pieces of the spec loader shared between its files.
#include "toml_reader.hpp"

namespace splinefig::figures::detail {

// The spec of `text` as parse_spec() reads it (spec.hpp), its caption fields not yet worked out.
FigureSpec read_spec(std::string_view text, const std::string& name, const std::string& base_dir);

struct ParseContext {
  std::string file;      // name in messages
  std::string base_dir;  // resolves relative image paths
};

AxesSpec parse_axes(TableReader& r, const ParseContext& ctx);
Raster parse_raster(TableReader& r, const ParseContext& ctx);
// Checks a basis spec with the spline core; returns the basis or fails naming `key`.
Basis checked_basis(TableReader& r, std::string_view key, const std::string& spec);
// The kernel of a filter spec (a basis spec, box, tent or lanczos3), or fails naming `key`.
Kernel kernel_value(TableReader& r, std::string_view key, const std::string& spec);
Labelling parse_labelling(TableReader& r);
render::Marker parse_marker_shape(TableReader& r, std::string_view key, render::Marker fallback);

// The keys of a series' look over the defaults of a curve (2 px, round), a control polygon
// (1 px grey dashed, with dots) or a point set (dots).
enum class LookDefault { Curve, Polygon, Points };
SeriesLook parse_series_look(TableReader& r, LookDefault defaults);

// Every generated element of one [axes] table (companion texts, filter figures), each with
// the source line of its table (for document order).
void parse_generated_elements(TableReader& r, std::vector<std::pair<size_t, PlotElement>>& elements);

// [[axes.fill]] with `under` (spec_fill.cpp), and the check, once the axes' elements are all
// read, that its labels name a curve, kernel or series of the axes.
FillElement parse_fill_under(TableReader& r);
void check_fill_references(const AxesSpec& ax);

}  // namespace splinefig::figures::detail
