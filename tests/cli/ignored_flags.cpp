// A flag that would change nothing is refused, not silently ignored: one line naming it, exit 2,
// nothing on stdout. Each case is a combination where the command used to run as if the flag
// were not there.
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using splinefig::test::count_lines;
using splinefig::test::run;

namespace {

void check_refused(const std::vector<std::string>& args, const std::string& line, const std::string& input = "") {
  const auto r = run(args, input);
  std::string cmd = "splinefig";
  for (const auto& a : args) cmd += " " + a;
  INFO(cmd << "\nstdout: " << r.out.substr(0, 200) << "\nstderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err == "splinefig " + args[0] + ": " + line + "\n");
}

const std::string kKnots = "0,0\n1,1\n2,0\n3,1\n4,0\n";

}  // namespace

TEST_CASE("ignored flags: kernel --report with --response, --from/--to/--step or --delimiter is refused") {
  check_refused({"kernel", "--basis", "bspline", "--report", "--response"},
                "--report and --response cannot be combined (--report prints the filter's numbers, "
                "--response its f,|K(f)| lines)");
  for (const char* flag : {"--from", "--to", "--step"})
    check_refused({"kernel", "--basis", "bspline", "--report", flag, "0.5"},
                  "--report takes no --from, --to or --step (it reports on the whole filter)");
  check_refused({"kernel", "--basis", "bspline", "--from", "0", "--delimiter", "tab"},
                "--delimiter applies only to an INPUT file of values");
  // Still accepted: each flag where it does something.
  CHECK(run({"kernel", "--basis", "bspline", "--report"}).code == 0);
  CHECK(run({"kernel", "--basis", "bspline", "--response", "--from", "0", "--to", "1", "--step", "0.5"}).code == 0);
  CHECK(run({"kernel", "--basis", "bspline", "-", "--delimiter", "tab"}, "0\n1\n").code == 0);
}

TEST_CASE("ignored flags: eval --grain with --spacing arclength, interp --grain with bspline or bezier output") {
  check_refused({"eval", "--basis", "catmull-rom", "--spacing", "arclength", "--count", "5", "--grain", "4"},
                "--grain has no effect with --spacing arclength (its rows are the --count points)", kKnots);
  for (const char* out : {"bspline", "bezier"})
    check_refused({"interp", "--output", out, "--grain", "4"}, "--grain applies only to --output curve", kKnots);
  CHECK(run({"eval", "--basis", "catmull-rom", "--spacing", "polygon", "--count", "5", "--grain", "4"}, kKnots).code == 0);
  CHECK(run({"interp", "--output", "curve", "--grain", "4"}, kKnots).code == 0);
}

TEST_CASE("ignored flags: diff --scale without --diff-image or --triptych is refused") {
  check_refused({"diff", "a.png", "b.png", "--scale", "4"}, "--scale applies only to --diff-image and --triptych");
}
