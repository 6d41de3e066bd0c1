// Labels with sub- and superscripts (see rich_text.hpp).
#include "rich_text.hpp"

#include <algorithm>

namespace splinefig::figures::detail {
namespace {

struct Piece {
  std::string text;
  int level;  // -1 sub, 0 normal, +1 super
};

// Splits markup into pieces; `error` set on malformed input.
std::vector<Piece> parse(const std::string& m, std::string* error) {
  std::vector<Piece> out;
  auto add = [&](char c, int level) {
    if (out.empty() || out.back().level != level) out.push_back({"", level});
    out.back().text += c;
  };
  for (size_t i = 0; i < m.size(); ++i) {
    char c = m[i];
    if (c == '\\' && i + 1 < m.size() && std::string("_^{}\\").find(m[i + 1]) != std::string::npos) {
      add(m[++i], 0);
    } else if (c == '_' || c == '^') {
      int level = c == '_' ? -1 : 1;
      if (i + 1 >= m.size()) {
        if (error) *error = std::string("a dangling ") + c + " at the end";
        return out;
      }
      if (m[i + 1] == '{') {
        size_t close = m.find('}', i + 2);
        if (close == std::string::npos) {
          if (error) *error = "an unclosed { after " + std::string(1, c);
          return out;
        }
        for (size_t k = i + 2; k < close; ++k) {
          if (m[k] == '\\' && k + 1 < close) ++k;
          add(m[k], level);
        }
        i = close;
      } else {
        add(m[++i], level);
      }
    } else if (c == '{' || c == '}') {
      if (error) *error = std::string("an unescaped ") + c + " (write \\" + c + ")";
      return out;
    } else {
      add(c, 0);
    }
  }
  return out;
}

}  // namespace

std::string markup_problem(const std::string& markup) {
  for (unsigned char c : markup)
    if (c >= 0x80) return "only ASCII text can be rendered (write subscripts as c_3, superscripts as 10^{-2})";
  std::string error;
  parse(markup, &error);
  return error;
}

RichText set_text(const std::string& markup, double size, const Measure& measure) {
  RichText rt;
  const double space = measure("a a", size).width - measure("aa", size).width;
  double pen = 0;
  for (const Piece& p : parse(markup, nullptr)) {
    const double s = p.level == 0 ? size : 0.7 * size;
    const double dy = p.level < 0 ? 0.22 * size : p.level > 0 ? -0.40 * size : 0.0;
    size_t lead = p.text.find_first_not_of(' ');
    if (lead == std::string::npos) {  // only spaces
      pen += space * static_cast<double>(p.text.size()) * s / size;
      continue;
    }
    const double lead_w = space * static_cast<double>(lead) * s / size;
    std::string body = p.text.substr(lead);
    size_t trail = body.size() - 1 - body.find_last_not_of(' ');
    render::TextExtent e = measure(body, s);
    rt.runs.push_back({body, s, pen + lead_w, dy});
    rt.ascent = std::max(rt.ascent, e.ascent - dy);
    rt.descent = std::max(rt.descent, e.descent + dy);
    // Advance: the ink width plus a side bearing, plus trailing spaces.
    pen += lead_w + e.width + 0.02 * s + space * static_cast<double>(trail) * s / size;
  }
  rt.width = std::max(0.0, pen - 0.02 * size);
  return rt;
}

}  // namespace splinefig::figures::detail
