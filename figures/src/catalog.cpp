// Built-in spec lookup, index.json and the gallery page.
#include <splinefig/figures/catalog.hpp>
#include <splinefig/image/atomic_file.hpp>

#include <nlohmann/json.hpp>

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

namespace fs = std::filesystem;

namespace splinefig::figures {

std::string builtin_specs_dir() {
  if (const char* env = std::getenv("SPLINEFIG_SPECS_DIR"); env && *env) return env;
  std::vector<fs::path> candidates;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    // An installed (or relocated) tree: bin/splinefig next to share/splinefig/specs.
    candidates.push_back(exe.parent_path().parent_path() / SPLINEFIG_DATADIR / "splinefig" / "specs");
#ifdef SPLINEFIG_SOURCE_SPECS_DIR
    // A program of the build tree uses the specs it was built from; an installed one never
    // looks at the source tree.
    const fs::path build = fs::path(SPLINEFIG_BUILD_DIR).lexically_normal();
    const auto rel = exe.lexically_normal().lexically_relative(build);
    if (!rel.empty() && *rel.begin() != "..") candidates.emplace_back(SPLINEFIG_SOURCE_SPECS_DIR);
#endif
  }
  candidates.emplace_back(SPLINEFIG_INSTALLED_SPECS_DIR);
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

namespace {

using Json = nlohmann::ordered_json;

Scale scale_of(const Json& v, const char* key) {
  const std::string s = v.at(key).get<std::string>();
  if (s == "linear") return Scale::Linear;
  if (s == "log") return Scale::Log;
  if (s == "db") return Scale::Decibel;
  throw std::runtime_error(std::string("\"") + key + "\" is \"" + s + "\", not linear, log or db");
}

// A number as index.json holds it: null for a value that is not finite.
double number_of(const Json& v) {
  return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}

template <size_t N>
std::array<double, N> numbers_of(const Json& v, const char* key) {
  const Json& a = v.at(key);
  if (!a.is_array() || a.size() != N)
    throw std::runtime_error(std::string("\"") + key + "\" needs " + std::to_string(N) + " numbers");
  std::array<double, N> out{};
  for (size_t i = 0; i < N; ++i) out[i] = number_of(a[i]);
  return out;
}

}  // namespace

std::string index_json(const std::vector<FigureInfo>& figures) {
  Json list = Json::array();
  for (const FigureInfo& f : figures) {
    Json axes = Json::array();
    for (const AxesInfo& ax : f.axes) {
      Json series = Json::array();
      for (const SeriesInfo& si : ax.series) series.push_back({{"label", si.label}, {"color", si.color}, {"kind", si.kind}});
      axes.push_back({{"pixel_box", ax.pixel_box},
                      {"x_range", ax.x_range},
                      {"y_range", ax.y_range},
                      {"x_scale", scale_name(ax.x_scale)},
                      {"y_scale", scale_name(ax.y_scale)},
                      {"series", std::move(series)}});
    }
    list.push_back({{"name", f.name},
                    {"title", f.title},
                    {"caption", f.caption},
                    {"files", f.files},
                    {"width", f.width},
                    {"height", f.height},
                    {"axes", std::move(axes)}});
  }
  // Non-finite numbers become null; text that is not UTF-8 is kept readable (U+FFFD).
  return Json{{"figures", std::move(list)}}.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::vector<FigureInfo> read_index_json(const std::string& text) {
  try {
    const Json doc = Json::parse(text);
    std::vector<FigureInfo> figures;
    for (const Json& f : doc.at("figures")) {
      FigureInfo info;
      info.name = f.at("name").get<std::string>();
      info.title = f.at("title").get<std::string>();
      info.caption = f.at("caption").get<std::string>();
      info.files = f.at("files").get<std::vector<std::string>>();
      info.width = f.at("width").get<int>();
      info.height = f.at("height").get<int>();
      for (const Json& a : f.at("axes")) {
        AxesInfo ax;
        ax.pixel_box = numbers_of<4>(a, "pixel_box");
        ax.x_range = numbers_of<2>(a, "x_range");
        ax.y_range = numbers_of<2>(a, "y_range");
        ax.x_scale = scale_of(a, "x_scale");
        ax.y_scale = scale_of(a, "y_scale");
        for (const Json& s : a.at("series"))
          ax.series.push_back(
              {s.at("label").get<std::string>(), s.at("color").get<std::string>(), s.at("kind").get<std::string>()});
        info.axes.push_back(std::move(ax));
      }
      figures.push_back(std::move(info));
    }
    return figures;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("index.json: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("index.json: ") + e.what());
  }
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
  write_file_atomically(path, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
}

}  // namespace splinefig::figures
