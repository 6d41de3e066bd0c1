// Text: UTF-8 decoding, DejaVu face lookup and fallback, HarfBuzz shaping and FreeType glyph
// outlines (see splinefig/renderer/text_outlines.hpp).
//
// Everything is done in font units and scaled afterwards, so one outline and one shaping of a
// string serve every size. HarfBuzz shapes with its own OpenType tables, unhinted (advances and
// kerning exactly as the font's designer gave them); FreeType reads the outlines unscaled and
// unhinted (FT_LOAD_NO_SCALE). The caches hold font-unit data only and are guarded by one
// mutex: FreeType faces are not thread-safe, and layouts are cheap once their strings are
// cached.
#include "text_layout.hpp"

#include <splinefig/renderer/text_outlines.hpp>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_BBOX_H
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

namespace fs = std::filesystem;

namespace splinefig::render {

std::string font_file_name(FontFamily family, FontWeight weight, bool italic) {
  const bool bold = weight == FontWeight::Bold;
  std::string base = family == FontFamily::Serif ? "DejaVuSerif" : family == FontFamily::Mono ? "DejaVuSansMono" : "DejaVuSans";
  const char* slant = family == FontFamily::Serif ? "Italic" : "Oblique";
  if (bold && italic) return base + "-Bold" + slant + ".ttf";
  if (bold) return base + "-Bold.ttf";
  if (italic) return base + "-" + slant + ".ttf";
  return base + ".ttf";
}

std::vector<std::string> font_dirs() {
  std::vector<std::string> dirs;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path own = exe.parent_path().parent_path() / "share" / "splinefig" / "fonts";
    if (fs::is_directory(own, ec)) dirs.push_back(own.string());
  }
  dirs.emplace_back("/usr/share/fonts/truetype/dejavu");
  return dirs;
}

std::string find_font(const std::string& file_name) {
  static std::mutex m;
  static std::map<std::string, std::string> found;  // the file system is asked once per name
  std::lock_guard<std::mutex> lock(m);
  if (auto it = found.find(file_name); it != found.end()) return it->second;
  std::string path;
  std::error_code ec;
  for (const std::string& d : font_dirs()) {
    const fs::path p = fs::path(d) / file_name;
    if (fs::is_regular_file(p, ec)) {
      path = p.string();
      break;
    }
  }
  found[file_name] = path;
  return path;
}

std::vector<std::string> font_fallback(const TextStyle& style) {
  std::vector<std::string> out;
  auto add = [&](const std::string& name) {
    for (const auto& o : out)
      if (o == name) return;
    if (!find_font(name).empty()) out.push_back(name);
  };
  const FontFamily order[] = {style.family, FontFamily::Sans, FontFamily::Serif, FontFamily::Mono};
  for (FontFamily f : order) {
    add(font_file_name(f, style.weight, style.italic));
    add(font_file_name(f, style.weight, false));
    add(font_file_name(f, FontWeight::Normal, false));
  }
  add("DejaVuMathTeXGyre.ttf");
  return out;
}

namespace detail {
namespace {

[[noreturn]] void bad(const std::string& what) { throw DrawError(what); }

struct CodePoint {
  char32_t c;
  std::size_t byte;  // offset of its first byte
  std::size_t len;   // its bytes
};

// Strict UTF-8 (RFC 3629): no overlong forms, no surrogates, nothing above U+10FFFF.
std::vector<CodePoint> decode_utf8(std::string_view s) {
  std::vector<CodePoint> out;
  out.reserve(s.size());
  std::size_t i = 0;
  while (i < s.size()) {
    const auto b0 = static_cast<unsigned char>(s[i]);
    std::size_t n;
    char32_t c, min;
    if (b0 < 0x80) { n = 1; c = b0; min = 0; }
    else if ((b0 & 0xE0) == 0xC0) { n = 2; c = b0 & 0x1F; min = 0x80; }
    else if ((b0 & 0xF0) == 0xE0) { n = 3; c = b0 & 0x0F; min = 0x800; }
    else if ((b0 & 0xF8) == 0xF0) { n = 4; c = b0 & 0x07; min = 0x10000; }
    else bad("text: invalid UTF-8 at byte " + std::to_string(i));
    if (i + n > s.size()) bad("text: invalid UTF-8 at byte " + std::to_string(i) + " (a truncated sequence)");
    for (std::size_t k = 1; k < n; ++k) {
      const auto b = static_cast<unsigned char>(s[i + k]);
      if ((b & 0xC0) != 0x80) bad("text: invalid UTF-8 at byte " + std::to_string(i + k));
      c = (c << 6) | (b & 0x3F);
    }
    if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF))
      bad("text: invalid UTF-8 at byte " + std::to_string(i));
    out.push_back({c, i, n});
    i += n;
  }
  return out;
}

