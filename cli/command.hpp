#pragma once
// Subcommand registry. Each cmd_*.cpp defines one subcommand and registers it with
//   static const splinefig::cli::Registration reg{"eval", "Evaluate a spline ...", setup};
// where setup(CLI::App&) adds the options and returns the function that runs it.
// The function returns the process exit code of a run that did what was asked (diff: its
// verdict); it reports errors by throwing (one line, printed as "splinefig NAME: message"), and
// main.cpp alone turns the error's kind (base/error.hpp) into the exit code.
#include "reference.hpp"

#include <splinefig/base/error.hpp>
#include <splinefig/base/limits.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/points_csv.hpp>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <unistd.h>

namespace splinefig::cli {

using Runner = std::function<int()>;
using Setup = std::function<Runner(CLI::App&)>;

struct Command {
  std::string name;
  std::string description;
  Setup setup;
};

std::vector<Command>& registry();

struct Registration {
  Registration(std::string name, std::string description, Setup setup) {
    registry().push_back({std::move(name), std::move(description), std::move(setup)});
  }
};

// A user-facing error: one line naming what is wrong and where, of kind `kind` (a bad flag or
// input unless said), or of the kind of the error `cause` it says in other words.
struct Failure : std::runtime_error, Error {
  explicit Failure(const std::string& what, ErrorKind kind = ErrorKind::bad_input) : std::runtime_error(what), Error(kind) {}
  Failure(const std::string& what, const std::exception& cause) : Failure(what, error_kind(cause)) {}
};

// The basis specs every command that takes one accepts (spline/basis.hpp), for --help.
inline constexpr const char* basis_specs =
    "catmull-rom, cardinal:a=A, bspline, tensioned-bspline:a=A, beta:b1=B1,b2=B2, "
    "uniform-bspline:degree=N, mitchell-netravali:b=B,c=C";

// A spec given to `flag`, read by `parse` (parse_basis, parse_kernel, ...): its SpecError
// becomes a Failure naming the flag.
template <class Parse>
auto parse_spec_flag(const std::string& flag, const std::string& spec, Parse&& parse) -> decltype(parse(spec)) {
  try {
    return parse(spec);
  } catch (const SpecError& e) {
    throw Failure(flag + ": " + e.what());
  }
}

// printable(text): spline/points_csv.hpp (input bytes shown escaped in one-line messages).
using splinefig::printable;

// A file the command reads by name (a spec, a CSV): it must be a regular file, so that a
// directory is not taken for an empty input and a FIFO or device (/dev/zero) cannot hang the
// command. `what` names it ("-o", "--betas", or empty for a positional argument).
inline void check_input_file(const std::string& path, const std::string& what = "") {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  const std::string name = (what.empty() ? "" : what + " ") + path;
  if (ec || !fs::exists(st)) return;  // the reader says it is missing, as it always has
  if (fs::is_directory(st)) throw Failure(name + ": is a directory, not a file");
  if (!fs::is_regular_file(st)) throw Failure(name + ": not a regular file (a FIFO, socket or device)");
}

// A number said back in a message: the shortest text that reads back as `v` ("1e+308",
// "1e-308", "64.0001"), neither std::to_string's 300 digits nor its "0.000000".
inline std::string number_text(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// A number flag's value as the user typed it (the last time it was given): `v` read from that
// text as a double (strtod; `overflow` when beyond a double's range, as 1e400 is), and `said`
// the flag and the value as a message names them: the value in its shortest form when it reads
// as a finite double ("--scale -1e+300"), else as typed, at most 40 bytes ("--scale 1e400", not
// the "inf" CLI11 stored). A flag not given is said with its value `stored`.
struct TypedNumber {
  double v;
  bool overflow;
  std::string said;
};
inline TypedNumber typed_number(const CLI::App& app, const std::string& flag, double stored) {
  const CLI::Option* o = app.get_option_no_throw(flag);
  if (!o || o->count() == 0 || o->results().empty()) return {stored, false, flag + " " + number_text(stored)};
  const std::string& text = o->results().back();
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const bool whole = !text.empty() && end == text.c_str() + text.size();
  const bool overflow = whole && errno == ERANGE && std::isinf(v);
  const std::string shown = whole && std::isfinite(v) ? number_text(v) : text.size() <= 40 ? text : excerpt(text);
  return {whole ? v : stored, overflow, flag + " " + shown};
}

// The flags shared by the commands that render figures; `said`: the flag and its value as
// typed_number says them (by default from the value).
inline void check_output_scale(double scale, const std::string& said = "") {
  if (!(scale > 0) || scale > 64) throw Failure((said.empty() ? "--scale " + number_text(scale) : said) + ": must be in (0, 64]");
}
// --threads N: 0 is every core; more than kMaxThreads is kMaxThreads (docs/cli.md).
inline int check_threads(int threads) {
  if (threads < 0) throw Failure("--threads " + std::to_string(threads) + ": must not be negative");
  return std::min(threads, splinefig::kMaxThreads);
}
// --dpi N: spec pixels per inch, 0 (the default) for none, else in [kMinDpi, kMaxDpi].
inline double check_dpi(double dpi, const std::string& said = "") {
  if (dpi != 0 && !(dpi >= splinefig::kMinDpi && dpi <= splinefig::kMaxDpi)) {
    throw Failure((said.empty() ? "--dpi " + number_text(dpi) : said) + ": must be in [" + number_text(splinefig::kMinDpi) + ", " +
                  number_text(splinefig::kMaxDpi) + "]");
  }
  return dpi;
}

// --coverage-tolerance T: in [0, 1], a fraction of full coverage (0: the exact sweep everywhere);
// it replaces the spec's [canvas] coverage_tolerance (docs/renderer.md, "Dense strokes").
inline double check_coverage_tolerance(double t, const std::string& said = "") {
  if (!(t >= 0 && t <= 1))
    throw Failure((said.empty() ? "--coverage-tolerance " + number_text(t) : said) +
                  ": must be in [0, 1] (a fraction of full coverage; 0: exact)");
  return t;
}

// A line on stderr saying what a long command is doing ("splinefig resample: filtering ..."),
// shown only on a terminal (never when stderr is piped or redirected) and only when `large`;
// each say() replaces it, and it is erased when the object goes.
class ProgressLine {
 public:
  ProgressLine(const char* command, bool large) : command_(command), on_(large && ::isatty(2)) {}
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  void say(const std::string& what) const {
    if (on_) std::fprintf(stderr, "\r\x1b[Ksplinefig %s: %s...", command_, printable(what).c_str()), std::fflush(stderr);
  }
  ~ProgressLine() {
    if (on_) std::fprintf(stderr, "\r\x1b[K"), std::fflush(stderr);
  }

 private:
  const char* command_;
  bool on_;
};

}  // namespace splinefig::cli
