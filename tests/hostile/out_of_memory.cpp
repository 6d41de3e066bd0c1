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