std::string code_name(char32_t c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
  return buf;
}

struct ShapedGlyph {
  std::uint32_t id;
  double advance, dx, dy;  // font units, y up
  std::uint32_t cluster;   // HarfBuzz's cluster: the byte of the run where the glyph's characters start
};

struct Face {
  std::string name;
  FT_Face ft = nullptr;
  hb_blob_t* blob = nullptr;
  hb_face_t* hb_face = nullptr;
  hb_font_t* hb_font = nullptr;
  double upem = 2048;
  std::unordered_map<std::uint32_t, std::unique_ptr<GlyphOutline>> outlines;
  std::unordered_map<std::string, std::shared_ptr<const std::vector<ShapedGlyph>>> shaped;
  std::unordered_map<char32_t, bool> has;
  ~Face() {
    if (hb_font) hb_font_destroy(hb_font);
    if (hb_face) hb_face_destroy(hb_face);
    if (blob) hb_blob_destroy(blob);
    if (ft) FT_Done_Face(ft);
  }
};

// FreeType's outline walker, into a Path in font units.
struct Decompose {
  Path* path;
  bool open = false;
  static Vec2 v(const FT_Vector* p) { return {static_cast<double>(p->x), static_cast<double>(p->y)}; }
  static int move(const FT_Vector* to, void* u) {
    auto* d = static_cast<Decompose*>(u);
    if (d->open) d->path->close();
    d->path->move_to(v(to));
    d->open = true;
    return 0;
  }
  static int line(const FT_Vector* to, void* u) {
    static_cast<Decompose*>(u)->path->line_to(v(to));
    return 0;
  }
  static int conic(const FT_Vector* c, const FT_Vector* to, void* u) {
    static_cast<Decompose*>(u)->path->quad_to(v(c), v(to));
    return 0;
  }
  static int cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* u) {
    static_cast<Decompose*>(u)->path->cubic_to(v(c1), v(c2), v(to));
    return 0;
  }
};

class Fonts {
 public:
  static Fonts& get() {
    static Fonts f;
    return f;
  }
  std::mutex mutex;

  // The face of a DejaVu file name, loaded on first use; nullptr if it cannot be loaded.
  Face* face(const std::string& name) {
    if (auto it = faces_.find(name); it != faces_.end()) return it->second.get();
    std::unique_ptr<Face> f;
    const std::string path = find_font(name);
    if (!path.empty() && lib_) {
      f = std::make_unique<Face>();
      f->name = name;
      if (FT_New_Face(lib_, path.c_str(), 0, &f->ft) != 0) {
        f->ft = nullptr;
        f.reset();
      } else {
        f->upem = f->ft->units_per_EM > 0 ? f->ft->units_per_EM : 2048;
        f->blob = hb_blob_create_from_file(path.c_str());
        f->hb_face = hb_face_create(f->blob, 0);
        f->hb_font = hb_font_create(f->hb_face);
        hb_font_set_scale(f->hb_font, static_cast<int>(f->upem), static_cast<int>(f->upem));
      }
    }
    Face* raw = f.get();
    faces_[name] = std::move(f);
    return raw;
  }

  bool has(Face& f, char32_t c) {
    if (auto it = f.has.find(c); it != f.has.end()) return it->second;
    const bool h = FT_Get_Char_Index(f.ft, c) != 0;
    f.has[c] = h;
    return h;
  }

