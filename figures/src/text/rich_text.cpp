// Labels with math markup (see rich_text.hpp).
#include "rich_text.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace splinefig::figures::detail {
namespace {

struct Name {
  const char* name;
  char32_t code;
  bool letter;  // a variable: italic in math
};

// TeX names: the Greek alphabet (TeX's own names, plus the capitals TeX writes as Latin ones)
// and the symbols labels need.
constexpr Name kNames[] = {
    {"alpha", 0x03B1, true}, {"beta", 0x03B2, true}, {"gamma", 0x03B3, true}, {"delta", 0x03B4, true},
    {"epsilon", 0x03F5, true}, {"varepsilon", 0x03B5, true}, {"zeta", 0x03B6, true}, {"eta", 0x03B7, true},
    {"theta", 0x03B8, true}, {"vartheta", 0x03D1, true}, {"iota", 0x03B9, true}, {"kappa", 0x03BA, true},
    {"lambda", 0x03BB, true}, {"mu", 0x03BC, true}, {"nu", 0x03BD, true}, {"xi", 0x03BE, true},
    {"omicron", 0x03BF, true}, {"pi", 0x03C0, true}, {"varpi", 0x03D6, true}, {"rho", 0x03C1, true},
    {"varrho", 0x03F1, true}, {"sigma", 0x03C3, true}, {"varsigma", 0x03C2, true}, {"tau", 0x03C4, true},
    {"upsilon", 0x03C5, true}, {"phi", 0x03D5, true}, {"varphi", 0x03C6, true}, {"chi", 0x03C7, true},
    {"psi", 0x03C8, true}, {"omega", 0x03C9, true},
    {"Alpha", 0x0391, false}, {"Beta", 0x0392, false}, {"Gamma", 0x0393, false}, {"Delta", 0x0394, false},
    {"Epsilon", 0x0395, false}, {"Zeta", 0x0396, false}, {"Eta", 0x0397, false}, {"Theta", 0x0398, false},
    {"Iota", 0x0399, false}, {"Kappa", 0x039A, false}, {"Lambda", 0x039B, false}, {"Mu", 0x039C, false},
    {"Nu", 0x039D, false}, {"Xi", 0x039E, false}, {"Omicron", 0x039F, false}, {"Pi", 0x03A0, false},
    {"Rho", 0x03A1, false}, {"Sigma", 0x03A3, false}, {"Tau", 0x03A4, false}, {"Upsilon", 0x03A5, false},
    {"Phi", 0x03A6, false}, {"Chi", 0x03A7, false}, {"Psi", 0x03A8, false}, {"Omega", 0x03A9, false},
    {"infty", 0x221E, false}, {"le", 0x2264, false}, {"leq", 0x2264, false}, {"ge", 0x2265, false},
    {"geq", 0x2265, false}, {"ne", 0x2260, false}, {"neq", 0x2260, false}, {"times", 0x00D7, false},
    {"cdot", 0x22C5, false}, {"pm", 0x00B1, false}, {"mp", 0x2213, false}, {"to", 0x2192, false},
    {"rightarrow", 0x2192, false}, {"leftarrow", 0x2190, false}, {"prime", 0x2032, false},
    {"approx", 0x2248, false}, {"equiv", 0x2261, false}, {"sim", 0x223C, false}, {"propto", 0x221D, false},
    {"partial", 0x2202, false}, {"nabla", 0x2207, false}, {"sqrt", 0x221A, false}, {"int", 0x222B, false},
    {"sum", 0x2211, false}, {"prod", 0x220F, false}, {"in", 0x2208, false}, {"ldots", 0x2026, false},
    {"cdots", 0x22EF, false}, {"circ", 0x2218, false}, {"deg", 0x00B0, false}, {"minus", 0x2212, false},
};

void append_utf8(std::string& s, char32_t c) {
  if (c < 0x80) {
    s += static_cast<char>(c);
  } else if (c < 0x800) {
    s += static_cast<char>(0xC0 | (c >> 6));
    s += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    s += static_cast<char>(0xE0 | (c >> 12));
    s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    s += static_cast<char>(0xF0 | (c >> 18));
    s += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (c & 0x3F));
  }
}

const Name* find_name(std::string_view n) {
  for (const Name& k : kNames)
    if (n == k.name) return &k;
  return nullptr;
}

// The length of the UTF-8 sequence starting at s[i], or 0 if it is not valid UTF-8.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto b0 = static_cast<unsigned char>(s[i]);
  std::size_t n;
  char32_t c, min;
  if (b0 < 0x80) return 1;
  if ((b0 & 0xE0) == 0xC0) { n = 2; c = b0 & 0x1F; min = 0x80; }
  else if ((b0 & 0xF0) == 0xE0) { n = 3; c = b0 & 0x0F; min = 0x800; }
  else if ((b0 & 0xF8) == 0xF0) { n = 4; c = b0 & 0x07; min = 0x10000; }
  else return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(s[i + k]);
    if ((b & 0xC0) != 0x80) return 0;
    c = (c << 6) | (b & 0x3F);
  }
  if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return 0;
  return n;
}

struct Piece {
  std::string text;
  int level;  // -1 sub, 0 normal, +1 super
  bool italic;
};

class Parser {
 public:
  Parser(const std::string& m, std::string* error) : m_(m), error_(error) {}

