// CSV points in and out, and the number parsing every flag shares (see csv.hpp).
#include "csv.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

namespace splinefig::cli {
namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// Quotes text for an error message, cut short, with control and non-ASCII bytes as \xNN.
std::string quoted(std::string_view s) {
  return "'" + printable(s.substr(0, 40)) + (s.size() > 40 ? "...'" : "'");
}

// Parses a finite double or returns why not.
bool to_double(std::string_view text, double& v, std::string& why) {
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

// The next line of `in` (without its '\n') into `line`; false at the end. Input that is not
// text ends the read at once: a NUL byte (as from /dev/zero or a binary file), or a line
// longer than kMaxLine without a newline.
constexpr std::size_t kMaxLine = std::size_t(1) << 20;
bool next_line(std::istream& in, std::string& line, std::string_view source, std::size_t lineno) {
  line.clear();
  std::streambuf* sb = in.rdbuf();
  bool any = false;
  for (;;) {
    const int c = sb ? sb->sbumpc() : std::char_traits<char>::eof();
    if (c == std::char_traits<char>::eof()) return any;
    any = true;
    if (c == '\n') return true;
    if (c == 0)
      throw Failure(std::string(source) + " line " + std::to_string(lineno) + ": a NUL byte: the input is not text");
    line.push_back(static_cast<char>(c));
    if (line.size() > kMaxLine)
      throw Failure(std::string(source) + " line " + std::to_string(lineno) +
                    ": longer than 1 MiB without a newline: the input is not CSV text");
  }
}

}  // namespace

double parse_number(std::string_view text, std::string_view what) {
  double v = 0;
  std::string why;
  if (!to_double(text, v, why)) throw Failure(std::string(what) + ": value " + why);
  return v;
}

long long parse_integer(std::string_view text, std::string_view what, long long lo, long long hi) {
  const std::string_view t = trim(text);
  long long v = 0;
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (!t.empty() && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (t.empty() || ec == std::errc::invalid_argument || ptr != last || first == last)
    throw Failure(std::string(what) + ": " + quoted(t) + " is not a whole number");
  if (ec == std::errc::result_out_of_range || v < lo || v > hi)
    throw Failure(std::string(what) + ": " + std::string(t) + " is out of range (" + std::to_string(lo) +
                  ".." + std::to_string(hi) + ")");
  return v;
}

std::vector<double> parse_vector(std::string_view text, std::string_view what) {
  std::vector<double> out;
  size_t field = 1;
  while (true) {
    const auto comma = text.find(',');
    double v = 0;
    std::string why;
    if (!to_double(text.substr(0, comma), v, why))
      throw Failure(std::string(what) + ": component " + std::to_string(field) + " " + why);
    out.push_back(v);
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
    ++field;
  }
  return out;
}

Points read_points(std::istream& in, std::string_view source) {
  Points pts;
  size_t first_line = 0;  // the line that fixed the dimension
  std::string line;
  std::vector<double> p;
  for (size_t lineno = 1; next_line(in, line, source, lineno); ++lineno) {
    // A UTF-8 byte order mark before the first line (as some editors write) is not data.
    if (lineno == 1 && line.starts_with("\xef\xbb\xbf")) line.erase(0, 3);
    const std::string_view l = trim(line);
    if (l.empty() || l.front() == '#') continue;
    p.clear();
    std::string_view rest = l;
    for (size_t field = 1;; ++field) {
      const auto comma = rest.find(',');
      double v = 0;
      std::string why;
      if (!to_double(rest.substr(0, comma), v, why))
        throw Failure(std::string(source) + " line " + std::to_string(lineno) + ", field " +
                      std::to_string(field) + ": " + (why == "is empty" ? "empty field" : why));
      p.push_back(v);
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    if (pts.dim == 0) {
      first_line = lineno;
    } else if (static_cast<int>(p.size()) != pts.dim) {
      throw Failure(std::string(source) + " line " + std::to_string(lineno) + ": " + std::to_string(p.size()) +
                    (p.size() == 1 ? " coordinate" : " coordinates") + ", but line " + std::to_string(first_line) + " has " + std::to_string(pts.dim));
    }
    pts.push_back(p);
  }
  if (in.bad() || (&in == &std::cin && std::ferror(stdin))) throw Failure("cannot read " + std::string(source));
  return pts;
}

void append_number(std::string& out, double v) {
  std::array<char, 32> buf{};
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  (void)ec;  // 32 bytes always hold a shortest double
  out.append(buf.data(), end);
}

std::string format_number(double v) {
  std::string s;
  append_number(s, v);
  return s;
}

void append_point(std::string& out, std::span<const double> p) {
  for (size_t d = 0; d < p.size(); ++d) {
    if (d) out += ',';
    append_number(out, p[d]);
  }
  out += '\n';
}

std::string format_points(const Points& p) {
  std::size_t non_finite = 0;
  return format_points(p, non_finite);
}

std::string format_points(const Points& p, std::size_t& non_finite) {
  std::string s;
  s.reserve(p.coords.size() * 20);
  non_finite = p.coords.size();
  for (size_t i = 0; i < p.size(); ++i) {
    const auto q = p[i];
    const std::size_t k = first_non_finite(q);  // q is in cache: no second pass over memory
    if (k < q.size()) {
      non_finite = i * q.size() + k;
      return s;
    }
    append_point(s, q);
  }
  return s;
}

std::size_t first_non_finite(std::span<const double> v) {
  std::size_t i = 0;
  while (i < v.size() && std::isfinite(v[i])) ++i;
  return i;
}

void write_stdout(std::string_view text) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
    throw Failure("cannot write to stdout", 1);
}

}  // namespace splinefig::cli
