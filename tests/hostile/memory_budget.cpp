// The memory `figures` takes does not grow with --threads: the figures rendered at once share a
// budget (at most one per core, and only as many canvases as the memory left holds), and under
// an address-space limit the thread pool starts only the helpers whose stacks and malloc arenas
// fit. So a run that fits under `ulimit -v` with two threads fits with 64, with the same bytes,
// and one that cannot fit fails with one line per figure naming it and its canvas.
#include "hostile.hpp"
#include "skip.hpp"

using namespace splinefig::hostile;

namespace {

using splinefig::test::shell_quote;
using splinefig::test::slurp;

const char* const kFigures[] = {"ends", "multiplicity", "s003-fig01", "s003-fig05"};  // spec order

// `splinefig figures` of kFigures into dir/out, under `ulimit -v kib` when kib > 0; the exit
// status and stderr.
std::pair<int, std::string> figures(const fs::path& dir, const std::string& out, int threads, int scale, long kib) {
  std::string only;
  for (const char* f : kFigures) {
    if (!only.empty()) only += ',';
    only += f;
  }
  const std::string cmd = "cd " + shell_quote(dir.string()) + " && " + (kib > 0 ? "ulimit -v " + std::to_string(kib) + " && " : "") +
                          "timeout -s KILL " + std::to_string(kTimeLimit) + " " + shell_quote(SPLINEFIG_EXE) +
                          " figures --specs " + shell_quote(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs") +
                          " --out " + out + " --only " + only + " --threads " + std::to_string(threads) + " --scale " +
                          std::to_string(scale) + " > " + out + ".txt 2> " + out + ".err";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / (out + ".err"))};
}

}  // namespace

TEST_CASE("figures under an address-space limit that two threads fit renders on 64 threads, byte for byte") {
#if defined(__SANITIZE_ADDRESS__)
  splinefig::testing_support::skip("ulimit -v cannot limit a program built with AddressSanitizer");
  return;
#endif
  const fs::path dir = scratch();
  // At --scale 4 each figure is 3200 x 2000 px, a 98 MiB float canvas. Measured with a Release
  // build: the four figures need about 170 MB of address space one at a time, 340 MB two at a
  // time; when every figure ran at once, one thread each (and one figure's 64 raster threads each
  // took a stack and a malloc arena), they needed 740-770 MB. 450 000 KiB is 461 MB.
  const auto ref = figures(dir, "ref", 1, 4, 0);
  REQUIRE(ref.first == 0);
  const auto limited = figures(dir, "t64", 64, 4, 450000);
  INFO(limited.second);
  CHECK(limited.first == 0);
  CHECK(limited.second.empty());
  for (const char* f : kFigures) {
    INFO(f);
    const std::string a = slurp(dir / "ref" / (std::string(f) + ".png")), b = slurp(dir / "t64" / (std::string(f) + ".png"));
    CHECK(!a.empty());
    CHECK(a == b);
  }
  // One figure alone gets the 64 threads for its rasterizer: they too must leave it its canvas.
  const std::string cmd = "cd " + shell_quote(dir.string()) + " && ulimit -v 450000 && timeout -s KILL " +
                          std::to_string(kTimeLimit) + " " + shell_quote(SPLINEFIG_EXE) + " figures --specs " +
                          shell_quote(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs") +
                          " --out one --only ends --threads 64 --scale 4 > one.txt 2> one.err";
  const int status = std::system(cmd.c_str());
  INFO(slurp(dir / "one.err"));
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(slurp(dir / "one" / "ends.png") == slurp(dir / "ref" / "ends.png"));
  fs::remove_all(dir);
}

TEST_CASE("figures under an address-space limit too small for any canvas: one line per figure, in spec order") {
#if defined(__SANITIZE_ADDRESS__)
  splinefig::testing_support::skip("ulimit -v cannot limit a program built with AddressSanitizer");
  return;
#endif
  const fs::path dir = scratch();
  // At --scale 8 an 800 x 500 canvas is 6400 x 4000 float RGBA pixels, 391 MiB, and
  // multiplicity's 800 x 560 is 6400 x 4480, 438 MiB: each more than the whole limit.
  const auto r = figures(dir, "out", 64, 8, 250000);
  std::string expected;
  for (const char* f : kFigures)
    expected += "splinefig figures: " + std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/" + f +
                ".toml: out of memory rendering the figure (" +
                (std::string(f) == "multiplicity" ? "6400 x 4480 px at --scale 8, 438 MiB" : "6400 x 4000 px at --scale 8, 391 MiB") +
                " as a float RGBA image)\n";
  expected += "splinefig figures: 4 of 4 figures failed\n";
  CHECK(r.first == 2);
  CHECK(r.second == expected);
  CHECK(r.second.find("bad_alloc") == std::string::npos);
  for (const char* f : kFigures) CHECK_FALSE(fs::exists(dir / "out" / (std::string(f) + ".png")));
  fs::remove_all(dir);
}
