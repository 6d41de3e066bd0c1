// The caption's computed fields read and checked (caption_fields.hpp, docs/spec.md "Caption fields").
#include "caption_fields.hpp"

#include "toml_reader.hpp"

#include <splinefig/figures/axes.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

namespace splinefig::figures::detail {
namespace {

// The value functions and how many arguments each takes.
const std::map<std::string, int, std::less<>>& functions() {
  static const std::map<std::string, int, std::less<>> f{
      {"point", 1},    {"x", 1},        {"y", 1},        {"d1", 1},       {"d2", 1},   {"curvature", 1},
      {"max_y", 2},    {"min_y", 2},    {"argmax_y", 2}, {"argmin_y", 2}, {"knot", 1}, {"count", 0},
      {"b1", 1},       {"b2", 1},       {"item", 1},     {"k", 1},        {"db", 1},       {"points", 0},
      {"steps", 0},    {"leakage", 0},  {"marks", 0},    {"bias", 0},     {"tension", 0},
      {"along", 3},    {"mirror_x", 0}};
  return f;
}

bool is_name(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

std::string trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

// "fn(a, b)" into the field; an empty string if it is fine, else what is wrong.
std::string parse_value(const std::string& text, CaptionField& f) {
  const auto open = text.find('('), close = text.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open || !trim(text.substr(close + 1)).empty())
    return "\"" + text + "\": expected FUNCTION(ARGUMENTS), e.g. \"d2(0)\"";
  f.function = trim(text.substr(0, open));
  const auto fn = functions().find(f.function);
  if (fn == functions().end())
    return "\"" + f.function + "\" is not a value function (point, x, y, d1, d2, curvature, max_y, min_y, argmax_y, "
           "argmin_y, knot, count, item, b1, b2, k, db, points, steps, leakage, marks, bias, tension, along, mirror_x)";
  const std::string inner = trim(text.substr(open + 1, close - open - 1));
  std::size_t at = 0;
  while (!inner.empty() && at <= inner.size()) {
    const auto comma = std::min(inner.find(',', at), inner.size());
    const std::string arg = trim(inner.substr(at, comma - at));
    char* end = nullptr;
    const double v = std::strtod(arg.c_str(), &end);
    if (arg.empty() || *end != '\0' || !std::isfinite(v)) return "\"" + arg + "\" is not a finite number";
    f.args.push_back(v);
    at = comma + 1;
  }
  if (static_cast<int>(f.args.size()) != fn->second)
    return f.function + "() takes " + std::to_string(fn->second) + " argument" + (fn->second == 1 ? "" : "s") + ", got " +
           std::to_string(f.args.size());
  if (f.function == "knot" || f.function == "item" || f.function == "b1" || f.function == "b2")
    if (f.args[0] < 0 || f.args[0] != std::floor(f.args[0]) || f.args[0] > 1e9)
      return f.function + "() takes an index 0, 1, 2, ..., got " + tick_number(f.args[0], 6);
  if (f.function == "along") {
    for (int k = 1; k <= 2; ++k)
      if (f.args[k] < 0 || f.args[k] != std::floor(f.args[k]) || f.args[k] > 1e9)
        return "along(t, i, j) takes knot indices 0, 1, 2, ... for i and j, got " + tick_number(f.args[k], 6);
    if (f.args[1] == f.args[2]) return "along(t, i, j) needs two different knots i and j";
  }
  if (f.args.size() == 2 && !(f.args[0] < f.args[1])) return f.function + "(a, b) needs a < b";
  return {};
}

}  // namespace

std::vector<Ref> references(const std::string& caption, std::string& problem) {
  std::vector<Ref> refs;
  for (std::size_t p = caption.find("{="); p != std::string::npos; p = caption.find("{=", p + 2)) {
    const auto close = caption.find('}', p);
    const std::string name = close == std::string::npos ? "" : caption.substr(p + 2, close - p - 2);
    if (!is_name(name)) {
      problem = "a field is written {=NAME} (letters, digits, _), at \"" + caption.substr(p, 24) + "\"";
      return {};
    }
    refs.push_back({p, close + 1, name});
  }
  return refs;
}

std::vector<CaptionField> parse_caption_fields(TableReader& r, const std::string& caption, const SpecLocation& caption_key) {
  std::vector<CaptionField> fields;
  std::set<std::string> names;
  r.each_table("caption_field", [&](TableReader& s, const toml::table&) {
    CaptionField f;
    f.origin = s.origin("");
    const auto name = s.opt_string("name");
    if (!name || !is_name(*name)) s.fail("name", "needs name = \"NAME\" (letters, digits, _), used as {=NAME} in the caption");
    if (!names.insert(*name).second) s.fail("name", "\"" + *name + "\" is declared twice");
    f.name = *name;
    const auto element = s.opt_string("element");
    if (!element || element->empty())
      s.fail("element", "needs element = \"KEY PATH\" of a plot element, e.g. \"axes[1].bezier[0]\"");
    f.element = *element;
    const auto value = s.opt_string("value");
    if (!value) s.fail("value", "needs value = \"FUNCTION(ARGUMENTS)\", e.g. \"d2(0)\"");
    if (std::string bad = parse_value(*value, f); !bad.empty()) s.fail("value", bad);
    f.decimals = s.integer("decimals", 2, 0, 12);
    f.fraction = s.boolean("fraction", false);
    if (f.fraction && f.function == "points") s.fail("fraction", "points() prints decimals; fraction = true is for a value");
    fields.push_back(std::move(f));
  });
  std::string problem;
  const std::vector<Ref> refs = references(caption, problem);
  if (!problem.empty()) throw SpecFileError(caption_key, problem);
  std::set<std::string> used;
  for (const Ref& ref : refs) {
    if (!names.count(ref.name))
      throw SpecFileError(caption_key, "{=" + ref.name + "} names no [[caption_field]] (declare it with name = \"" +
                          ref.name + "\")");
    used.insert(ref.name);
  }
  for (const CaptionField& f : fields)
    if (!used.count(f.name)) throw SpecFileError(f.origin, "\"" + f.name + "\" is declared but the caption never uses {=" + f.name + "}");
  return fields;
}

}  // namespace splinefig::figures::detail
