#pragma once
// Internal: the pieces of the spec loader shared between its files.
#include "toml_reader.hpp"

namespace splinefig::figures::detail {

struct ParseContext {
  std::string file;      // name in messages
  std::string base_dir;  // resolves relative image paths
};

AxesSpec parse_axes(const toml::table& table, const std::string& path, const ParseContext& ctx);
Raster parse_raster(TableReader& r, const ParseContext& ctx);
// Checks a basis spec with the spline core; returns the basis or fails naming `key`.
Basis checked_basis(TableReader& r, std::string_view key, const std::string& spec);
Labelling parse_labelling(TableReader& r);

}  // namespace splinefig::figures::detail
