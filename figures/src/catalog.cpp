// Built-in spec lookup, index.json and the gallery page.
#include <splinefig/figures/catalog.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;

namespace splinefig::figures {

std::string builtin_specs_dir() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("SPLINEFIG_SPECS_DIR"); env && *env) return env;
#ifdef SPLINEFIG_SPECS_DIR
  candidates.emplace_back(SPLINEFIG_SPECS_DIR);
#endif
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "splinefig" / "specs");
#ifdef SPLINEFIG_INSTALLED_SPECS_DIR
  candidates.emplace_back(SPLINEFIG_INSTALLED_SPECS_DIR);
#endif
  for (const auto& c : candidates)
    if (fs::is_directory(c, ec)) return c.string();
  return {};
}

namespace {

// The spec's `order = N` line if it has one (a cheap scan: the full parse comes later).
double spec_order(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("[", 0) == 0) break;  // top-level keys come before the first table
    if (line.rfind("order", 0) == 0) {
      auto eq = line.find('=');
      if (eq != std::string::npos) {
        char* end = nullptr;
        double v = std::strtod(line.c_str() + eq + 1, &end);
        if (end != line.c_str() + eq + 1 && std::isfinite(v)) return v;
      }
    }
  }
  return 1e9;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest form that reads back the same
  return std::string(buf, r.ptr);
}

const char* scale_name(Scale s) { return s == Scale::Log ? "log" : s == Scale::Decibel ? "db" : "linear"; }

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::vector<SpecFile> list_specs(const std::string& dir) {
  std::vector<std::pair<double, SpecFile>> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (!e.is_regular_file() || e.path().extension() != ".toml") continue;
    found.push_back({spec_order(e.path()), {e.path().stem().string(), e.path().string()}});
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second.name < b.second.name;
  });
  std::vector<SpecFile> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

std::string index_json(const std::vector<FigureInfo>& figures) {
  std::ostringstream o;
  auto arr = [&](auto begin, auto end) {
    o << "[";
    for (auto it = begin; it != end; ++it) o << (it == begin ? "" : ", ") << json_number(*it);
    o << "]";
  };
  o << "{\n  \"figures\": [";
  for (size_t i = 0; i < figures.size(); ++i) {
    const FigureInfo& f = figures[i];
    o << (i ? "," : "") << "\n    {\n";
    o << "      \"name\": " << json_string(f.name) << ",\n";
    o << "      \"title\": " << json_string(f.title) << ",\n";
    o << "      \"caption\": " << json_string(f.caption) << ",\n";
    o << "      \"files\": [";
    for (size_t k = 0; k < f.files.size(); ++k) o << (k ? ", " : "") << json_string(f.files[k]);
    o << "],\n";
    o << "      \"width\": " << f.width << ",\n      \"height\": " << f.height << ",\n";
    o << "      \"axes\": [";
    for (size_t a = 0; a < f.axes.size(); ++a) {
      const AxesInfo& ax = f.axes[a];
      o << (a ? "," : "") << "\n        {\"pixel_box\": ";
      arr(ax.pixel_box.begin(), ax.pixel_box.end());
      o << ", \"x_range\": ";
      arr(ax.x_range.begin(), ax.x_range.end());
      o << ", \"y_range\": ";
      arr(ax.y_range.begin(), ax.y_range.end());
      o << ", \"x_scale\": \"" << scale_name(ax.x_scale) << "\", \"y_scale\": \"" << scale_name(ax.y_scale) << "\",\n";
      o << "         \"series\": [";
      for (size_t s = 0; s < ax.series.size(); ++s) {
        const SeriesInfo& si = ax.series[s];
        o << (s ? ", " : "") << "{\"label\": " << json_string(si.label) << ", \"color\": " << json_string(si.color)
          << ", \"kind\": " << json_string(si.kind) << "}";
      }
      o << "]}";
    }
    o << (f.axes.empty() ? "]\n" : "\n      ]\n") << "    }";
  }
  o << "\n  ]\n}\n";
  return o.str();
}

