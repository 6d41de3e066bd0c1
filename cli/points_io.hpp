#pragma once
// Points in and out as CSV for eval, interp and kernel (docs/conventions.md; the reading rules
// are spline/points_csv.hpp's). Numbers are written as the shortest decimal
// that reads back to the same double (std::to_chars), so output round-trips exactly.
//
// Errors are splinefig::cli::Failure with one line naming the source, line and field, e.g.
//   "stdin line 7, field 2: 'abc' is not a number".
// Output is built in memory and written at once by write_stdout (stdio.hpp), so a failed
// command prints nothing on stdout.
#include "command.hpp"

#include <splinefig/spline/points.hpp>
#include <splinefig/spline/points_csv.hpp>

#include <istream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig::cli {

// All points in `in`; `source` names it in errors ("stdin", a file name). Rejects text,
// empty fields, NaN/inf, values out of double range, and lines of another dimension.
// An input with no points gives an empty Points (dim 0); callers say what they need.
Points read_points(std::istream& in, std::string_view source = "stdin", const CsvOptions& options = {});

// The points of the input file `path`, or of stdin when it is empty or "-" (spline/points_csv.hpp:
// a first line of names is skipped). input_name(path) is the name errors use ("stdin", path).
Points read_input(const std::string& path, const CsvOptions& options);
std::string input_name(const std::string& path);
// --delimiter: comma (default), semicolon, tab, space (runs of blanks).
CsvOptions csv_options(const std::string& delimiter);
// The optional input file argument (none or "-": stdin) and --delimiter, as eval, interp and
// kernel take them; `what` says what the points are.
void add_input(CLI::App& app, std::string& input, std::string& delimiter, const std::string& what);

// Shortest round-trip decimal of v.
void append_number(std::string& out, double v);
std::string format_number(double v);
// "x,y,z\n"
void append_point(std::string& out, std::span<const double> p);
std::string format_points(const Points& p);
// The same, also setting `non_finite` to the index (into p.coords) of the first value that is
// not finite (the text then stops before it), or p.coords.size(). Checked while formatting,
// so a large output is read once.
std::string format_points(const Points& p, std::size_t& non_finite);

// The index of the first value that is not finite (NaN, +-inf), or v.size() if all are.
// Every command checks its numbers with it before writing: a non-finite result is an error
// naming the input that caused it, never printed.
std::size_t first_non_finite(std::span<const double> v);

}  // namespace splinefig::cli
