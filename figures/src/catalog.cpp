// Built-in spec lookup, index.json and the gallery page.
#include <splinefig/figures/catalog.hpp>
#include <splinefig/image/atomic_file.hpp>
#include <splinefig/vector/vector.hpp>

#include "text/rich_text.hpp"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <cstring>
#include <thread>

namespace fs = std::filesystem;

namespace splinefig::figures {

std::string builtin_specs_dir() {
  if (const char* env = std::getenv("SPLINEFIG_SPECS_DIR"); env && *env) return env;
  std::vector<fs::path> candidates;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    // An installed (or relocated) tree, or the build tree: bin/splinefig (cli/splinefig) next
    // to share/splinefig/specs.
    candidates.push_back(exe.parent_path().parent_path() / SPLINEFIG_DATADIR / "splinefig" / "specs");
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

}  // namespace

std::vector<SpecFile> list_specs(const std::string& dir) {
  std::vector<std::pair<double, SpecFile>> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    // A .toml that cannot be followed (a symlink loop, a dangling link) is kept: loading it
    // gives its one-line error, as for any spec that cannot be read.
    std::error_code status_error;
    const bool regular = e.is_regular_file(status_error);
    if (e.path().extension() != ".toml" || (!regular && !status_error)) continue;
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
      for (const SeriesInfo& si : ax.series) {
        Json entry = {{"label", si.label}, {"color", si.color}, {"kind", si.kind}, {"line", si.line}, {"dash", si.dash}};
        if (!si.marker.empty()) entry["marker"] = si.marker;
        if (si.piece) entry["piece"] = true;
        series.push_back(std::move(entry));
      }
      axes.push_back({{"pixel_box", ax.pixel_box},
                      {"x_range", ax.x_range},
                      {"y_range", ax.y_range},
                      {"x_scale", scale_name(ax.x_scale)},
                      {"y_scale", scale_name(ax.y_scale)},
                      {"series", std::move(series)}});
    }
    Json entry = {{"name", f.name},
                  {"title", f.title},
                  {"caption", f.caption},
                  {"source", f.source},
                  {"files", f.files},
                  {"width", f.width},
                  {"height", f.height},
                  {"axes", std::move(axes)}};
    if (f.pixel_exact) entry["pixel_exact"] = true;
    if (!f.animation.file.empty())
      entry["animation"] = {{"file", f.animation.file},
                            {"width", f.animation.width},
                            {"height", f.animation.height},
                            {"frames", f.animation.frames},
                            {"alt", f.animation.alt}};
    list.push_back(std::move(entry));
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
      info.source = f.value("source", std::string());  // absent in an index written before the key
      info.files = f.at("files").get<std::vector<std::string>>();
      info.width = f.at("width").get<int>();
      info.height = f.at("height").get<int>();
      info.pixel_exact = f.value("pixel_exact", false);
      if (const auto a = f.find("animation"); a != f.end()) {  // a figure with [animation]
        info.animation.file = a->at("file").get<std::string>();
        info.animation.width = a->at("width").get<int>();
        info.animation.height = a->at("height").get<int>();
        info.animation.frames = a->at("frames").get<int>();
        info.animation.alt = a->at("alt").get<std::string>();
      }
      for (const Json& a : f.at("axes")) {
        AxesInfo ax;
        ax.pixel_box = numbers_of<4>(a, "pixel_box");
        ax.x_range = numbers_of<2>(a, "x_range");
        ax.y_range = numbers_of<2>(a, "y_range");
        ax.x_scale = scale_of(a, "x_scale");
        ax.y_scale = scale_of(a, "y_scale");
        for (const Json& s : a.at("series")) {
          SeriesInfo si{s.at("label").get<std::string>(), s.at("color").get<std::string>(), s.at("kind").get<std::string>()};
          si.line = s.value("line", true);
          si.dash = s.value("dash", std::vector<double>{});
          si.marker = s.value("marker", std::string{});
          si.piece = s.value("piece", false);
          ax.series.push_back(std::move(si));
        }
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

std::vector<FigureInfo> read_index_file(const std::string& dir, const std::function<void(const std::string&)>& warn) {
  const std::string path = (fs::path(dir) / "index.json").string();
  auto refuse = [&](const std::string& why) {
    if (warn) warn(path + ": " + why + "; writing a new one with the figures rendered now");
    return std::vector<FigureInfo>{};
  };
  // Opened without blocking (a FIFO put there must not stall the run) and checked on the
  // descriptor, so that what is read is what was checked.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    if (errno == ENOENT) return {};
    return refuse(std::string("cannot read it (") + std::strerror(errno) + ")");
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st{};
  if (::fstat(fd, &st) != 0) return refuse(std::string("cannot read it (") + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode))
    return refuse(S_ISDIR(st.st_mode) ? "a directory, not a file" : "not a regular file (a FIFO, socket or device)");
  if (static_cast<unsigned long long>(st.st_size) > kMaxIndexBytes)
    return refuse("has " + std::to_string(st.st_size) + " bytes, over the limit of 64 MiB");
  std::string text;
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return refuse(std::string("cannot read it (") + std::strerror(errno) + ")");
    if (n == 0) break;
    text.append(buf, static_cast<std::size_t>(n));
    if (text.size() > kMaxIndexBytes) return refuse("grew over the limit of 64 MiB while read");
  }
  try {
    return read_index_json(text);
  } catch (const std::exception& e) {
    return refuse(std::string("not an index (") + e.what() + ")");
  }
}

