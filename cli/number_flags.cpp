// Numbers given as flag values: one finite number, a whole number in a range, a list of numbers
// (see number_flags.hpp).
#include "number_flags.hpp"

#include <charconv>
#include <string>

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


bool to_double(std::string_view text, double& v, std::string& why) { return parse_csv_number(text, v, why); }

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


}  // namespace splinefig::cli
