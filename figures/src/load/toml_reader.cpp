// Checked access to TOML tables of figure specs (see toml_reader.hpp).
#include "toml_reader.hpp"

#include "../text/rich_text.hpp"

#include <splinefig/spline/points_csv.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace splinefig::figures::detail {

namespace {

std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

const char* type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

}  // namespace

std::string key_depth_problem(std::string_view text, const std::string& file) {
  std::size_t line = 1, parts = 0, i = 0, depth = 0;  // depth: open brackets and braces
  bool after_dot = false;  // a '.' since the chain's last atom
  auto atom = [&]() {
    parts = after_dot ? parts + 1 : 1;
    after_dot = false;
    return parts > kMaxKeyParts;
  };
  auto too_deep = [&]() {
    return SpecLocation{file, line, ""}.str() + ": a dotted key of more than " + std::to_string(kMaxKeyParts) +
           " parts (the limit of key and table-header depth)";
  };
  auto is_bare = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      const std::string_view fence = c == '"' ? "\"\"\"" : "'''";
      const bool multi = text.substr(i, 3) == fence;
      const std::size_t start_line = line;
      i += multi ? 3 : 1;
      while (i < text.size()) {
        if (text[i] == '\n') ++line;
        if (c == '"' && text[i] == '\\') {  // an escape; a backslash may end a line of a """ string
          if (i + 1 < text.size() && text[i + 1] == '\n') ++line;
          i += 2;
          continue;
        }
        if (text[i] == c && (!multi || text.substr(i, 3) == fence)) {
          i += multi ? 3 : 1;
          // a multi-line string may end in up to two more quotes
          while (multi && i < text.size() && text[i] == c) ++i;
          break;
        }
        ++i;
      }
      if (atom()) { line = start_line; return too_deep(); }
      continue;
    }
    if (is_bare(c)) {
      while (i < text.size() && is_bare(text[i])) ++i;
      if (atom()) return too_deep();
      continue;
    }
    if (c == '.') after_dot = parts > 0;
    else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    } else if (c != ' ' && c != '\t') {
      if (c == '\n') ++line;
      if (c == '[' || c == '{') {
        if (++depth > kMaxValueNesting)
          return SpecLocation{file, line, ""}.str() + ": arrays and inline tables nested more than " +
                 std::to_string(kMaxValueNesting) + " deep (the limit of value nesting)";
      } else if ((c == ']' || c == '}') && depth > 0) {
        --depth;
      }
      parts = 0;
      after_dot = false;
    }
    ++i;
  }
  return {};
}

