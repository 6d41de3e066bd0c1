// libFuzzer harness: the CSV point reader of every subcommand (cli/csv.hpp), and the writer on
// what it read. Any input must give points that write and read back exactly, or one Failure
// line; anything else is a finding.
#include "points_io.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1 << 16) return 0;
  using namespace splinefig;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  Points p;
  try {
    p = cli::read_points(in, "fuzz.csv");
  } catch (const cli::Failure& e) {
    const std::string m = e.what();
    if (m.rfind("fuzz.csv", 0) != 0 || m.find('\n') != std::string::npos) {
      std::fprintf(stderr, "fuzz_csv: badly formed error: %s\n", e.what());
      std::abort();
    }
    return 0;
  }
  std::istringstream again(cli::format_points(p));
  const Points q = cli::read_points(again, "again");
  if (q.dim != p.dim || q.coords != p.coords) {
    std::fprintf(stderr, "fuzz_csv: the points do not read back\n");
    std::abort();
  }
  return 0;
}
