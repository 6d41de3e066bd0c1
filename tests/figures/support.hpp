#pragma once
// Helpers for the figures tests: running the CLI, a small JSON reader for index.json, PNG
// pixels as 8-bit sRGB, and data-to-pixel maps read from index.json (docs/figures.md).
#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace figtest {

namespace fs = std::filesystem;

struct Result {
  int code = -1;
  std::string out;  // stdout and stderr
};

// Runs a shell command, capturing stdout and stderr together.
inline Result run(const std::string& command) {
  Result r;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen((command + " 2>&1").c_str(), "r"), ::pclose);
  if (!pipe) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe.get())) > 0) r.out.append(buf, n);
  int status = ::pclose(pipe.release());
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline std::string exe() { return SPLINEFIG_EXE; }

// A fresh directory under the build tree for one test.
inline fs::path scratch(const std::string& name) {
  fs::path d = fs::path(SPLINEFIG_BINARY_DIR) / "test-figures" / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// ---- A small JSON reader (objects, arrays, strings, numbers, true/false/null) ----------
struct Json {
  enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
  bool boolean = false;
  double number = 0;
  std::string string;
  std::vector<Json> array;
  std::map<std::string, Json> object;

  const Json& operator[](const std::string& k) const {
    auto it = object.find(k);
    if (it == object.end()) throw std::runtime_error("json: no key " + k);
    return it->second;
  }
  const Json& operator[](size_t i) const { return array.at(i); }
  bool has(const std::string& k) const { return object.count(k) > 0; }
  size_t size() const { return type == Type::Array ? array.size() : object.size(); }
};

class JsonParser {
 public:
  explicit JsonParser(const std::string& s) : s_(s) {}
  Json parse() {
    Json v = value();
    ws();
    if (i_ != s_.size()) fail("trailing characters");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& m) { throw std::runtime_error("json: " + m + " at " + std::to_string(i_)); }
  void ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    ws();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  std::string str() {
    if (!eat('"')) fail("expected a string");
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c == '\\') {
        char e = s_.at(i_++);
        switch (e) {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case 'r': out += '\r'; break;
          case 'u': out += static_cast<char>(std::stoi(s_.substr(i_, 4), nullptr, 16)); i_ += 4; break;
          default: out += e;
        }
      } else {
        out += c;
      }
    }
    if (!eat('"')) fail("unterminated string");
    return out;
  }
  Json value() {
    ws();
    Json v;
    if (i_ >= s_.size()) fail("unexpected end");
    char c = s_[i_];
    if (c == '{') {
      ++i_;
      v.type = Json::Type::Object;
      if (eat('}')) return v;
      do {
        std::string k = str();
        if (!eat(':')) fail("expected :");
        v.object[k] = value();
      } while (eat(','));
      if (!eat('}')) fail("expected }");
    } else if (c == '[') {
      ++i_;
      v.type = Json::Type::Array;
      if (eat(']')) return v;
      do v.array.push_back(value());
      while (eat(','));
      if (!eat(']')) fail("expected ]");
    } else if (c == '"') {
      v.type = Json::Type::String;
      v.string = str();
    } else if (s_.compare(i_, 4, "true") == 0) {
      v.type = Json::Type::Bool, v.boolean = true, i_ += 4;
    } else if (s_.compare(i_, 5, "false") == 0) {
      v.type = Json::Type::Bool, i_ += 5;
    } else if (s_.compare(i_, 4, "null") == 0) {
      i_ += 4;
    } else {
      size_t used = 0;
      v.type = Json::Type::Number;
      v.number = std::stod(s_.substr(i_), &used);
      i_ += used;
    }
    return v;
  }
  const std::string& s_;
  size_t i_ = 0;
};

inline Json parse_json(const std::string& text) { return JsonParser(text).parse(); }

// ---- Pixels --------------------------------------------------------------------------------
struct Rgb {
  double r, g, b;
};

struct Png {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> data;
  Rgb at(int x, int y) const {
    const unsigned char* p = &data[(static_cast<size_t>(y) * width + x) * channels];
    return {double(p[0]), double(p[channels > 2 ? 1 : 0]), double(p[channels > 2 ? 2 : 0])};
  }
};

inline Png load_png(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("cannot open " + path.string());
  Png p;
  p.width = in->spec().width;
  p.height = in->spec().height;
  p.channels = in->spec().nchannels;
  p.data.resize(static_cast<size_t>(p.width) * p.height * p.channels);
  in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::UINT8, p.data.data());
  return p;
}

inline Rgb hex(const std::string& h) {
  unsigned v = static_cast<unsigned>(std::stoul(h.substr(1, 6), nullptr, 16));
  return {double((v >> 16) & 255), double((v >> 8) & 255), double(v & 255)};
}

inline double distance(Rgb a, Rgb b) { return std::sqrt((a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) + (a.b - b.b) * (a.b - b.b)); }

// How much of colour c (over white) pixel p shows: 1 = exactly c, 0 = white. Estimated in
// sRGB along the line from white to c; good enough for "is the curve here".
inline double share(Rgb p, Rgb c) {
  Rgb w{255, 255, 255};
  double dx = c.r - w.r, dy = c.g - w.g, dz = c.b - w.b, l2 = dx * dx + dy * dy + dz * dz;
  double t = ((p.r - w.r) * dx + (p.g - w.g) * dy + (p.b - w.b) * dz) / l2;
  Rgb q{w.r + t * dx, w.g + t * dy, w.b + t * dz};
  return distance(p, q) > 40 ? 0.0 : t;  // off the line: some other colour
}

// Data -> pixel through an index.json axes entry (docs/conventions.md).
struct AxesMap {
  double left, top, right, bottom, x0, x1, y0, y1;
  explicit AxesMap(const Json& axes) {
    left = axes["pixel_box"][0].number, top = axes["pixel_box"][1].number;
    right = axes["pixel_box"][2].number, bottom = axes["pixel_box"][3].number;
    x0 = axes["x_range"][0].number, x1 = axes["x_range"][1].number;
    y0 = axes["y_range"][0].number, y1 = axes["y_range"][1].number;
  }
  double px(double x) const { return left + (x - x0) / (x1 - x0) * (right - left); }
  double py(double y) const { return bottom + (y - y0) / (y1 - y0) * (top - bottom); }
};

// Renders the named built-in figures with the CLI into a fresh directory; returns it.
inline fs::path render_builtin(const std::string& test, const std::vector<std::string>& names, const std::string& extra = "") {
  fs::path dir = scratch(test);
  std::string cmd = exe() + " figures --out " + dir.string() + " " + extra;
  for (const auto& n : names) cmd += " --only " + n;
  Result r = run(cmd);
  if (r.code != 0) throw std::runtime_error("figures failed: " + r.out);
  return dir;
}

inline const Json& figure(const Json& index, const std::string& name) {
  for (const auto& f : index["figures"].array)
    if (f["name"].string == name) return f;
  throw std::runtime_error("no figure " + name + " in index.json");
}

}  // namespace figtest
