#pragma once
// Points read from CSV text, the rules every reader of point data shares (the command line's
// eval, interp and kernel, a figure spec's points_file): one point per line, coordinates split
// by the delimiter, any dimension >= 1 but the same on every line; blank lines and lines whose
// first non-blank character is '#' are ignored. The first data line may be a header of names
// (no field of it is a number); it is skipped, and every point must then have as many
// coordinates as it has names.
//
// Errors are CsvError with one line naming the source, line and field, e.g.
//   "knots.csv line 7, field 2: 'abc' is not a number".
// A value is quoted at most 24 bytes long, escaped (printable()). A file whose first data line
// does not parse is "not a CSV file", quoting nothing of it: no line of a file that is not CSV
// (a points_file = "/etc/shadow") reaches a message. A source named "stdin" is text the user
// typed or piped, quoted from its first line on.
#include <splinefig/base/error.hpp>
#include <splinefig/spline/points.hpp>

#include <cstddef>
#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace splinefig {

struct CsvError : ErrorOf<std::runtime_error, ErrorKind::bad_input> {
  std::size_t line;  // 1-based line of the source, 0 when the error is not about one line
  CsvError(const std::string& what, std::size_t line) : ErrorOf(what), line(line) {}
};

struct CsvOptions {
  char delimiter = ',';  // ' ' splits at runs of blanks (spaces and tabs)
  bool header = true;    // accept a first line of names
};

// "comma" or ",", "semicolon" or ";", "tab" or "\t", "space" or " " (runs of spaces and tabs);
// nullopt for anything else.
std::optional<char> parse_delimiter(std::string_view name);

// All points in `in`; `source` names it in errors ("stdin", a file name). Rejects text,
// empty fields, NaN/inf, values out of double range, lines of another dimension, a NUL byte and
// a line over 1 MiB (input that is not text). An input with no points gives dim 0.
Points read_csv_points(std::istream& in, std::string_view source, const CsvOptions& options = {});

// One finite number (leading '+' and surrounding blanks accepted); false with `why` ("is
// empty", "'x' is not a number", ...) otherwise.
bool parse_csv_number(std::string_view text, double& value, std::string& why);

// `text` as it may be shown on a terminal in a one-line message: control characters (a
// newline included), DEL and every byte >= 0x80 of the input echoed in it are written as \xNN,
// so that raw bytes, escape sequences or an invisible byte order mark can neither garble the
// terminal nor hide in the message.
std::string printable(std::string_view text);

// Text the user gave (a label, a basis spec's parameter, a flag's value) as a one-line message
// quotes it: between `quote`s, at most 40 bytes (cut at a character boundary, "..." after it and
// the text's size), control characters and DEL as \xNN, so that a 100 KB label is not
// repeated: "\"$AAAA...\" (100002 bytes)".
std::string excerpt(std::string_view text, char quote = '"');

}  // namespace splinefig
