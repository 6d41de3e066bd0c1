// The commands under a file-size limit (writes fail with EFBIG, as on a full disk): an error
// naming the file, a non-zero exit, and no partial or empty file left under any name.
#include "scratch.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

struct Result {
  int code;
  std::string err;
};

// `args` run by the splinefig binary with a 16 KiB file-size limit and SIGXFSZ ignored.
Result run_limited(const fs::path& dir, const std::string& args) {
  const fs::path err = dir.parent_path() / (dir.filename().string() + ".err");
  const std::string cmd = "ulimit -f 16; trap '' XFSZ; exec '" + std::string(SPLINEFIG_EXE) + "' " + args + " 2>'" +
                          err.string() + "' >/dev/null";
  const int status = std::system(("sh -c \"" + cmd + "\"").c_str());
  std::ifstream in(err);
  Result r{WIFEXITED(status) ? WEXITSTATUS(status) : -1,
           std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())};
  fs::remove(err);
  return r;
}

}  // namespace

TEST_CASE("cli: render and figures on a full disk fail, naming the file, and leave no partial file") {
  const auto dir = scratch_dir("cli-full-disk");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml";
  const fs::path png = dir / "bias.png";
  const Result r = run_limited(dir, "render '" + spec + "' -o '" + png.string() + "' --scale 2");
  CHECK(r.code != 0);
  CHECK(r.err.find(png.string()) != std::string::npos);
  CHECK(r.err.find("File too large") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(fs::is_empty(dir));

  const fs::path out = dir / "gallery";
  fs::create_directories(out);
  const Result f = run_limited(dir, "figures --only bias --scale 2 --out '" + out.string() + "'");
  CHECK(f.code != 0);
  for (const auto& e : fs::directory_iterator(out)) {
    INFO(e.path());
    CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
    CHECK(e.path().extension() != ".png");  // no empty or truncated figure
  }
}
