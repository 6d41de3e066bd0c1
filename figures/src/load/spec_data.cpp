// Point data from CSV files and from the [data] table of a spec (see spec_data.hpp).
#include "spec_data.hpp"

#include <splinefig/spline/points_csv.hpp>

#include <filesystem>
#include <fstream>

namespace splinefig::figures::detail {
namespace {

// Names of [data] entries: what a TOML bare key allows, so that `points = "NAME"` reads as
// the key it refers to.
bool valid_name(std::string_view name) {
  if (name.empty()) return false;
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

std::string known_names(const SpecData& data) {
  if (data.named.empty()) return "the spec has no [data] table";
  std::string s = "known:";
  for (const auto& [name, _] : data.named) s += " " + name;
  return s;
}

// x,y points of the CSV file `path` (as given: `shown`), by the command line's rules.
std::vector<Vec2> read_file(TableReader& r, const std::string& file_key, const std::string& shown,
                            const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  // A symlink loop or an unreadable directory on the way is said as such, not as missing.
  if (!fs::exists(st))
    r.fail(file_key, ec && st.type() != fs::file_type::not_found
                         ? "cannot open the data file \"" + path.string() + "\" (" + ec.message() + ")"
                         : "no such data file \"" + path.string() + "\"");
  if (!fs::is_regular_file(st)) r.fail(file_key, "\"" + path.string() + "\" is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) r.fail(file_key, "cannot read the data file \"" + path.string() + "\"");
  Points p;
  try {
    p = read_csv_points(in, shown);
  } catch (const CsvError& e) {
    r.fail(file_key, e.what());
  }
  if (p.empty()) r.fail(file_key, shown + ": no points in the file");
  if (p.dim != 2)
    r.fail(file_key, shown + ": " + std::to_string(p.dim) + (p.dim == 1 ? " coordinate" : " coordinates") +
                         " per line, a point is x,y");
  std::vector<Vec2> out;
  out.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) out.push_back({p[i][0], p[i][1]});
  return out;
}

}  // namespace

SpecData parse_data(TableReader& r, const std::string& base_dir) {
  SpecData data;
  data.base_dir = base_dir;
  if (!r.has("data")) return data;
  const toml::node* n = r.node("data");
  const toml::table* t = n->as_table();
  if (!t) r.fail("data", "expected a table [data] of named point lists (NAME = [[x, y], ...])");
  TableReader d(*t, r.file(), "data");
  for (const auto& [key, value] : *t) {
    const std::string name(key.str());
    if (!valid_name(name)) d.fail(name, "a data name is letters, digits, '_' and '-'");
    if (!value.is_array()) d.fail(name, "expected an array of points [[x, y], ...]");
    std::vector<Vec2> pts = d.points(name);
    if (pts.empty()) d.fail(name, "no points");
    data.named.emplace(name, std::move(pts));
  }
  d.finish();
  return data;
}

std::optional<std::vector<Vec2>> data_points(TableReader& r, std::string_view key, const SpecData& data) {
  const std::string file_key = std::string(key) + "_file";
  const toml::node* file = r.has(file_key) ? r.node(file_key) : nullptr;
  const toml::node* value = r.has(key) ? r.node(key) : nullptr;
  if (file) {
    if (value) r.fail(file_key, "give either " + std::string(key) + " or " + file_key + ", not both");
    if (!file->is_string() || file->as_string()->get().empty())
      r.fail_at(*file, file_key, "expected the name of a CSV file (a string)");
    const auto name = r.opt_string(file_key);  // a NUL in it is refused there
    std::filesystem::path p(*name);
    if (p.is_relative()) p = std::filesystem::path(data.base_dir) / p;
    return read_file(r, file_key, *name, p);
  }
  if (value && value->is_string()) {
    const std::string name = *value->value<std::string>();
    const auto it = data.named.find(name);
    if (it == data.named.end()) r.fail(key, "no data named \"" + name + "\" (" + known_names(data) + ")");
    return it->second;
  }
  return std::nullopt;
}

std::optional<std::vector<Vec2>> SpecData::points(TableReader& r, std::string_view key) const {
  return data_points(r, key, *this);
}

}  // namespace splinefig::figures::detail
