#pragma once
// The message parse_spec throws for a spec's text, and the check that each of a list of bad
// specs gets its documented one-line message ("FILE:LINE: KEY: ..." as a prefix).
#include <splinefig/figures/spec.hpp>

#include <catch2/catch.hpp>

#include <string>

namespace figtest {

// The message parse_spec throws for `text` read as the file `name` (relative data files from
// `dir`), or "" if it parses.
inline std::string spec_error(const std::string& text, const std::string& name, const std::string& dir = ".") {
  try {
    splinefig::figures::parse_spec(text, name, dir);
  } catch (const splinefig::figures::SpecFileError& e) {
    return e.what();
  }
  return "";
}

// `cases`: anything with .text and .expect (the message's expected start).
template <class Cases>
void check_spec_errors(const Cases& cases, const std::string& name, const std::string& dir = ".") {
  for (const auto& c : cases) {
    INFO(c.text);
    const std::string msg = spec_error(c.text, name, dir);
    CAPTURE(msg);
    CHECK(msg.rfind(c.expect, 0) == 0);
    CHECK(msg.find('\n') == std::string::npos);
  }
}

}  // namespace figtest
