// CSV point text in (see points_csv.hpp).
#include <splinefig/spline/points_csv.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace splinefig {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// Text for an error message, cut short, with control and non-ASCII bytes as \xNN.
constexpr std::size_t kQuoted = 24;
std::string quoted(std::string_view s) {
  // A char, not "'": GCC 12 warns of a bogus overlap (-Wrestrict, GCC PR 105329) for a
  // one-character string literal + a temporary std::string.
  return '\'' + printable(s.substr(0, kQuoted)) + (s.size() > kQuoted ? "...'" : "'");
}

std::string at(std::string_view source, std::size_t line) {
  return std::string(source) + " line " + std::to_string(line);
}

// The next line of `in` (without its '\n') into `line`; false at the end. Input that is not
// text ends the read at once: a NUL byte (as from /dev/zero or a binary file), or a line
// longer than kMaxLine without a newline.
constexpr std::size_t kMaxLine = std::size_t(1) << 20;
bool next_line(std::istream& in, std::string& line, std::string_view source, std::size_t lineno) {
  line.clear();
  std::streambuf* sb = in.rdbuf();
  bool any = false;
  for (;;) {
    int c;
    try {  // a file stream reports a failed read(2) (/proc/self/mem) by throwing
      c = sb ? sb->sbumpc() : std::char_traits<char>::eof();
    } catch (const std::exception&) {
      throw CsvError(at(source, lineno) + ": a read error: the input is not a readable file", lineno);
    }
    if (c == std::char_traits<char>::eof()) return any;
    any = true;
    if (c == '\n') return true;
    if (c == 0) throw CsvError(at(source, lineno) + ": a NUL byte: the input is not text", lineno);
    line.push_back(static_cast<char>(c));
    if (line.size() > kMaxLine)
      throw CsvError(at(source, lineno) + ": longer than 1 MiB without a newline: the input is not CSV text", lineno);
  }
}

// The fields of a (trimmed, non-empty) line.
void split(std::string_view l, char delimiter, std::vector<std::string_view>& fields) {
  fields.clear();
  if (delimiter == ' ') {
    while (!l.empty()) {
      std::size_t n = 0;
      while (n < l.size() && !blank(l[n])) ++n;
      fields.push_back(l.substr(0, n));
      l.remove_prefix(n);
      while (!l.empty() && blank(l.front())) l.remove_prefix(1);
    }
    return;
  }
  for (;;) {
    const auto d = l.find(delimiter);
    fields.push_back(l.substr(0, d));
    if (d == std::string_view::npos) return;
    l.remove_prefix(d + 1);
  }
}

}  // namespace

std::optional<char> parse_delimiter(std::string_view name) {
  if (name == "," || name == "comma") return ',';
  if (name == ";" || name == "semicolon") return ';';
  if (name == "\t" || name == "tab" || name == "\\t") return '\t';
  if (name == " " || name == "space" || name == "whitespace") return ' ';
  return std::nullopt;
}

bool parse_csv_number(std::string_view text, double& v, std::string& why) {
  const std::string_view t = trim(text);
  if (t.empty()) {
    why = "is empty";
    return false;
  }
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (*first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec == std::errc::result_out_of_range && ptr == last) {
    why = quoted(t) + " is out of the range of a double";
    return false;
  }
  if (ec != std::errc() || ptr != last || first == last) {
    why = quoted(t) + " is not a number";
    return false;
  }
  if (!std::isfinite(v)) {
    why = quoted(t) + " is not a finite number";
    return false;
  }
  return true;
}

Points read_csv_points(std::istream& in, std::string_view source, const CsvOptions& options) {
  Points pts;
  std::size_t first_line = 0;   // the line that fixed the dimension
  std::size_t header_line = 0;  // the line of names, if any
  std::size_t names = 0;
  bool first_data = true;
  std::string line;
  std::vector<std::string_view> fields;
  std::vector<double> p;
  for (std::size_t lineno = 1; next_line(in, line, source, lineno); ++lineno) {
    // A UTF-8 byte order mark before the first line (as some editors write) is not data.
    if (lineno == 1 && line.starts_with("\xef\xbb\xbf")) line.erase(0, 3);
    const std::string_view l = trim(line);
    if (l.empty() || l.front() == '#') continue;
    split(l, options.delimiter, fields);
    p.clear();
    if (first_data && options.header) {
      first_data = false;
      bool any_number = false;
      for (const auto f : fields) {
        double v = 0;
        std::string why;
        any_number = any_number || parse_csv_number(f, v, why) || why == "is empty" ||
                     why.ends_with("is out of the range of a double") || why.ends_with("is not a finite number");
      }
      if (!any_number) {
        header_line = lineno;
        names = fields.size();
        continue;
      }
    }
    first_data = false;
    for (std::size_t field = 1; field <= fields.size(); ++field) {
      double v = 0;
      std::string why;
      if (!parse_csv_number(fields[field - 1], v, why)) {
        // Before the first point nothing says the input is CSV: a file of another kind
        // (/etc/shadow named as points_file) is not quoted. Text on stdin is what the user
        // typed or piped, and is.
        if (pts.dim == 0 && source != "stdin") {
          const char* reasons[] = {"is empty", "is not a number", "is out of the range of a double", "is not a finite number"};
          std::string reason = reasons[1];
          for (const char* r : reasons)
            if (why.ends_with(r)) reason = r;
          throw CsvError(at(source, lineno) + ": not a CSV file (field " + std::to_string(field) +
                             " of its first data line " + reason + ")",
                         lineno);
        }
        throw CsvError(at(source, lineno) + ", field " + std::to_string(field) + ": " +
                           (why == "is empty" ? "empty field" : why),
                       lineno);
      }
      p.push_back(v);
    }
    const auto count = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " coordinate" : " coordinates"); };
    if (header_line && p.size() != names)
      throw CsvError(at(source, lineno) + ": " + count(p.size()) + ", but the header on line " +
                         std::to_string(header_line) + " names " + std::to_string(names),
                     lineno);
    if (pts.dim == 0) {
      first_line = lineno;
    } else if (static_cast<int>(p.size()) != pts.dim) {
      throw CsvError(at(source, lineno) + ": " + count(p.size()) + ", but line " + std::to_string(first_line) +
                         " has " + std::to_string(pts.dim),
                     lineno);
    }
    pts.push_back(p);
  }
  if (in.bad()) throw CsvError("cannot read " + std::string(source), 0);
  return pts;
}

std::string excerpt(std::string_view s, char quote) {
  constexpr std::size_t kMax = 40;
  std::size_t end = std::min(s.size(), kMax);
  while (end < s.size() && end > 0 && (static_cast<unsigned char>(s[end]) & 0xc0) == 0x80) --end;
  std::string out(1, quote);
  for (std::size_t i = 0; i < end; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += s[i];
    }
  }
  if (end < s.size()) {
    out += "...";
    out += quote;
    out += " (" + std::to_string(s.size()) + " bytes)";
  } else {
    out += quote;
  }
  return out;
}

std::string printable(std::string_view text) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c >= 0x7f) {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += ch;
    }
  }
  return out;
}

}  // namespace splinefig