std::string utf8_problem(std::string_view text, const std::string& file) {
  std::size_t i = 0, line = 1, line_start = 0;
  auto bad_at = [&]() -> std::size_t {  // the offset of the first invalid byte, or npos
    while (i < text.size()) {
      const auto b0 = static_cast<unsigned char>(text[i]);
      if (b0 == '\n') {
        ++line;
        line_start = i + 1;
      }
      std::size_t n = 1;
      char32_t c = b0, min = 0;
      if (b0 >= 0x80) {
        if ((b0 & 0xE0) == 0xC0) n = 2, c = b0 & 0x1F, min = 0x80;
        else if ((b0 & 0xF0) == 0xE0) n = 3, c = b0 & 0x0F, min = 0x800;
        else if ((b0 & 0xF8) == 0xF0) n = 4, c = b0 & 0x07, min = 0x10000;
        else return i;
        if (i + n > text.size()) return i;
        for (std::size_t k = 1; k < n; ++k) {
          const auto b = static_cast<unsigned char>(text[i + k]);
          if ((b & 0xC0) != 0x80) return i;  // the sequence is named by its first byte
          c = (c << 6) | (b & 0x3F);
        }
        if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return i;
      }
      i += n;
    }
    return std::string_view::npos;
  };
  const std::size_t at = bad_at();
  if (at == std::string_view::npos) return {};
  // The key: the last "key =" at or before the bad line, under the last [table] header, named
  // as the reader names it ([[axes]] then [[axes.series]]: "axes[0].series[0]").
  std::string key, table;
  std::map<std::string, int> arrays;  // array-of-tables name -> index of its current table
  std::size_t pos = 0;
  while (pos <= at) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view l = text.substr(pos, eol - pos);
    const std::size_t b = l.find_first_not_of(" \t");
    if (b != std::string_view::npos && pos + b < at) {
      l.remove_prefix(b);
      if (l[0] == '[') {
        const bool array = l.size() > 1 && l[1] == '[';
        std::string_view h = l.substr(array ? 2 : 1);
        h = h.substr(0, std::min(h.find(']'), h.size()));
        while (!h.empty() && h.front() == ' ') h.remove_prefix(1);
        while (!h.empty() && h.back() == ' ') h.remove_suffix(1);
        const std::string name(h);
        if (array) {
          for (auto it = arrays.begin(); it != arrays.end();)  // a new parent table restarts its children
            it = it->first.rfind(name + ".", 0) == 0 ? arrays.erase(it) : std::next(it);
          auto [it, fresh] = arrays.emplace(name, 0);
          if (!fresh) ++it->second;
        }
        table.clear();
        std::size_t start = 0;
        for (;;) {
          const std::size_t dot = name.find('.', start);
          const std::string prefix = name.substr(0, dot);
          if (!table.empty()) table += '.';
          table.append(name, start, dot == std::string::npos ? std::string::npos : dot - start);
          if (auto it = arrays.find(prefix); it != arrays.end()) {
            table += '[';
            table += std::to_string(it->second);
            table += ']';
          }
          if (dot == std::string::npos) break;
          start = dot + 1;
        }
        key.clear();
      } else if (l[0] != '#') {
        const std::size_t eq = l.find('=');
        if (eq != std::string_view::npos && pos + b + eq < at) {
          std::string_view k = l.substr(0, eq);
          while (!k.empty() && (k.back() == ' ' || k.back() == '\t')) k.remove_suffix(1);
          if (k.find_first_of("\"'") == std::string_view::npos) key = std::string(k);
        }
      }
    }
    pos = eol + 1;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "invalid UTF-8 (byte 0x%02X at column %zu)", static_cast<unsigned>(static_cast<unsigned char>(text[at])),
                at - line_start + 1);
  const std::string name = key.empty() ? table : table.empty() ? key : table + "." + key;
  return SpecLocation{file, line, name}.str() + ": " + buf;
}

SpecLocation location_of(const std::string& file, const toml::source_region& where) {
  return {file, static_cast<std::size_t>(where.begin.line), ""};
}

TableReader::TableReader(const toml::table& table, std::string file, std::string path)
    : table_(table), file_(std::move(file)), path_(std::move(path)) {}

SpecLocation TableReader::where() const { return location_of(file_, table_.source()); }

std::string TableReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

SpecLocation TableReader::origin(std::string_view key) const {
  const toml::node* n = table_.get(key);
  const SpecLocation loc = n && n->source().begin.line != 0 ? location_of(file_, n->source()) : where();
  return loc.with_key(key.empty() ? path_ : key_path(key));
}

void TableReader::fail(std::string_view key, const std::string& message) const {
  if (const toml::node* n = table_.get(key)) fail_at(*n, key, message);
  throw SpecFileError(where().with_key(key.empty() ? path_ : key_path(key)), message);
}

void TableReader::fail_at(const toml::node& node, std::string_view key, const std::string& message) const {
  const SpecLocation loc = node.source().begin.line == 0 ? where() : location_of(file_, node.source());
  throw SpecFileError(loc.with_key(key_path(key)), message);
}

bool TableReader::has(std::string_view key) const {
  return table_.contains(key) || (data_ && table_.contains(std::string(key) + "_file"));
}

const toml::node* TableReader::node(std::string_view key) {
  used_.insert(std::string(key));
  return table_.get(key);
}