void update_index(const std::string& dir, const std::vector<FigureInfo>& rendered, const std::vector<SpecFile>& specs,
                  const std::function<bool(const FigureInfo&)>& keep, const GalleryOptions& gallery,
                  const std::function<void(const std::string&)>& warn) {
  const std::string lock_path = (fs::path(dir) / ".index.lock").string();
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY, 0644);
  if (fd < 0) throw std::runtime_error(lock_path + ": cannot open the index lock (" + std::strerror(errno) + ")");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }  // releases the lock
  } closer{fd};
  // Another run merges in a few milliseconds; one that holds the lock for a minute is stuck.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK && errno != EINTR)
      throw std::runtime_error(lock_path + ": cannot lock the index (" + std::strerror(errno) + ")");
    if (std::chrono::steady_clock::now() > give_up)
      throw std::runtime_error(lock_path + ": another process has held the index lock for 60 s");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::vector<FigureInfo> index = rendered;
  if (keep) {
    std::vector<FigureInfo> kept = read_index_file(dir, warn);
    std::erase_if(kept, [&](const FigureInfo& f) { return !keep(f); });
    index = merge_index(kept, rendered, specs, dir);
  }
  write_text_file((fs::path(dir) / "index.json").string(), index_json(index));
  write_text_file((fs::path(dir) / "index.html").string(), gallery_html(index, gallery));
}

bool plain_file_name(std::string_view name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (const char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '/' || c == '\\' || c < 0x20 || c == 0x7f) return false;
  }
  return true;
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
      if (!plain_file_name(file) || !fs::is_regular_file(fs::symlink_status(fs::path(dir) / file, ec))) return false;
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

namespace {

// Text for the page: control characters (a NUL, ESC, C1 controls; not tab and newline), which
// HTML forbids and a terminal viewing the file would obey, as U+FFFD, then escaped.
std::string html_text(std::string_view s) {
  std::string clean;
  clean.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const bool c1 = c == 0xc2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(s[i + 1]) <= 0x9f;
    if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7f || c1) {
      clean += "\xef\xbf\xbd";
      if (c1) ++i;
    } else {
      clean += s[i];
    }
  }
  return vector::xml_escape(clean);
}

}  // namespace

std::string markup_html(const std::string& markup) {
  if (!detail::markup_problem(markup).empty()) return html_text(markup);
  const double size = 10;
  const detail::RichText rt = detail::set_text(markup, size, [](const std::string& t, double, bool) {
    return render::TextExtent{static_cast<double>(t.size()), 1, 1};
  });
  std::string out;
  for (const detail::Run& r : rt.runs) {
    std::string t = html_text(r.text);
    if (r.italic) t = "<i>" + t + "</i>";
    if (r.size < size && r.dy > 0) t = "<sub>" + t + "</sub>";
    else if (r.size < size && r.dy < 0) t = "<sup>" + t + "</sup>";
    out += t;
  }
  return out;
}

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string file_with(const FigureInfo& f, const std::string& ext) {
  for (const auto& file : f.files)
    if (ends_with(file, ext)) return file;
  return "";
}