  std::vector<Piece> run() {
    while (i_ < m_.size() && ok_) {
      const char c = m_[i_];
      if (c == '$') {
        math_ = !math_;
        ++i_;
      } else if (c == '_' || c == '^') {
        const int level = c == '_' ? -1 : 1;
        ++i_;
        if (i_ >= m_.size()) return fail(std::string("a dangling ") + c + " at the end");
        if (m_[i_] == '{') {
          ++i_;
          for (;;) {
            if (i_ >= m_.size()) return fail("an unclosed { after " + std::string(1, c));
            if (m_[i_] == '}') break;
            if (m_[i_] == '{' || m_[i_] == '_' || m_[i_] == '^')
              return fail(std::string("a nested ") + m_[i_] + " inside " + c + "{...}");
            if (m_[i_] == '$') return fail(std::string("a $ inside ") + c + "{...}");
            token(level);
            if (!ok_) return out_;
          }
          ++i_;
        } else if (m_[i_] == '}' || m_[i_] == '{' || m_[i_] == '$') {
          return fail(std::string("nothing to set after ") + c);
        } else {
          token(level);
        }
      } else if (c == '{' && i_ + 1 < m_.size() && m_[i_ + 1] == '}') {
        i_ += 2;  // an empty group: ends a name, sets nothing
      } else if (c == '{' || c == '}') {
        return fail(std::string("an unescaped ") + c + " (write \\" + c + ")");
      } else {
        token(0);
      }
    }
    if (ok_ && math_) return fail("an unclosed $");
    return out_;
  }

 private:
  std::vector<Piece> fail(const std::string& e) {
    if (error_ && error_->empty()) *error_ = e;
    ok_ = false;
    return out_;
  }

  void add(const std::string& s, int level, bool italic) {
    if (out_.empty() || out_.back().level != level || out_.back().italic != italic) out_.push_back({"", level, italic});
    out_.back().text += s;
  }

  // One character, escape or \name at i_, set at `level`.
  void token(int level) {
    const char c = m_[i_];
    if (c == '\\') {
      if (i_ + 1 < m_.size() && std::string_view("_^{}\\$").find(m_[i_ + 1]) != std::string_view::npos) {
        add(std::string(1, m_[i_ + 1]), level, false);
        i_ += 2;
        return;
      }
      std::size_t j = i_ + 1;
      while (j < m_.size() && ((m_[j] >= 'a' && m_[j] <= 'z') || (m_[j] >= 'A' && m_[j] <= 'Z'))) ++j;
      if (j == i_ + 1) {  // a backslash before anything else is itself
        add("\\", level, false);
        ++i_;
        return;
      }
      const std::string name = m_.substr(i_ + 1, j - i_ - 1);
      const Name* k = find_name(name);
      if (!k) {
        fail("unknown name \\" + name + " (write \\\\ for a backslash)");
        return;
      }
      std::string s;
      append_utf8(s, k->code);
      add(s, level, math_ && k->letter);
      i_ = j;  // spaces after a name are kept; "\alpha{}x" sets αx
      return;
    }
    const std::size_t n = utf8_length(m_, i_);
    if (n == 0) {
      fail("invalid UTF-8 at byte " + std::to_string(i_));
      return;
    }
    if (math_ && c == '-') {
      add("\u2212", level, false);
    } else {
      const bool latin = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
      add(m_.substr(i_, n), level, math_ && latin);
    }
    i_ += n;
  }

  const std::string& m_;
  std::string* error_;
  std::size_t i_ = 0;
  bool math_ = false, ok_ = true;
  std::vector<Piece> out_;
};

}  // namespace

std::string tex_symbol(std::string_view name) {
  const Name* k = find_name(name);
  if (!k) return {};
  std::string s;
  append_utf8(s, k->code);
  return s;
}

std::string markup_problem(const std::string& markup) {
  std::string error;
  Parser(markup, &error).run();
  return error;
}

namespace {
// A sub- or superscript piece as Unicode sub/superscript characters, if all of it has one.
bool scripted(const std::string& s, bool sup, std::string& out) {
  static const char* const sub_digits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  static const char* const sup_digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string r;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c >= '0' && c <= '9') r += (sup ? sup_digits : sub_digits)[c - '0'];
    else if (c == '+') r += sup ? "⁺" : "₊";
    else if (c == '-' ) r += sup ? "⁻" : "₋";
    else if (s.compare(i, 3, "\u2212") == 0) r += sup ? "⁻" : "₋", i += 2;
    else if (!sup && c == 'i') r += "ᵢ";
    else if (!sup && c == 'k') r += "ₖ";
    else if (!sup && c == 'n') r += "ₙ";
    else if (!sup && c == 'a') r += "ₐ";
    else if (sup && c == 'n') r += "ⁿ";
    else if (sup && c == 'k') r += "ᵏ";
    else return false;
  }
  out += r;
  return true;
}
}  // namespace

std::string plain_text(const std::string& markup) {
  std::string out;
  for (const Piece& p : Parser(markup, nullptr).run()) {
    if (p.level == 0 || !scripted(p.text, p.level > 0, out)) {
      if (p.level != 0) out += p.level > 0 ? "^" : "_";
      out += p.text;
    }
  }
  return out;
}

RichText set_text(const std::string& markup, double size, const Measure& measure) {
  RichText rt;
  double pen = 0;
  for (const Piece& p : Parser(markup, nullptr).run()) {
    const double s = p.level == 0 ? size : 0.7 * size;
    const double dy = p.level < 0 ? 0.22 * size : p.level > 0 ? -0.40 * size : 0.0;
    const render::TextExtent e = measure(p.text, s, p.italic);
    rt.runs.push_back({p.text, s, pen, dy, p.italic});
    if (e.ascent != 0 || e.descent != 0) {  // a run of spaces has no ink
      rt.ascent = std::max(rt.ascent, e.ascent - dy);
      rt.descent = std::max(rt.descent, e.descent + dy);
    }
    pen += e.width;  // the shaped advance: spaces and side bearings included
  }
  rt.width = pen;
  return rt;
}

}  // namespace splinefig::figures::detail
