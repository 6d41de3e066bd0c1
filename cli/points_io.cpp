// CSV points in and out (see points_io.hpp).
#include "points_io.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <cstring>
#include <fstream>
#include <sstream>

namespace splinefig::cli {
namespace {

// All of stdin in large reads (std::cin synchronized with stdio reads a character at a time);
// a NUL byte stops the read at once (the input is not text).
std::istringstream slurp_stdin() {
  std::string text;
  char buf[1 << 16];
  std::size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, stdin)) > 0) {
    // Not text (/dev/zero, a binary file): stop at once, before reading it all.
    if (const void* nul = std::memchr(buf, 0, got)) {
      text.append(static_cast<const char*>(buf), static_cast<const char*>(nul));
      const auto line = std::count(text.begin(), text.end(), '\n') + 1;
      throw Failure("stdin line " + std::to_string(line) + ": a NUL byte: the input is not text");
    }
    text.append(buf, got);
  }
  if (std::ferror(stdin)) throw Failure("cannot read stdin");
  return std::istringstream(std::move(text));
}

}  // namespace

Points read_points(std::istream& in, std::string_view source, const CsvOptions& options) {
  try {
    Points pts = read_csv_points(in, source, options);
    if (&in == &std::cin && std::ferror(stdin)) throw Failure("cannot read " + std::string(source), ErrorKind::unreadable);
    return pts;
  } catch (const CsvError& e) {
    throw Failure(e.what(), e);
  }
}

Points read_input(const std::string& path, const CsvOptions& options) {
  if (path.empty() || path == "-") {
    std::istringstream in = slurp_stdin();
    return read_points(in, "stdin", options);
  }
  check_input_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Failure(path + ": cannot open it (" + std::strerror(errno) + ")", ErrorKind::unreadable);
  return read_points(in, path, options);
}

std::string input_name(const std::string& path) { return path.empty() || path == "-" ? "stdin" : path; }

CsvOptions csv_options(const std::string& delimiter) {
  const auto d = parse_delimiter(delimiter);
  if (!d) throw Failure("--delimiter: '" + printable(delimiter) + "' is not one of comma, semicolon, tab, space");
  return {*d, true};
}

void add_input(CLI::App& app, std::string& input, std::string& delimiter, const std::string& what) {
  app.add_option("INPUT", input,
                 what + ": a CSV file, or - (the default) for stdin; one point per line, a first line of "
                        "names is skipped if none of it is a number")
      ->type_name("PATH");
  choices(app.add_option("--delimiter", delimiter, "Between coordinates: comma, semicolon, tab or space (runs of blanks)")
              ->type_name("NAME")
              ->capture_default_str(),
          {"comma", "semicolon", "tab", "space"});
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

}  // namespace splinefig::cli