// A file name of the directory as a relative URL: every byte but letters, digits and -._~
// percent-encoded, so that '#', '?', '%', spaces and commas (srcset) stay part of the name.
std::string file_url(std::string_view name) {
  static constexpr char hex[] = "0123456789ABCDEF";
  std::string out;
  for (const char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
      out += ch;
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

constexpr int kWideCardPixels = 1000;

// A card that takes a whole row of the two-column grid: a pixel-exact figure (wider than a
// column at its pixel size) or one drawn wider than the usual 800 px.
bool wide_card(const FigureInfo& f) { return f.pixel_exact || f.width >= kWideCardPixels; }

// The cards of a section in the order the two-column grid fills without an empty cell between
// cards: a wide card that comes while a row holds one card waits until the next card completes
// that row; if none does, the row's lone card goes after the wide ones, to the section's end.
std::vector<const FigureInfo*> packed(const std::vector<const FigureInfo*>& cards) {
  std::vector<const FigureInfo*> out, held;
  bool open = false;  // the current row holds one card
  for (const FigureInfo* f : cards) {
    if (wide_card(*f)) {
      (open ? held : out).push_back(f);
      continue;
    }
    out.push_back(f);
    open = !open;
    if (!open) {
      out.insert(out.end(), held.begin(), held.end());
      held.clear();
    }
  }
  if (!held.empty()) {  // `open`: the last card of `out` is the row's lone card
    const FigureInfo* lone = out.back();
    out.back() = held.front();
    out.insert(out.end(), held.begin() + 1, held.end());
    out.push_back(lone);
  }
  return out;
}

void figure_html(std::ostringstream& o, const FigureInfo& f) {
  std::string png = file_with(f, ".png"), svg = file_with(f, ".svg");
  const std::string shown = png.empty() ? (svg.empty() ? (f.files.empty() ? "" : f.files.front()) : svg) : png;
  // A pixel-exact figure is shown from its PNG, one image pixel to one CSS pixel.
  const bool exact = f.pixel_exact && !png.empty();
  const std::string title = html_text(f.title.empty() ? f.name : f.title);
  std::string classes = exact ? "pixel-exact" : "";
  if (wide_card(f)) classes += classes.empty() ? "wide" : " wide";
  o << "<figure id=\"" << html_text(f.name) << "\"" << (classes.empty() ? "" : " class=\"" + classes + "\"")
    << ">\n  <div class=\"frame\"><a href=\"" << file_url(shown) << "\"><img src=\"" << file_url(shown) << "\"";
  // The vector file is the sharp source on high-density screens; a pixel-exact figure keeps its pixels.
  if (!exact && !svg.empty() && !png.empty()) o << " srcset=\"" << file_url(png) << " 1x, " << file_url(svg) << " 2x\"";
  // The alt text describes the picture for a reader who cannot see it: its title and caption.
  const std::string alt = f.caption.empty() ? title : title + ": " + html_text(detail::plain_text(f.caption));
  o << " width=\"" << f.width << "\" height=\"" << f.height << "\" alt=\"" << alt << "\"></a></div>\n";
  // The figure's animation (an animated WebP of its filmstrips) under the still, with its own alt text.
  if (!f.animation.file.empty())
    o << "  <div class=\"frame animation\"><a href=\"" << file_url(f.animation.file) << "\"><img src=\""
      << file_url(f.animation.file) << "\" width=\"" << f.animation.width << "\" height=\"" << f.animation.height
      << "\" alt=\"" << html_text(f.animation.alt) << "\"></a></div>\n";
  o << "  <figcaption><b>" << title << "</b>";
  if (!f.source.empty()) o << "<span class=\"source\">" << html_text(f.source) << "</span>";
  o << " " << markup_html(f.caption);
  if (exact)
    o << " <span class=\"exact\">Shown pixel for pixel (" << f.width << " &times; " << f.height
      << "); on a narrow screen it scrolls sideways, or <a href=\"" << file_url(png) << "\">open the PNG</a>.</span>";
  o << "\n    <span class=\"files\">";
  for (const auto& file : f.files) {
    const auto dot = file.find_last_of('.');
    std::string label = dot == std::string::npos ? file : file.substr(dot + 1);
    std::transform(label.begin(), label.end(), label.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    o << "<a href=\"" << file_url(file) << "\">" << html_text(label) << "</a>";
  }
  o << "</span></figcaption>\n</figure>\n";
}

}  // namespace

std::string gallery_html(const std::vector<FigureInfo>& figures, const GalleryOptions& options) {
  std::ostringstream o;
  o << R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>splinefig figures</title>
<style>
  * { box-sizing: border-box; }
  body { font-family: "DejaVu Sans", sans-serif; color: #1a1a1a; background: #f4f4f4; margin: 0;
         padding: clamp(8px, 2.5vw, 32px); line-height: 1.45; }
  header, section, footer { max-width: 1880px; margin: 0 auto; }
  h1 { font-size: clamp(20px, 3vw, 28px); margin: 0 0 4px; }
  h2 { font-size: clamp(17px, 2.2vw, 22px); margin: 28px 0 12px; border-bottom: 1px solid #ccc; padding-bottom: 4px; }
  nav a { margin-right: 14px; color: #1f5f99; }
  /* One column on phones and narrow windows, two from 950 px; a wide card takes a whole row
     (the generator orders the cards so that none leaves an empty cell before it). */
  .grid { display: grid; grid-template-columns: minmax(0, 1fr); gap: clamp(10px, 2vw, 24px); }
  @media (min-width: 950px) {
    .grid { grid-template-columns: repeat(2, minmax(0, 1fr)); }
    figure.wide { grid-column: 1 / -1; }
  }
  figure { margin: 0; background: #fff; border: 1px solid #ddd; padding: clamp(6px, 1.5vw, 12px); min-width: 0; }
  figure img { width: 100%; height: auto; display: block; }
  figure.wide img { width: auto; max-width: 100%; margin: 0 auto; }
  figure .animation { margin-top: 8px; }
  /* Pixel-exact: never resampled (one image pixel, one CSS pixel); scrolls sideways when wider. */
  figure.pixel-exact .frame:first-child { overflow-x: auto; }
  figure.pixel-exact .frame:first-child img { width: auto; max-width: none; image-rendering: pixelated; }
  figcaption .exact { display: block; margin-top: 4px; font-size: 13px; color: #555; }
  figcaption { font-size: 14px; margin-top: 8px; overflow-wrap: anywhere; }
  figcaption b { display: block; margin-bottom: 2px; }
  figcaption .source { display: block; margin-bottom: 4px; font-size: 13px; color: #555; font-style: italic; }
  .files { display: block; margin-top: 6px; font-size: 12px; }
  .files a { margin-right: 10px; color: #1f5f99; }
  footer { margin-top: 28px; font-size: 12px; color: #666; }
</style>
</head>
<body>
<header>
<h1>splinefig figures</h1>
)";
  struct Section {
    const char* id;
    const char* title;
    std::vector<const FigureInfo*> figures;
  };
  Section sections[3] = {{"memo", "The spline tutorial notes", {}}, {"filters", "Filters", {}},
                         {"companions", "Companion texts", {}}};
  for (const FigureInfo& f : figures) {
    const int k = f.name.rfind("filter-", 0) == 0 ? 1 : f.name.rfind("s00", 0) == 0 ? 2 : 0;
    sections[k].figures.push_back(&f);
  }
  o << "<nav>";
  for (const Section& s : sections)
    if (!s.figures.empty()) o << "<a href=\"#" << s.id << "\">" << s.title << "</a>";
  o << "</nav>\n</header>\n";
  for (const Section& s : sections) {
    if (s.figures.empty()) continue;
    o << "<section id=\"" << s.id << "\">\n<h2>" << s.title << "</h2>\n<div class=\"grid\">\n";
    for (const FigureInfo* f : packed(s.figures)) figure_html(o, *f);
    o << "</div>\n</section>\n";
  }
  o << "<footer>splinefig";
  if (!options.version.empty()) o << " " << html_text(options.version);
  if (options.date >= 0) {
    const std::time_t t = static_cast<std::time_t>(options.date);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[16];
    std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
    o << " &middot; " << buf;
  }
  o << R"(</footer>
<script>
  window.addEventListener("load", function () {
    var ok = true;
    document.querySelectorAll("img").forEach(function (img) {
      var loaded = img.complete && img.naturalWidth > 0;
      img.setAttribute("data-loaded", loaded ? "yes" : "no");
      ok = ok && loaded;
    });
    document.body.setAttribute("data-images-ok", ok ? "yes" : "no");
    var wide = document.documentElement.scrollWidth > document.documentElement.clientWidth;
    document.body.setAttribute("data-overflow", wide ? "yes" : "no");
    // The most cards side by side in any section (the page shows at most two).
    var columns = 0;
    document.querySelectorAll(".grid").forEach(function (grid) {
      var lefts = {};
      grid.querySelectorAll('figure:not(.wide)').forEach(function (f) { lefts[Math.round(f.getBoundingClientRect().left)] = 1; });
      columns = Math.max(columns, Object.keys(lefts).length);
    });
    document.body.setAttribute("data-columns", String(columns));
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
