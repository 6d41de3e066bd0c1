#pragma once
// Typed, checked access to one TOML table of a figure spec. Every getter validates its
// value and throws SpecFileError "FILE:LINE: KEY: message" on anything wrong; finish()
// rejects the keys nobody asked for (typos such as `colour`), so no key is silently ignored.
#include <splinefig/figures/spec.hpp>

#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace splinefig::figures::detail {

class TableReader;

// Where points named rather than written come from (spec_data.hpp: `KEY_file` and [data] names).
class PointSource {
 public:
  // The points of `key` of the table `r` reads when they are given by name; nullopt when `key`
  // holds points itself (or nothing).
  virtual std::optional<std::vector<Vec2>> points(TableReader& r, std::string_view key) const = 0;

 protected:
  ~PointSource() = default;
};

class TableReader {
 public:
  // `file` names the spec in messages; `path` is the table's key path ("axes[0].curve[2]").
  TableReader(const toml::table& table, std::string file, std::string path);

  bool has(std::string_view key) const;
  const toml::node* node(std::string_view key);  // marks the key as used

  double number(std::string_view key, double fallback);
  std::optional<double> opt_number(std::string_view key);
  double positive(std::string_view key, double fallback);      // > 0
  double non_negative(std::string_view key, double fallback);  // >= 0
  int integer(std::string_view key, int fallback, int lo, int hi);
  bool boolean(std::string_view key, bool fallback);
  std::string string(std::string_view key, const std::string& fallback);
  std::optional<std::string> opt_string(std::string_view key);
  // Text to be drawn: checked against the label markup (rich_text.hpp).
  std::string label(std::string_view key, const std::string& fallback);
  std::optional<std::string> opt_label(std::string_view key);
  std::vector<std::string> labels(std::string_view key);
  // One of `choices`; returns its index.
  int choice(std::string_view key, const std::vector<std::string>& choices, int fallback);
  Color color(std::string_view key, Color fallback);
  std::optional<Color> opt_color(std::string_view key);
  std::vector<Color> colors(std::string_view key);
  std::vector<double> numbers(std::string_view key);  // [] if absent
  std::vector<std::string> strings(std::string_view key);
  std::optional<Vec2> opt_point(std::string_view key);
  // [[x,y], ...]; [] if absent. With set_data(): also KEY_file = "x.csv" and KEY = "NAME" of
  // [data] (spec_data.hpp), as the source reads them, and has(KEY) is true when KEY_file is there.
  std::vector<Vec2> points(std::string_view key);
  void set_data(const PointSource* data) { data_ = data; }
  // Keys that must be there: fail with `missing` when they are not.
  Vec2 required_point(std::string_view key, const std::string& missing);
  std::string required_label(std::string_view key, const std::string& missing);
  std::vector<std::vector<double>> matrix(std::string_view key);  // rows of numbers

  // Sub-tables: [key] (at most one) or [[key]] (any number), in document order.
  std::vector<const toml::table*> tables(std::string_view key);
  // Calls read(sub, table) for each of them, `sub` reading the table under the key path
  // "KEY" ([key]) or "KEY[i]" ([[key]]) below this one; then sub.finish() rejects the keys
  // that read() never asked for.
  template <class F>
  void each_table(std::string_view key, F&& read) {
    const toml::node* n = node(key);
    const bool single = n && n->is_table();
    int i = 0;
    for (const toml::table* t : tables(key)) {
      TableReader sub(*t, file_, single ? key_path(key) : key_path(key) + "[" + std::to_string(i++) + "]");
      sub.set_data(data_);
      sub.set_text_units(px_per_size_unit_, text_size_);
      read(sub, *t);
      sub.finish();
    }
  }

  // Throws for the first key that was never read.
  void finish() const;

  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  [[noreturn]] void fail_at(const toml::node& node, std::string_view key, const std::string& message) const;
  // Fails at `node` if the string `s` read from it holds a NUL.
  void check_no_nul(const toml::node& node, std::string_view key, const std::string& s) const;
  SpecLocation where() const;  // the table's file and line, no key
  std::string key_path(std::string_view key) const;
  // The key's place (its line, else the table's; `key` empty: the table itself), the prefix of
  // fail(key, ...): for checks made after loading.
  SpecLocation origin(std::string_view key) const;
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

  // The stroke keys shared by every stroked element: width, join, miter_limit, cap, dash,
  // dash_offset. `width` must be >= 0 (0 draws nothing).
  render::StrokeStyle stroke(render::StrokeStyle fallback);
  // A text's font keys; the size, when given, is in the figure's unit of font size (points with
  // a print width, else pixels) and comes back in pixels at 1x.
  Font font(Font fallback, std::string_view size_key = "size", std::string_view color_key = "color");
  // A font size key of the figure's unit (as font() reads `size`), in pixels at 1x; `fallback`
  // is in pixels already. At most kMaxFontSize pixels.
  double font_size(std::string_view key, double fallback);
  // Pixels at 1x per unit of a font size key (1, or pixels per point with a print width), and the
  // size in pixels of a text item without one (TextSizes::text); sub-tables inherit them.
  void set_text_units(double px_per_size_unit, double text_size) {
    px_per_size_unit_ = px_per_size_unit;
    text_size_ = text_size;
  }
  double text_size() const { return text_size_; }
  // "sans" | "serif" | "mono".
  render::FontFamily font_family(std::string_view key, render::FontFamily fallback);
  TextAnchor anchor(TextAnchor fallback);

 private:
  double to_number(const toml::node& n, std::string_view key) const;
  Vec2 to_point(const toml::node& n, std::string_view key) const;
  const toml::table& table_;
  std::string file_, path_;
  std::set<std::string, std::less<>> used_;
  const PointSource* data_ = nullptr;
  double px_per_size_unit_ = 1, text_size_ = TextSizes{}.text;
};

// `file` and the line where `where` begins (none when the parser gave none).
SpecLocation location_of(const std::string& file, const toml::source_region& where);

// Checks that a spec's text is valid UTF-8 before it is parsed; on the first invalid byte,
// "FILE:LINE: KEY: invalid UTF-8 (byte 0xNN at column C)", KEY the dotted key whose value
// holds it (its table's header and the key on that or an earlier line). Empty when valid.
std::string utf8_problem(std::string_view text, const std::string& file);

// Checks, before the TOML parser sees it, that no dotted key, table header or chain of dotted
// atoms in `text` has more than kMaxKeyParts parts: the parser builds (and the document frees)
// one nested table per part, recursively, so 50000 parts overflowed the stack. Strings and
// comments are skipped as TOML reads them; a number such as 1.5 counts as two parts, well within
// the limit. "FILE:LINE: a dotted key of more than 64 parts" on the first such chain, else empty.
// Arrays and inline tables (and table headers' brackets) open inside each other more than
// kMaxValueNesting deep are refused too: the parser recurses into each, a few KiB of stack a
// level, and 150 inline tables (toml++ allows 256) overflowed a 256 KiB stack.
std::string key_depth_problem(std::string_view text, const std::string& file);

}  // namespace splinefig::figures::detail