namespace {

// A JSON value: just what index.json holds.
struct JsonValue {
  enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
  double number = 0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;
};

class JsonReader {
 public:
  explicit JsonReader(const std::string& text) : s_(text) {}
  JsonValue document() {
    JsonValue v = value(0);
    space();
    if (i_ != s_.size()) fail("text after the end");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("index.json: " + what + " at byte " + std::to_string(i_));
  }
  void space() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t')) ++i_;
  }
  bool take(char c) {
    space();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  std::string text() {
    if (!take('"')) fail("expected a string");
    std::string out;
    while (true) {
      if (i_ >= s_.size()) fail("unterminated string");
      char c = s_[i_++];
      if (c == '"') return out;
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= s_.size()) fail("unterminated string");
      char e = s_[i_++];
      switch (e) {
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': {
          if (i_ + 4 > s_.size()) fail("bad \\u escape");
          unsigned code = 0;
          auto r = std::from_chars(s_.data() + i_, s_.data() + i_ + 4, code, 16);
          if (r.ptr != s_.data() + i_ + 4 || code >= 0x80) fail("unsupported \\u escape");
          out += static_cast<char>(code);
          i_ += 4;
          break;
        }
        default: out += e;
      }
    }
  }
  JsonValue value(int depth) {
    if (depth > 16) fail("nested too deeply");
    space();
    if (i_ >= s_.size()) fail("unexpected end");
    JsonValue v;
    const char c = s_[i_];
    if (c == '{') {
      ++i_;
      v.type = JsonValue::Type::Object;
      if (take('}')) return v;
      do {
        std::string key = text();
        if (!take(':')) fail("expected ':'");
        v.object.emplace_back(std::move(key), value(depth + 1));
      } while (take(','));
      if (!take('}')) fail("expected '}'");
    } else if (c == '[') {
      ++i_;
      v.type = JsonValue::Type::Array;
      if (take(']')) return v;
      do v.array.push_back(value(depth + 1));
      while (take(','));
      if (!take(']')) fail("expected ']'");
    } else if (c == '"') {
      v.type = JsonValue::Type::String;
      v.string = text();
    } else if (s_.compare(i_, 4, "null") == 0) {
      i_ += 4;
    } else if (s_.compare(i_, 4, "true") == 0 || s_.compare(i_, 5, "false") == 0) {
      v.type = JsonValue::Type::Bool;
      i_ += s_[i_] == 't' ? 4 : 5;
    } else {
      v.type = JsonValue::Type::Number;
      auto r = std::from_chars(s_.data() + i_, s_.data() + s_.size(), v.number);
      if (r.ec != std::errc()) fail("expected a value");
      i_ = static_cast<size_t>(r.ptr - s_.data());
    }
    return v;
  }
  const std::string& s_;
  size_t i_ = 0;
};

const JsonValue& member(const JsonValue& v, const std::string& key) {
  if (v.type != JsonValue::Type::Object) throw std::runtime_error("index.json: expected an object holding \"" + key + "\"");
  for (const auto& [k, m] : v.object)
    if (k == key) return m;
  throw std::runtime_error("index.json: missing \"" + key + "\"");
}

const std::vector<JsonValue>& array_of(const JsonValue& v, const std::string& key) {
  const JsonValue& a = member(v, key);
  if (a.type != JsonValue::Type::Array) throw std::runtime_error("index.json: \"" + key + "\" is not an array");
  return a.array;
}

std::string string_of(const JsonValue& v, const std::string& key) {
  const JsonValue& s = member(v, key);
  if (s.type != JsonValue::Type::String) throw std::runtime_error("index.json: \"" + key + "\" is not a string");
  return s.string;
}

double number_of(const JsonValue& v) {
  if (v.type == JsonValue::Type::Null) return std::numeric_limits<double>::quiet_NaN();  // json_number's non-finite
  if (v.type != JsonValue::Type::Number) throw std::runtime_error("index.json: expected a number");
  return v.number;
}

template <size_t N>
std::array<double, N> numbers_of(const JsonValue& v, const std::string& key) {
  const auto& a = array_of(v, key);
  if (a.size() != N) throw std::runtime_error("index.json: \"" + key + "\" needs " + std::to_string(N) + " numbers");
  std::array<double, N> out{};
  for (size_t i = 0; i < N; ++i) out[i] = number_of(a[i]);
  return out;
}

Scale scale_of(const JsonValue& v, const std::string& key) {
  const std::string s = string_of(v, key);
  if (s == "linear") return Scale::Linear;
  if (s == "log") return Scale::Log;
  if (s == "db") return Scale::Decibel;
  throw std::runtime_error("index.json: \"" + key + "\" is \"" + s + "\", not linear, log or db");
}

}  // namespace

