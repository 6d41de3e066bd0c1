#pragma once
// idiff's report lines, character for character (OpenImageIO 2.4's idiff prints them with
// {fmt}: doubles as "{:g}", the max error as "{:g}", pixel values and thresholds as "{}", the
// shortest text that reads back to the same float, and percentages as "{:1.3g}").
#include <splinefig/compare/idiff.hpp>
#include <splinefig/compare/image.hpp>

#include <string>

namespace splinefig::compare {

// printf("%g"), with "inf" and "nan" for non-finite values.
std::string format_g(double v);
// {fmt}'s "{}" for a float: the shortest digits that round-trip, fixed notation for decimal
// exponents -4 .. 15, otherwise d.ddde+XX.
std::string format_shortest(float v);
// printf("%1.3g").
std::string format_percent(double v);

// The lines idiff prints for a comparison that is reported (from "  Mean error" to the
// "pixels over <fail>" line), each ending in '\n'. `a` and `b` are the images as compared
// (their channel names and values at the max-error pixel are printed).
std::string idiff_report_lines(const Metrics& m, const Thresholds& t, const Image& a, const Image& b);

// "PASS", "WARNING" or "FAILURE".
const char* verdict_word(Verdict v);

}  // namespace splinefig::compare