  const GlyphOutline& outline(Face& f, std::uint32_t id) {
    if (auto it = f.outlines.find(id); it != f.outlines.end()) return *it->second;
    auto g = std::make_unique<GlyphOutline>();
    if (FT_Load_Glyph(f.ft, id, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0 &&
        f.ft->glyph->format == FT_GLYPH_FORMAT_OUTLINE && f.ft->glyph->outline.n_points > 0) {
      FT_Outline_Funcs funcs{};
      funcs.move_to = &Decompose::move;
      funcs.line_to = &Decompose::line;
      funcs.conic_to = &Decompose::conic;
      funcs.cubic_to = &Decompose::cubic;
      Decompose d{&g->outline};
      FT_Outline_Decompose(&f.ft->glyph->outline, &funcs, &d);
      if (d.open) g->outline.close();
      FT_BBox box;
      FT_Outline_Get_BBox(&f.ft->glyph->outline, &box);  // exact: the curves' extrema, not control points
      g->xmin = static_cast<double>(box.xMin);
      g->ymin = static_cast<double>(box.yMin);
      g->xmax = static_cast<double>(box.xMax);
      g->ymax = static_cast<double>(box.yMax);
      g->empty = g->outline.empty();
    }
    auto& slot = f.outlines[id];
    slot = std::move(g);
    return *slot;
  }

  std::shared_ptr<const std::vector<ShapedGlyph>> shape(Face& f, std::string_view run) {
    std::string key(run);
    if (auto it = f.shaped.find(key); it != f.shaped.end()) return it->second;
    hb_buffer_t* buf = hb_buffer_create();
    hb_buffer_add_utf8(buf, run.data(), static_cast<int>(run.size()), 0, static_cast<int>(run.size()));
    hb_buffer_guess_segment_properties(buf);
    hb_shape(f.hb_font, buf, nullptr, 0);
    unsigned n = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
    const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
    auto out = std::make_shared<std::vector<ShapedGlyph>>();
    out->reserve(n);
    for (unsigned i = 0; i < n; ++i)
      out->push_back({info[i].codepoint, static_cast<double>(pos[i].x_advance), static_cast<double>(pos[i].x_offset),
                      static_cast<double>(pos[i].y_offset), info[i].cluster});
    hb_buffer_destroy(buf);
    if (f.shaped.size() > 20000) f.shaped.clear();  // a bound for programs that set endless strings
    f.shaped[key] = out;
    return out;
  }

 private:
  Fonts() {
    if (FT_Init_FreeType(&lib_) != 0) lib_ = nullptr;
  }
  ~Fonts() {
    faces_.clear();
    if (lib_) FT_Done_FreeType(lib_);
  }
  FT_Library lib_ = nullptr;
  std::map<std::string, std::unique_ptr<Face>> faces_;
};

struct StyleKey {
  FontFamily family;
  FontWeight weight;
  bool italic;
  bool operator<(const StyleKey& o) const {
    return std::tie(family, weight, italic) < std::tie(o.family, o.weight, o.italic);
  }
};

// The faces of a style's fallback chain (the style's own face first); under Fonts::mutex.
const std::vector<Face*>& chain(Fonts& fonts, const TextStyle& style) {
  static std::map<StyleKey, std::vector<Face*>> chains;
  const StyleKey key{style.family, style.weight, style.italic};
  if (auto it = chains.find(key); it != chains.end()) return it->second;
  const std::string own = font_file_name(style.family, style.weight, style.italic);
  Face* first = fonts.face(own);
  if (!first)
    throw std::runtime_error("text: font file " + own + " is not installed (looked in share/splinefig/fonts and "
                             "/usr/share/fonts/truetype/dejavu; Debian: fonts-dejavu-core, fonts-dejavu-extra)");
  std::vector<Face*> faces;
  for (const std::string& name : font_fallback(style))
    if (Face* f = fonts.face(name)) faces.push_back(f);
  return chains[key] = std::move(faces);
}

// Refuses more than kMaxCombiningMarks marks (Mn, Mc, Me) in a row: Unicode's stream-safe
// text format (UAX #15) allows 30 non-starters after a base, which covers every script, and
// shaping a longer cluster takes time quadratic in its length (HarfBuzz attaches each mark
// looking back over those before it; 200000 marks on one base took two minutes), and each
// mark's outline is drawn over the same pixels.
constexpr std::size_t kMaxCombiningMarks = 30;
void check_clusters(const std::vector<CodePoint>& cps) {
  hb_unicode_funcs_t* u = hb_unicode_funcs_get_default();
  std::size_t run = 0;
  for (const CodePoint& cp : cps) {
    const hb_unicode_general_category_t g = hb_unicode_general_category(u, cp.c);
    const bool mark = g == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK || g == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
                      g == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
    run = mark ? run + 1 : 0;
    if (run > kMaxCombiningMarks)
      bad("text: more than " + std::to_string(kMaxCombiningMarks) + " combining marks in a row (" + code_name(cp.c) +
          " at byte " + std::to_string(cp.byte) + " of the text; Unicode's stream-safe limit is 30)");
  }
}

}  // namespace

