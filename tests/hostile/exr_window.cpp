// Found by fuzz_resample: an OpenEXR header whose data window is 16775427 x 3 pixels made
// OpenEXR allocate 2 GB while opening the file, before the size was checked against the limits
// (65536 a side): under a 800 MB address space the message was "OpenEXR exception:
// std::bad_alloc". The header check now refuses the window before OpenEXR sees it.
#include "hostile.hpp"

using namespace splinefig::hostile;

// Under AddressSanitizer, which reserves terabytes of shadow memory and so cannot run under
// ulimit -v, the same input runs without the limit: it is still refused from the header, and the
// sanitizer watches the path it takes.
TEST_CASE("an OpenEXR data window over the limits is refused from the header, in little memory") {
#if defined(__SANITIZE_ADDRESS__)
  const std::string limit = "";
#else
  const std::string limit = "ulimit -v 800000 && ";
#endif
  const fs::path dir = scratch();
  const std::string exr = std::string(SPLINEFIG_SOURCE_DIR) + "/tests/hostile/data/exr_wide_window.exr";
  fs::copy_file(exr, dir / "wide.exr");
  const std::string cmd = "cd " + splinefig::test::shell_quote(dir.string()) + " && " + limit + "timeout -s KILL " +
                          std::to_string(kTimeLimit) + " " + splinefig::test::shell_quote(SPLINEFIG_EXE) +
                          " diff wide.exr wide.exr > out.txt 2> err.txt";
  const int status = std::system(cmd.c_str());
  const std::string err = splinefig::test::slurp(dir / "err.txt");
  INFO(err);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 4);
  CHECK(err == "splinefig diff: cannot read wide.exr: image too large (16775427 x 3 pixels, limit 65536 a side)\n");
  fs::remove_all(dir);
}
