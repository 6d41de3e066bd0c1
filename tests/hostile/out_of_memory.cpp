// A figure that runs out of memory (figures --scale 8 under ulimit -v) is one line naming the
// spec and what it needed, not a bare "std::bad_alloc"; the other figures' results stand.
#include "hostile.hpp"
#include "skip.hpp"

using namespace splinefig::hostile;

TEST_CASE("a figure out of memory is one line naming the spec and its canvas, not std::bad_alloc") {
#if defined(__SANITIZE_ADDRESS__)
  splinefig::testing_support::skip("ulimit -v cannot limit a program built with AddressSanitizer");
  return;
#endif
  const fs::path dir = scratch();
  const std::string specs = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs";
  // 6400 x 4000 float RGBA pixels need 391 MiB, over the 300 MB of address space with the
  // program's own; at --scale 1 the same figure fits.
  const std::string cmd = "cd " + splinefig::test::shell_quote(dir.string()) + " && ulimit -v 300000 && timeout -s KILL " +
                          std::to_string(kTimeLimit) + " " + splinefig::test::shell_quote(SPLINEFIG_EXE) +
                          " figures --specs " + splinefig::test::shell_quote(specs) +
                          " --out out --only bias --threads 1 --scale 8 > out.txt 2> err.txt";
  const int status = std::system(cmd.c_str());
  const std::string err = splinefig::test::slurp(dir / "err.txt");
  INFO(err);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(err == "splinefig figures: " + specs +
                   "/bias.toml: out of memory rendering the figure (6400 x 4000 px at --scale 8, 391 MiB as a float RGBA "
                   "image)\nsplinefig figures: 1 of 1 figures failed\n");
  CHECK(err.find("bad_alloc") == std::string::npos);
  CHECK_FALSE(fs::exists(dir / "out" / "bias.png"));
  fs::remove_all(dir);
}

TEST_CASE("render out of memory is one line naming the spec and its canvas, not std::bad_alloc") {
#if defined(__SANITIZE_ADDRESS__)
  splinefig::testing_support::skip("ulimit -v cannot limit a program built with AddressSanitizer");
  return;
#endif
  const fs::path dir = scratch();
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml";
  const std::string cmd = "cd " + splinefig::test::shell_quote(dir.string()) + " && ulimit -v 300000 && timeout -s KILL " +
                          std::to_string(kTimeLimit) + " " + splinefig::test::shell_quote(SPLINEFIG_EXE) + " render " +
                          splinefig::test::shell_quote(spec) + " -o bias.png --threads 1 --scale 8 > out.txt 2> err.txt";
  const int status = std::system(cmd.c_str());
  const std::string err = splinefig::test::slurp(dir / "err.txt");
  INFO(err);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(err == "splinefig render: " + spec +
                   ": out of memory rendering the figure (6400 x 4000 px at --scale 8, 391 MiB as a float RGBA image)\n");
  CHECK_FALSE(fs::exists(dir / "bias.png"));
  fs::remove_all(dir);
}

// Loading the image I/O module (OpenImageIO and its dependencies) under an address-space or
// data limit that maps its libraries but not the threads their initialisers start died by
// SIGSEGV or abort ("terminate called without an active exception"), with nothing to catch:
// figures --format exr did so under ulimit -v 400000 to 440000 and ulimit -d 60000 to 100000.
// Across and beyond that window every run either writes its figure or refuses in one line
// and writes nothing.
TEST_CASE("loading the image I/O module under a memory limit is one line or success, never a signal") {
#if defined(__SANITIZE_ADDRESS__)
  splinefig::testing_support::skip("ulimit -v cannot limit a program built with AddressSanitizer");
  return;
#endif
  const fs::path dir = scratch();
  const std::string specs = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs";
  int refused = 0, written = 0;
  auto run = [&](const std::string& limit) {
    fs::remove_all(dir / "out");
    const std::string cmd = "cd " + splinefig::test::shell_quote(dir.string()) + " && " + limit + " && timeout -s KILL " +
                            std::to_string(kTimeLimit) + " " + splinefig::test::shell_quote(SPLINEFIG_EXE) +
                            " figures --specs " + splinefig::test::shell_quote(specs) +
                            " --out out --only bias --format exr --threads 1 > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    const std::string err = splinefig::test::slurp(dir / "err.txt");
    INFO(limit << ": " << err);
    REQUIRE(WIFEXITED(status));
    if (WEXITSTATUS(status) == 0) {
      ++written;
      CHECK(fs::exists(dir / "out" / "bias.exr"));
      return;
    }
    ++refused;
    CHECK(WEXITSTATUS(status) == 2);
    CHECK_FALSE(fs::exists(dir / "out" / "bias.exr"));
    // The figure's line and the batch's count, nothing from a library.
    const std::string first = err.substr(0, err.find('\n') + 1);
    CHECK(first.rfind("splinefig figures: " + specs + "/bias.toml: ", 0) == 0);
    CHECK(err.substr(first.size()) == "splinefig figures: 1 of 1 figures failed\n");
  };
  for (int kb = 300000; kb <= 640000; kb += 20000) run("ulimit -v " + std::to_string(kb));
  for (int kb = 40000; kb <= 200000; kb += 10000) run("ulimit -d " + std::to_string(kb));
  // The sweeps reach both sides: refusals under the tightest limits, the figure under the loosest.
  CHECK(refused > 0);
  CHECK(written > 0);
  fs::remove_all(dir);
}

// Writing EXRs under a limit once the module is loaded: OpenEXR's worker threads died by
// SIGSEGV in copyFromFrameBuffer when the limit refused their buffers (2 runs in 6 under
// ulimit -v 540000 at --scale 3). Every run ends in an exit status, with splinefig's lines only.
TEST_CASE("writing EXRs under an address-space limit ends in an exit status, never a signal") {
#if defined(__SANITIZE_ADDRESS__)
  splinefig::testing_support::skip("ulimit -v cannot limit a program built with AddressSanitizer");
  return;
#endif
  const fs::path dir = scratch();
  const std::string specs = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs";
  for (int kb = 500000; kb <= 900000; kb += 40000) {
    fs::remove_all(dir / "out");
    const std::string cmd = "cd " + splinefig::test::shell_quote(dir.string()) + " && ulimit -v " + std::to_string(kb) +
                            " && timeout -s KILL " + std::to_string(kTimeLimit) + " " +
                            splinefig::test::shell_quote(SPLINEFIG_EXE) + " figures --specs " +
                            splinefig::test::shell_quote(specs) +
                            " --out out --only bias,filter-zoneplate --format png,exr --scale 3 > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    const std::string err = splinefig::test::slurp(dir / "err.txt");
    INFO("ulimit -v " << kb << ": " << err);
    REQUIRE(WIFEXITED(status));
    CHECK((WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 2));
    for (std::size_t at = 0; at < err.size(); at = err.find('\n', at) + 1) CHECK(err.compare(at, 19, "splinefig figures: ") == 0);
  }
  fs::remove_all(dir);
}
