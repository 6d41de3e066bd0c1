#pragma once
// Test helpers: images written straight through OpenImageIO (not through the code under test),
// a scratch directory, and running commands (splinefig, and idiff as a peer when installed).
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace test_support {

// A directory of this process's own (ctest runs test cases in parallel processes), emptied
// when the process starts.
inline std::string scratch(const std::string& name) {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::path(SPLINEFIG_BINARY_DIR) / "test-work" / "compare" / std::to_string(::getpid());
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
  }();
  return (dir / name).string();
}

// Writes `values` (w * h * nch floats) in `format` (TypeUInt8, TypeUInt16, TypeHalf, TypeFloat).
inline void write_raw(const std::string& path, int w, int h, int nch, const std::vector<float>& values,
                      OIIO::TypeDesc format, bool straight_alpha = true) {
  OIIO::ImageSpec spec(w, h, nch, format);
  if (straight_alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
  auto out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeFloat, values.data()) || !out->close())
    throw std::runtime_error("test could not write " + path);
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Run {
  int code = -1;
  std::string out, err;
};

inline Run run(const std::string& command) {
  const std::string o = scratch("cmd.out"), e = scratch("cmd.err");
  const int status = std::system((command + " > '" + o + "' 2> '" + e + "'").c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(o);
  r.err = read_text(e);
  return r;
}

inline Run run_splinefig(const std::string& args) { return run(std::string("'") + SPLINEFIG_EXE + "' " + args); }

// OpenImageIO's idiff is the peer (Debian's openimageio-tools, installed by scripts/deps).
inline bool have_idiff() { return std::system("command -v idiff > /dev/null 2>&1") == 0; }
inline Run idiff(const std::string& args) { return run("idiff " + args); }

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

}  // namespace test_support
