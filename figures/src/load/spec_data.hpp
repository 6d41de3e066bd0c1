#pragma once
// Internal: point data a spec names instead of typing it where it is used (docs/spec.md,
// "Data"): `KEY_file = "knots.csv"` next to any key that takes points (`points`, `knots`), read
// by the command line's CSV rules relative to the spec's directory, and `[data] NAME = [[x, y],
// ...]` tables, used as `points = "NAME"`.
#include "toml_reader.hpp"

#include <splinefig/figures/spec.hpp>

#include <map>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

namespace splinefig::figures::detail {

struct SpecData final : PointSource {
  std::string base_dir;                              // resolves KEY_file paths
  std::map<std::string, std::vector<Vec2>> named;    // [data]
  // data_points(r, key, *this).
  std::optional<std::vector<Vec2>> points(TableReader& r, std::string_view key) const override;
};

// The [data] table of the spec's top level `r` (none: no names).
SpecData parse_data(TableReader& r, const std::string& base_dir);

// The points of `key` when they are given by `KEY_file` or by a [data] name; nullopt when `key`
// holds points itself (or nothing).
std::optional<std::vector<Vec2>> data_points(TableReader& r, std::string_view key, const SpecData& data);

}  // namespace splinefig::figures::detail