TextLayout layout_text(std::string_view text, const TextStyle& style) {
  TextLayout lay;
  if (text.size() > kMaxTextBytes)
    bad("text: " + std::to_string(text.size()) + " bytes, over the limit of 2^20 (" + std::to_string(kMaxTextBytes) +
        ") in one text item");
  const std::vector<CodePoint> cps = decode_utf8(text);
  if (cps.empty()) return lay;
  check_clusters(cps);
  Fonts& fonts = Fonts::get();
  std::lock_guard<std::mutex> lock(fonts.mutex);
  const std::vector<Face*>& faces = chain(fonts, style);
  // Each character's face: the first of the chain that has it.
  std::vector<Face*> of(cps.size());
  for (std::size_t i = 0; i < cps.size(); ++i) {
    for (Face* f : faces)
      if (fonts.has(*f, cps[i].c)) {
        of[i] = f;
        break;
      }
    if (!of[i]) {
      std::string ch = cps[i].c >= 0x20 && cps[i].c != 0x7F ? " ('" + std::string(text.substr(cps[i].byte, cps[i].len)) + "')" : "";
      bad("text: no DejaVu font has " + code_name(cps[i].c) + ch);
    }
  }
  double pen = 0;
  bool inked = false;
  lay.ascent = -INFINITY;
  lay.descent = -INFINITY;
  for (std::size_t i = 0; i < cps.size();) {
    std::size_t j = i + 1;
    while (j < cps.size() && of[j] == of[i]) ++j;
    Face& f = *of[i];
    const std::size_t b0 = cps[i].byte, b1 = cps[j - 1].byte + cps[j - 1].len;
    const auto shaped = fonts.shape(f, text.substr(b0, b1 - b0));
    const double s = style.size / f.upem;
    for (const ShapedGlyph& g : *shaped) {
      const GlyphOutline& o = fonts.outline(f, g.id);
      const double x = pen + s * g.dx, y = -s * g.dy;
      lay.clusters.push_back({b0 + g.cluster, pen, s * g.advance});
      if (!o.empty) {
        lay.glyphs.push_back({&o, g.id, &f, x, y, s});
        lay.ascent = std::max(lay.ascent, s * o.ymax - y);
        lay.descent = std::max(lay.descent, y - s * o.ymin);
        inked = true;
      }
      pen += s * g.advance;
    }
    i = j;
  }
  lay.width = pen;
  if (!inked) lay.ascent = lay.descent = 0;
  return lay;
}

namespace {
// cos and sin of an angle in degrees, exact at multiples of 90.
void turn(double deg, double& c, double& s) {
  const double r = std::fmod(deg, 360.0);
  const double q = r / 90.0;
  if (q == std::floor(q)) {
    static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const int k = ((static_cast<int>(q) % 4) + 4) % 4;
    c = cs[k][0];
    s = cs[k][1];
    return;
  }
  const double a = r * std::numbers::pi / 180.0;
  c = std::cos(a);
  s = std::sin(a);
}

// The pen origin in the text frame, relative to the anchor, as the alignment puts it.
Vec2 aligned_origin(const TextLayout& lay, const TextStyle& style) {
  double ox = 0, oy = 0;
  if (style.halign == HAlign::Center) ox = -0.5 * lay.width;
  else if (style.halign == HAlign::Right) ox = -lay.width;
  if (style.valign == VAlign::Top) oy = lay.ascent;
  else if (style.valign == VAlign::Bottom) oy = -lay.descent;
  else if (style.valign == VAlign::Middle) oy = 0.5 * (lay.ascent - lay.descent);
  return {ox, oy};
}
}  // namespace

