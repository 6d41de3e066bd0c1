#pragma once
// Numbers given as flag values (--from, --samples, --scale, ...), read by the rules of a CSV
// field (spline/points_csv.hpp: parse_csv_number). Errors are splinefig::cli::Failure naming the
// flag, e.g. "--from: value 'abc' is not a number".
#include "command.hpp"

#include <string_view>
#include <vector>

namespace splinefig::cli {

// One finite number from text (a flag value, a CSV field); `what` names it in the error,
// e.g. "--from". Leading '+' and surrounding blanks are accepted.
double parse_number(std::string_view text, std::string_view what);
// A whole number in [lo, hi].
long long parse_integer(std::string_view text, std::string_view what, long long lo, long long hi);
// Comma-separated finite numbers ("-1.5,2"), as for vector-valued flags.
std::vector<double> parse_vector(std::string_view text, std::string_view what);

}  // namespace splinefig::cli
