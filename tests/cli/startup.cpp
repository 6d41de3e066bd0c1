// Start-up: a command that touches no image file must not load the image I/O module (and with
// it OpenImageIO and its hundreds of shared libraries). What a process loads is taken from the
// dynamic loader's own account (LD_DEBUG=files, one file per process through LD_DEBUG_OUTPUT).
#include "cli/run.hpp"
#include "skip.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace splinefig::test;
namespace fs = std::filesystem;

namespace {

struct Loaded {
  Run run;
  std::vector<std::string> objects;  // every shared object the program loaded, as the loader names it
  bool oiio_needed_by_program = false;  // the program itself lists OpenImageIO (DT_NEEDED)
};

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-startup-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs splinefig with the loader's debug output on and returns what the splinefig process loaded.
Loaded loaded_by(const std::vector<std::string>& args, const std::string& input = "") {
  static int counter = 0;
  const fs::path dir = scratch("ld" + std::to_string(counter++));
  ::setenv("LD_DEBUG", "files", 1);
  ::setenv("LD_DEBUG_OUTPUT", (dir / "ld").c_str(), 1);
  Loaded l;
  l.run = run(args, input);
  ::unsetenv("LD_DEBUG");
  ::unsetenv("LD_DEBUG_OUTPUT");
  int programs = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string text = slurp(entry.path());
    // The files of the shell and of `timeout` that run.hpp starts are not splinefig's.
    if (text.find("initialize program: " + std::string(SPLINEFIG_EXE) + "\n") == std::string::npos) continue;
    ++programs;
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) {
      const auto at = line.find("file=");
      if (at == std::string::npos) continue;
      const auto end = line.find(" [", at);
      const std::string name = line.substr(at + 5, end - at - 5);
      if (line.find("generating link map") != std::string::npos) l.objects.push_back(name);
      if (name.find("libOpenImageIO.so") == 0 &&
          line.find("needed by " + std::string(SPLINEFIG_EXE) + " [") != std::string::npos)
        l.oiio_needed_by_program = true;
    }
  }
  fs::remove_all(dir);
  REQUIRE(programs == 1);
  return l;
}

bool has(const std::vector<std::string>& objects, const std::string& part) {
  return std::any_of(objects.begin(), objects.end(), [&](const std::string& o) { return o.find(part) != std::string::npos; });
}

const std::string knots = "0,0\n1,2\n3,3\n4,1\n";

// The commands of the start-up goal, each with the exit code it must give.
struct Case {
  std::vector<std::string> args;
  std::string input;
  int code;
};
std::vector<Case> imageless_commands() {
  return {
      {{"eval", "--basis", "bspline"}, knots, 0},
      {{"--version"}, "", 0},
      {{"--help"}, "", 0},
      {{"version"}, "", 0},
      {{"kernel", "--basis", "catmull-rom"}, "", 0},
      {{"interp", "--output", "bspline"}, knots, 0},
      {{"diff", "only-one.png"}, "", 2},                 // an argument error
      {{"render", "spec.toml"}, "", 2},                  // an argument error (no --output)
      {{"diff", "/nonexistent/a.png", "/nonexistent/b.png"}, "", 4},  // unreadable, found before decoding
  };
}

std::string describe(const std::vector<std::string>& args) {
  std::string s = "splinefig";
  for (const auto& a : args) s += " " + a;
  return s;
}

}  // namespace

TEST_CASE("commands that touch no image file do not load the image I/O module") {
  for (const Case& c : imageless_commands()) {
    INFO(describe(c.args));
    const Loaded l = loaded_by(c.args, c.input);
    CHECK(l.run.code == c.code);
    CHECK_FALSE(l.objects.empty());
    CHECK_FALSE(has(l.objects, "splinefig_image_oiio"));
  }
  // The check can see the module: writing an EXR loads it.
  const fs::path dir = scratch("write");
  const Loaded w = loaded_by({"render", std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml", "-o",
                              (dir / "cbasis.exr").string()});
  CHECK(w.run.code == 0);
  CHECK(has(w.objects, "splinefig_image_oiio"));
  CHECK(has(w.objects, "libOpenImageIO.so"));
  fs::remove_all(dir);
}

TEST_CASE("writing PNG figures does not load the image I/O module: libpng encodes them") {
  const fs::path dir = scratch("write-png");
  const Loaded r = loaded_by({"render", std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml", "-o",
                              (dir / "cbasis.png").string()});
  CHECK(r.run.code == 0);
  CHECK(fs::exists(dir / "cbasis.png"));
  CHECK_FALSE(has(r.objects, "splinefig_image_oiio"));
  CHECK_FALSE(has(r.objects, "libOpenImageIO"));
  const Loaded f = loaded_by({"figures", "--only", "cbasis,bias", "--out", (dir / "figs").string()});
  CHECK(f.run.code == 0);
  CHECK(fs::exists(dir / "figs" / "bias.png"));
  CHECK_FALSE(has(f.objects, "splinefig_image_oiio"));
  fs::remove_all(dir);
}

TEST_CASE("commands that touch no image file load no OpenImageIO and at most 30 shared objects") {
  if (loaded_by({"--version"}).oiio_needed_by_program) {
    splinefig::testing_support::skip("the splinefig program itself links OpenImageIO (DT_NEEDED), so every "
                                     "process loads it whatever image/ does");
    return;
  }
  for (const Case& c : imageless_commands()) {
    INFO(describe(c.args));
    const Loaded l = loaded_by(c.args, c.input);
    CHECK(l.run.code == c.code);
    CHECK_FALSE(has(l.objects, "libOpenImageIO"));
    // The sanitizers' runtimes (libasan, libubsan, ...) are the build's instrumentation, loaded
    // into every process of a sanitized build: not counted.
    const auto own = std::count_if(l.objects.begin(), l.objects.end(), [](const std::string& o) {
      return o.find("libasan.so") == std::string::npos && o.find("libubsan.so") == std::string::npos &&
             o.find("liblsan.so") == std::string::npos && o.find("libtsan.so") == std::string::npos;
    });
    CHECK(own <= 30);
  }
}

TEST_CASE("a missing image I/O module is a one-line error that writes nothing") {
  const fs::path dir = scratch("missing");
  ::setenv("SPLINEFIG_IMAGE_MODULE", (dir / "no-such-module.so").c_str(), 1);
  const Run r = run({"render", std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml", "-o",
                     (dir / "cbasis.exr").string()});
  ::unsetenv("SPLINEFIG_IMAGE_MODULE");
  CHECK(r.code != 0);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find("cannot find the image I/O module") != std::string::npos);
  CHECK(r.err.find((dir / "no-such-module.so").string()) != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "cbasis.exr"));
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 0);
  fs::remove_all(dir);
}
