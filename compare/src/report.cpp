// idiff's report text (see report.hpp).
#include <splinefig/compare/report.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace splinefig::compare {

std::string format_g(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string format_percent(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%1.3g", v);
  return buf;
}

std::string format_shortest(float v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (v == 0.0f) return std::signbit(v) ? "-0" : "0";
  // Shortest round-trip digits and decimal exponent, from the scientific form d.ddde±x.
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  const std::string sci(buf, res.ptr);
  const std::size_t e = sci.find('e');
  std::string mant = sci.substr(0, e);
  const int exp10 = std::atoi(sci.c_str() + e + 1);
  const bool negative = mant[0] == '-';
  if (negative) mant.erase(0, 1);
  std::string digits;
  for (char ch : mant)
    if (ch != '.') digits += ch;
  std::string out;
  if (exp10 < -4 || exp10 >= 16) {
    out = digits.substr(0, 1);
    if (digits.size() > 1) {
      out += '.';
      out.append(digits, 1, std::string::npos);
    }
    char ebuf[16];
    std::snprintf(ebuf, sizeof ebuf, "e%c%02d", exp10 < 0 ? '-' : '+', std::abs(exp10));
    out += ebuf;
  } else if (exp10 < 0) {
    out = "0." + std::string(std::size_t(-exp10 - 1), '0') + digits;
  } else if (std::size_t(exp10) + 1 >= digits.size()) {
    out = digits + std::string(std::size_t(exp10) + 1 - digits.size(), '0');
  } else {
    out = digits.substr(0, std::size_t(exp10) + 1) + "." + digits.substr(std::size_t(exp10) + 1);
  }
  return negative ? "-" + out : out;
}

std::string idiff_report_lines(const Metrics& m, const Thresholds& t, const Image& a, const Image& b) {
  std::string s;
  s += "  Mean error = " + format_g(m.mean_error) + "\n";
  s += "  RMS error = " + format_g(m.rms_error) + "\n";
  s += "  Peak SNR = " + format_g(m.psnr) + "\n";
  s += "  Max error  = " + format_g(m.max_error);
  if (m.max_error != 0.0f) {
    s += " @ (" + std::to_string(m.max_x) + ", " + std::to_string(m.max_y);
    if (m.max_c < int(a.channel_names.size()))
      s += ", " + a.channel_names[std::size_t(m.max_c)] + ")";
    else if (m.max_c < int(b.channel_names.size()))
      s += ", " + b.channel_names[std::size_t(m.max_c)] + ")";
    else
      s += ", channel " + std::to_string(m.max_c) + ")";
    s += "  values are ";
    for (int c = 0; c < a.channels; ++c)
      s += (c ? ", " : "") + format_shortest(a.value_or_zero(m.max_x, m.max_y, c));
    s += " vs ";
    for (int c = 0; c < b.channels; ++c)
      s += (c ? ", " : "") + format_shortest(b.value_or_zero(m.max_x, m.max_y, c));
  }
  s += "\n";
  const double npels = double(m.npels);
  s += "  " + std::to_string(m.nwarn) + " pixels (" + format_percent(100.0 * double(m.nwarn) / npels) + "%) over " +
       format_shortest(t.warn) + "\n";
  s += "  " + std::to_string(m.nfail) + " pixels (" + format_percent(100.0 * double(m.nfail) / npels) + "%) over " +
       format_shortest(t.fail) + "\n";
  return s;
}

const char* verdict_word(Verdict v) {
  switch (v) {
    case Verdict::match: return "PASS";
    case Verdict::warning: return "WARNING";
    case Verdict::failure: return "FAILURE";
  }
  return "FAILURE";
}

}  // namespace splinefig::compare