double TableReader::to_number(const toml::node& n, std::string_view key) const {
  double v;
  if (auto i = n.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (auto f = n.as_floating_point()) {
    v = f->get();
  } else {
    fail_at(n, key, std::string("expected a number, found ") + type_name(n.type()));
  }
  if (!std::isfinite(v)) fail_at(n, key, "expected a finite number, found " + std::string(std::isnan(v) ? "nan" : "inf"));
  return v;
}

Vec2 TableReader::to_point(const toml::node& n, std::string_view key) const {
  const toml::array* a = n.as_array();
  if (!a || a->size() != 2) fail_at(n, key, "expected a point [x, y]");
  return {to_number(*a->get(0), key), to_number(*a->get(1), key)};
}

std::optional<double> TableReader::opt_number(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return to_number(*n, key);
}

double TableReader::number(std::string_view key, double fallback) { return opt_number(key).value_or(fallback); }

double TableReader::positive(std::string_view key, double fallback) {
  double v = number(key, fallback);
  if (!(v > 0)) fail(key, "must be positive, found " + shortest(v));
  return v;
}

double TableReader::non_negative(std::string_view key, double fallback) {
  double v = number(key, fallback);
  if (v < 0) fail(key, "must not be negative, found " + shortest(v));
  return v;
}

int TableReader::integer(std::string_view key, int fallback, int lo, int hi) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  auto i = n->as_integer();
  if (!i) fail_at(*n, key, "expected an integer");
  if (i->get() < lo || i->get() > hi)
    fail_at(*n, key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " + std::to_string(i->get()));
  return static_cast<int>(i->get());
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  auto b = n->as_boolean();
  if (!b) fail_at(*n, key, "expected true or false");
  return b->get();
}

// No spec string needs a NUL, and a path holding one would be cut there ("a\0b" opened "a").
void TableReader::check_no_nul(const toml::node& n, std::string_view key, const std::string& s) const {
  if (s.find('\0') != std::string::npos) fail_at(n, key, "a string holding a NUL character (\\u0000)");
}

std::optional<std::string> TableReader::opt_string(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  auto s = n->as_string();
  if (!s) fail_at(*n, key, "expected a string");
  check_no_nul(*n, key, s->get());
  return s->get();
}

std::string TableReader::string(std::string_view key, const std::string& fallback) {
  return opt_string(key).value_or(fallback);
}

std::optional<std::string> TableReader::opt_label(std::string_view key) {
  auto s = opt_string(key);
  if (s) {
    std::string problem = markup_problem(*s);
    if (!problem.empty()) fail(key, excerpt(*s) + ": " + problem);
  }
  return s;
}

std::string TableReader::label(std::string_view key, const std::string& fallback) {
  return opt_label(key).value_or(fallback);
}

std::vector<std::string> TableReader::labels(std::string_view key) {
  auto v = strings(key);
  for (const auto& s : v) {
    std::string problem = markup_problem(s);
    if (!problem.empty()) fail(key, excerpt(s) + ": " + problem);
  }
  return v;
}

int TableReader::choice(std::string_view key, const std::vector<std::string>& choices, int fallback) {
  auto s = opt_string(key);
  if (!s) return fallback;
  for (size_t i = 0; i < choices.size(); ++i)
    if (*s == choices[i]) return static_cast<int>(i);
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : " | ") + c;
  fail(key, "unknown value " + excerpt(*s) + " (expected " + list + ")");
}

static std::optional<Color> hex(const std::string& s) { return render::parse_hex_color(s); }

std::optional<Color> TableReader::opt_color(std::string_view key) {
  auto s = opt_string(key);
  if (!s) return std::nullopt;
  auto c = hex(*s);
  if (!c) fail(key, excerpt(*s) + " is not a hex colour \"#rrggbb\" or \"#rrggbbaa\"");
  return c;
}

Color TableReader::color(std::string_view key, Color fallback) { return opt_color(key).value_or(fallback); }

std::vector<Color> TableReader::colors(std::string_view key) {
  std::vector<Color> out;
  for (const std::string& s : strings(key)) {
    auto c = hex(s);
    if (!c) fail(key, excerpt(s) + " is not a hex colour \"#rrggbb\" or \"#rrggbbaa\"");
    out.push_back(*c);
  }
  return out;
}

std::vector<double> TableReader::numbers(std::string_view key) {
  std::vector<double> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail_at(*n, key, "expected an array of numbers");
  for (const toml::node& e : *a) out.push_back(to_number(e, key));
  return out;
}

std::vector<std::string> TableReader::strings(std::string_view key) {
  std::vector<std::string> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail_at(*n, key, "expected an array of strings");
  for (const toml::node& e : *a) {
    auto s = e.as_string();
    if (!s) fail_at(e, key, "expected an array of strings");
    check_no_nul(e, key, s->get());
    out.push_back(s->get());
  }
  return out;
}

std::optional<Vec2> TableReader::opt_point(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return to_point(*n, key);
}