std::vector<FigureInfo> read_index_json(const std::string& text) {
  const JsonValue doc = JsonReader(text).document();
  std::vector<FigureInfo> figures;
  for (const JsonValue& f : array_of(doc, "figures")) {
    FigureInfo info;
    info.name = string_of(f, "name");
    info.title = string_of(f, "title");
    info.caption = string_of(f, "caption");
    for (const JsonValue& file : array_of(f, "files")) {
      if (file.type != JsonValue::Type::String) throw std::runtime_error("index.json: \"files\" holds a non-string");
      info.files.push_back(file.string);
    }
    info.width = static_cast<int>(number_of(member(f, "width")));
    info.height = static_cast<int>(number_of(member(f, "height")));
    for (const JsonValue& a : array_of(f, "axes")) {
      AxesInfo ax;
      ax.pixel_box = numbers_of<4>(a, "pixel_box");
      ax.x_range = numbers_of<2>(a, "x_range");
      ax.y_range = numbers_of<2>(a, "y_range");
      ax.x_scale = scale_of(a, "x_scale");
      ax.y_scale = scale_of(a, "y_scale");
      for (const JsonValue& s : array_of(a, "series"))
        ax.series.push_back({string_of(s, "label"), string_of(s, "color"), string_of(s, "kind")});
      info.axes.push_back(std::move(ax));
    }
    figures.push_back(std::move(info));
  }
  return figures;
}

std::vector<FigureInfo> merge_index(const std::vector<FigureInfo>& previous, const std::vector<FigureInfo>& rendered,
                                    const std::vector<SpecFile>& specs, const std::string& dir) {
  auto named = [](const std::vector<FigureInfo>& list, const std::string& name) -> const FigureInfo* {
    for (const auto& f : list)
      if (f.name == name) return &f;
    return nullptr;
  };
  auto still_there = [&](const FigureInfo& f) {
    if (named(rendered, f.name)) return false;
    std::error_code ec;
    for (const auto& file : f.files)
      if (!fs::is_regular_file(fs::path(dir) / file, ec)) return false;
    return !f.files.empty();
  };
  std::vector<FigureInfo> out;
  auto listed = [&](const std::string& name) {
    return std::any_of(specs.begin(), specs.end(), [&](const SpecFile& s) { return s.name == name; });
  };
  for (const SpecFile& s : specs) {
    if (const FigureInfo* f = named(rendered, s.name)) out.push_back(*f);
    else if (const FigureInfo* p = named(previous, s.name); p && still_there(*p)) out.push_back(*p);
  }
  for (const auto& f : rendered)
    if (!listed(f.name)) out.push_back(f);
  for (const auto& p : previous)
    if (!listed(p.name) && still_there(p) && !named(out, p.name)) out.push_back(p);
  return out;
}

std::string gallery_html(const std::vector<FigureInfo>& figures) {
  std::ostringstream o;
  o << R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>splinefig figures</title>
<style>
  body { font-family: "DejaVu Sans", sans-serif; color: #222; background: #f4f4f4; margin: 0; padding: 24px; }
  h1 { font-size: 22px; font-weight: bold; margin: 0 0 20px; }
  main { display: grid; grid-template-columns: repeat(auto-fill, minmax(420px, 1fr)); gap: 24px; }
  figure { margin: 0; background: #fff; border: 1px solid #ddd; padding: 12px; }
  figure img { width: 100%; height: auto; display: block; }
  figcaption { font-size: 14px; line-height: 1.4; margin-top: 8px; }
  figcaption b { display: block; }
  figcaption code { color: #777; font-size: 12px; }
</style>
</head>
<body>
<h1>splinefig figures</h1>
<main>
)";
  for (const FigureInfo& f : figures) {
    std::string png;
    for (const auto& file : f.files)
      if (file.size() > 4 && file.substr(file.size() - 4) == ".png") png = file;
    if (png.empty() && !f.files.empty()) png = f.files.front();
    o << "<figure id=\"" << html_escape(f.name) << "\">\n  <a href=\"" << html_escape(png) << "\"><img src=\""
      << html_escape(png) << "\" width=\"" << f.width << "\" height=\"" << f.height << "\" alt=\""
      << html_escape(f.title.empty() ? f.name : f.title) << "\"></a>\n  <figcaption><b>"
      << html_escape(f.title.empty() ? f.name : f.title) << "</b>" << html_escape(f.caption) << " <code>"
      << html_escape(f.name) << "</code></figcaption>\n</figure>\n";
  }
  o << R"(</main>
<script>
  window.addEventListener("load", function () {
    var ok = true;
    document.querySelectorAll("img").forEach(function (img) {
      var loaded = img.complete && img.naturalWidth > 0;
      img.setAttribute("data-loaded", loaded ? "yes" : "no");
      ok = ok && loaded;
    });
    document.body.setAttribute("data-images-ok", ok ? "yes" : "no");
  });
</script>
</body>
</html>
)";
  return o.str();
}

void write_text_file(const std::string& path, const std::string& text) {
  fs::path target(path);
  fs::path tmp = target;
  tmp += ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
    out << text;
    out.flush();
    if (!out) {
      out.close();
      fs::remove(tmp);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp);
    throw std::runtime_error("cannot write " + path + ": " + ec.message());
  }
}

}  // namespace splinefig::figures