void append_outlines(const TextLayout& lay, Vec2 anchor, const TextStyle& style, Path& out) {
  const Vec2 o = aligned_origin(lay, style);
  const double ox = o.x, oy = o.y;
  double c, sn;
  turn(style.angle, c, sn);
  for (const PlacedGlyph& g : lay.glyphs) {
    // Font units (y up) -> text frame (gx + s x, gy - s y) -> canvas, turned counter-clockwise
    // on screen: (u, v) -> anchor + (c u + sn v, -sn u + c v).
    const double gx = ox + g.x, gy = oy + g.y, s = g.scale;
    const double a = c * s, b = -sn * s, cc = -sn * s, d = -c * s;
    const double e = anchor.x + c * gx + sn * gy, f = anchor.y - sn * gx + c * gy;
    const auto& verbs = g.glyph->outline.verbs();
    const auto& pts = g.glyph->outline.points();
    auto map = [&](Vec2 p) { return Vec2{a * p.x + cc * p.y + e, b * p.x + d * p.y + f}; };
    std::size_t k = 0;
    for (Path::Verb v : verbs) {
      switch (v) {
        case Path::Verb::Move: out.move_to(map(pts[k++])); break;
        case Path::Verb::Line: out.line_to(map(pts[k++])); break;
        case Path::Verb::Cubic:
          out.cubic_to(map(pts[k]), map(pts[k + 1]), map(pts[k + 2]));
          k += 3;
          break;
        case Path::Verb::Close: out.close(); break;
      }
    }
  }
}

}  // namespace detail

Path text_path(std::string_view text, Vec2 anchor, const TextStyle& style) {
  Path out;
  detail::append_outlines(detail::layout_text(text, style), anchor, style, out);
  return out;
}

TextPlacement text_placement(std::string_view text, Vec2 anchor, const TextStyle& style) {
  const detail::TextLayout lay = detail::layout_text(text, style);
  TextPlacement p;
  p.width = lay.width;
  p.ascent = lay.ascent;
  p.descent = lay.descent;
  const Vec2 o = detail::aligned_origin(lay, style);
  double c, sn;
  detail::turn(style.angle, c, sn);
  p.origin = {anchor.x + c * o.x + sn * o.y, anchor.y - sn * o.x + c * o.y};
  // Each cluster (the glyphs sharing HarfBuzz's cluster byte): its leftmost pen position and the
  // sum of its advances. Clusters by their first byte, so a character finds its own as the last
  // one starting at or before it.
  std::map<std::size_t, std::pair<double, double>> clusters;  // byte -> (x, advance)
  for (const detail::GlyphCluster& g : lay.clusters) {
    auto [it, fresh] = clusters.try_emplace(g.byte, g.x, g.advance);
    if (!fresh) {
      it->second.first = std::min(it->second.first, g.x);
      it->second.second += g.advance;
    }
  }
  const std::vector<detail::CodePoint> cps = detail::decode_utf8(text);
  p.chars.reserve(cps.size());
  for (std::size_t i = 0; i < cps.size();) {
    // The characters i..j-1 of one cluster.
    auto it = clusters.upper_bound(cps[i].byte);
    const std::size_t end = it == clusters.end() ? text.size() : it->first;
    const auto [x, advance] = it == clusters.begin() ? std::pair<double, double>{0, 0} : std::prev(it)->second;
    std::size_t j = i + 1;
    while (j < cps.size() && cps[j].byte < end) ++j;
    const double share = advance / static_cast<double>(j - i);
    for (std::size_t k = i; k < j; ++k)
      p.chars.push_back({cps[k].c, cps[k].byte, cps[k].len, x + share * static_cast<double>(k - i), share});
    i = j;
  }
  return p;
}

TextExtent measure_text(std::string_view text, const TextStyle& style) {
  const detail::TextLayout lay = detail::layout_text(text, style);
  return TextExtent{lay.width, lay.ascent, lay.descent};
}

}  // namespace splinefig::render