std::vector<Vec2> TableReader::points(std::string_view key) {
  if (data_)
    if (auto p = data_->points(*this, key)) return std::move(*p);
  std::vector<Vec2> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail_at(*n, key, "expected an array of points [[x, y], ...]");
  for (const toml::node& e : *a) out.push_back(to_point(e, key));
  return out;
}

std::vector<std::vector<double>> TableReader::matrix(std::string_view key) {
  std::vector<std::vector<double>> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail_at(*n, key, "expected an array of rows");
  for (const toml::node& row : *a) {
    const toml::array* r = row.as_array();
    if (!r) fail_at(row, key, "expected an array of rows");
    std::vector<double> v;
    for (const toml::node& e : *r) v.push_back(to_number(e, key));
    out.push_back(std::move(v));
  }
  return out;
}

Vec2 TableReader::required_point(std::string_view key, const std::string& missing) {
  auto p = opt_point(key);
  if (!p) fail(key, missing);
  return *p;
}

std::string TableReader::required_label(std::string_view key, const std::string& missing) {
  auto t = opt_label(key);
  if (!t) fail(key, missing);
  return *t;
}

std::vector<const toml::table*> TableReader::tables(std::string_view key) {
  std::vector<const toml::table*> out;
  const toml::node* n = node(key);
  if (!n) return out;
  if (const toml::table* t = n->as_table()) {
    out.push_back(t);
  } else if (const toml::array* a = n->as_array()) {
    for (const toml::node& e : *a) {
      const toml::table* t = e.as_table();
      if (!t) fail_at(e, key, "expected a table [[" + key_path(key) + "]]");
      out.push_back(t);
    }
  } else {
    fail_at(*n, key, "expected a table [" + key_path(key) + "]");
  }
  return out;
}

void TableReader::finish() const {
  for (auto&& [k, v] : table_) {
    if (used_.count(k.str())) continue;
    const SpecLocation loc = location_of(file_, k.source().begin.line ? k.source() : v.source());
    throw SpecFileError(loc.with_key(key_path(k.str())), "unknown key");
  }
}

render::StrokeStyle TableReader::stroke(render::StrokeStyle s) {
  s.width = non_negative("width", s.width);
  s.join = static_cast<render::Join>(choice("join", {"miter", "round", "bevel"}, static_cast<int>(s.join)));
  s.miter_limit = number("miter_limit", s.miter_limit);
  if (s.miter_limit < 1) fail("miter_limit", "must be >= 1");
  s.cap = static_cast<render::Cap>(choice("cap", {"butt", "round", "square"}, static_cast<int>(s.cap)));
  if (has("dash")) {
    try {
      s.dashes = render::DashPattern(numbers("dash"));
    } catch (const std::invalid_argument& e) {
      fail("dash", e.what());
    }
  }
  s.dash_offset = number("dash_offset", s.dash_offset);
  return s;
}

double TableReader::font_size(std::string_view key, double fallback) {
  if (!has(key)) return fallback;
  const double given = positive(key, 1), size = given * px_per_size_unit_;
  if (size > kMaxFontSize) {
    if (px_per_size_unit_ == 1) fail(key, "font size " + shortest(given) + " is over the limit of 4096 px");
    fail(key, "font size " + shortest(given) + " pt is " + shortest(size) + " px at the print width, over the limit of 4096 px");
  }
  return size;
}

Font TableReader::font(Font f, std::string_view size_key, std::string_view color_key) {
  f.size = font_size(size_key, f.size);
  f.color = color(color_key, f.color);
  f.bold = boolean("bold", f.bold);
  if (node("font_family")) f.family = font_family("font_family", render::FontFamily::Sans);
  return f;
}

render::FontFamily TableReader::font_family(std::string_view key, render::FontFamily fallback) {
  return static_cast<render::FontFamily>(choice(key, {"sans", "serif", "mono"}, static_cast<int>(fallback)));
}

TextAnchor TableReader::anchor(TextAnchor a) {
  a.halign = static_cast<render::HAlign>(choice("align", {"left", "center", "right"}, static_cast<int>(a.halign)));
  a.valign = static_cast<render::VAlign>(
      choice("valign", {"baseline", "middle", "top", "bottom"}, static_cast<int>(a.valign)));
  return a;
}

}  // namespace splinefig::figures::detail
