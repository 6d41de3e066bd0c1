// `splinefig resample` end to end: file formats, colour handling, and bad input.
#include <catch2/catch.hpp>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// One directory per test case: ctest runs them in parallel.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(SPLINEFIG_BINARY_DIR) / "test-resample-cli" / name;
  fs::create_directories(dir);
  return dir;
}

struct Run {
  int code;
  std::string err;
};

Run run(const std::string& args) {
  const fs::path err = fs::path(SPLINEFIG_BINARY_DIR) / "test-resample-cli" /
                       ("stderr-" + std::to_string(::getpid()) + ".txt");
  const std::string cmd = std::string("\"") + SPLINEFIG_EXE + "\" resample " + args + " 2> \"" + err.string() + "\"";
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

void write(const fs::path& p, int w, int h, int c, OIIO::TypeDesc type, const std::vector<float>& data,
           std::vector<std::string> names = {}) {
  OIIO::ImageSpec spec(w, h, c, type);
  if (!names.empty()) spec.channelnames = names;
  if (c == 4 || c == 2) spec.alpha_channel = c - 1;
  if (type != OIIO::TypeDesc::FLOAT) spec.attribute("oiio:UnassociatedAlpha", 1);
  auto out = OIIO::ImageOutput::create(p.string());
  REQUIRE(out);
  REQUIRE(out->open(p.string(), spec));
  REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, data.data()));
  out->close();
}

struct Read {
  OIIO::ImageSpec spec;
  std::vector<float> data;
};
Read read(const fs::path& p) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(p.string(), &config);
  REQUIRE(in);
  Read r{in->spec(), {}};
  r.data.resize(static_cast<size_t>(r.spec.width) * r.spec.height * r.spec.nchannels);
  REQUIRE(in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, r.data.data()));
  return r;
}

// A path in double quotes for the shell (built up by appending: GCC 12 warns falsely about
// "literal" + std::string temporaries).
std::string q(const fs::path& p) {
  std::string s = "\"";
  s += p.string();
  s += '"';
  return s;
}

double srgb_encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

}  // namespace

TEST_CASE("resample cli: bad input gives one line, a non-zero exit and no output file") {
  const fs::path dir = scratch("bad-input");
  const fs::path in = dir / "in.png", out = dir / "bad-out.png";
  write(in, 8, 6, 3, OIIO::TypeDesc::UINT8, std::vector<float>(8 * 6 * 3, 0.5f));
  const std::string I = q(in), O = " -o " + q(out);
  const std::pair<std::string, std::string> cases[] = {
      {I + O + " --scale 2 --filter gauss", "unknown filter 'gauss'"},
      {I + O + " --size 0x5 --filter bspline", "--size width"},
      {I + O + " --size 70000x5 --filter bspline", "out of range"},
      {I + O + " --scale -2 --filter bspline", "must be positive"},
      {I + O + " --scale 0.01 --filter bspline", "becomes 0"},
      {I + O + " --scale 2 --filter beta:b1=5 --interpolating", "no stable inverse"},
      {q(dir / "missing.png") + O + " --scale 2 --filter bspline", "missing.png"},
      {I + " -o " + q(dir / "out.bmp") + " --scale 2 --filter bspline", "unsupported output format"},
  };
  for (const auto& [args, what] : cases) {
    INFO(args);
    const Run r = run(args);
    CHECK(r.code != 0);
    CHECK(r.err.find(what) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(out));
  }
  // A truncated file is unreadable.
  {
    std::ifstream src(in, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(src)), std::istreambuf_iterator<char>());
    std::ofstream(dir / "cut.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  const Run r = run(q(dir / "cut.png") + O + " --scale 2 --filter bspline");
  CHECK(r.code != 0);
  CHECK_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
}

TEST_CASE("resample cli: the output may not be the input, by any spelling") {
  const fs::path dir = scratch("alias");
  const fs::path in = dir / "in.png";
  write(in, 8, 6, 3, OIIO::TypeDesc::UINT8, std::vector<float>(8 * 6 * 3, 0.5f));
  std::ifstream orig(in, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(orig)), std::istreambuf_iterator<char>());
  fs::remove(dir / "link.png");
  fs::remove(dir / "hard.png");
  fs::create_symlink(in, dir / "link.png");
  fs::create_hard_link(in, dir / "hard.png");
  for (const fs::path& out : {in, dir / "." / "in.png", dir / "link.png", dir / "hard.png"}) {
    INFO(out);
    const Run r = run(q(in) + " -o " + q(out) + " --scale 2 --filter bspline");
    CHECK(r.code != 0);
    CHECK(r.err.find("it is the input") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  std::ifstream after(in, std::ios::binary);
  CHECK(std::string((std::istreambuf_iterator<char>(after)), std::istreambuf_iterator<char>()) == bytes);
}

TEST_CASE("resample cli: 8-bit PNG is filtered in linear light and re-encoded as sRGB") {
  const fs::path dir = scratch("colour");
  // Black and white averaged by a box: linear 0.5, which sRGB encodes as code 188, not 128.
  write(dir / "bw.png", 2, 1, 1, OIIO::TypeDesc::UINT8, {0.0f, 1.0f});
  REQUIRE(run(q(dir / "bw.png") + " -o " + q(dir / "bw-1.png") + " --size 1x1 --filter box").code == 0);
  const Read bw = read(dir / "bw-1.png");
  CHECK(bw.spec.format == OIIO::TypeDesc::UINT8);
  CHECK(std::lround(bw.data[0] * 255) == std::lround(srgb_encode(0.5) * 255));
  // Straight alpha is premultiplied for filtering: opaque red next to transparent green
  // averages to red at half coverage, with no green.
  write(dir / "rgba.png", 2, 1, 4, OIIO::TypeDesc::UINT8, {1, 0, 0, 1, 0, 1, 0, 0});
  REQUIRE(run(q(dir / "rgba.png") + " -o " + q(dir / "rgba-1.png") + " --size 1x1 --filter box").code == 0);
  const Read rgba = read(dir / "rgba-1.png");
  REQUIRE(rgba.spec.nchannels == 4);
  CHECK(rgba.data[0] == 1.0f);
  CHECK(rgba.data[1] == 0.0f);
  CHECK(std::lround(rgba.data[3] * 255) == 128);
}

TEST_CASE("resample cli: same size with --interpolating returns the PNG, threads do not change it") {
  const fs::path dir = scratch("identity");
  std::vector<float> px(40 * 30 * 3);
  for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<float>((i * 7919 % 256) / 255.0);
  write(dir / "noise.png", 40, 30, 3, OIIO::TypeDesc::UINT8, px);
  const std::string I = q(dir / "noise.png");
  REQUIRE(run(I + " -o " + q(dir / "same.png") + " --size 40x30 --filter bspline --interpolating --edge mirror").code == 0);
  CHECK(read(dir / "same.png").data == read(dir / "noise.png").data);
  REQUIRE(run(I + " -o " + q(dir / "t1.exr") + " --scale 2.5,1.5 --filter catmull-rom --threads 1").code == 0);
  REQUIRE(run(I + " -o " + q(dir / "t2.exr") + " --scale 2.5,1.5 --filter catmull-rom --threads 2").code == 0);
  const Read t1 = read(dir / "t1.exr"), t2 = read(dir / "t2.exr");
  CHECK(t1.spec.width == 100);
  CHECK(t1.spec.height == 45);
  CHECK(t1.data == t2.data);
}

TEST_CASE("resample cli: EXR keeps its channels and names, 16-bit PNG stays 16-bit") {
  const fs::path dir = scratch("channels");
  std::vector<float> px(6 * 4 * 5);
  for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<float>(i) * 0.25f - 3;
  write(dir / "five.exr", 6, 4, 5, OIIO::TypeDesc::FLOAT, px, {"R", "G", "B", "Z", "mask"});
  REQUIRE(run(q(dir / "five.exr") + " -o " + q(dir / "five-2.exr") + " --scale 2 --filter tent").code == 0);
  const Read five = read(dir / "five-2.exr");
  CHECK(five.spec.nchannels == 5);
  CHECK(five.spec.channelnames == std::vector<std::string>{"R", "G", "B", "Z", "mask"});
  CHECK(five.spec.format == OIIO::TypeDesc::FLOAT);
  CHECK(five.spec.width == 12);
  const Run png5 = run(q(dir / "five.exr") + " -o " + q(dir / "five.png") + " --scale 2 --filter tent");
  CHECK(png5.code != 0);
  CHECK(png5.err.find("1 to 4 channels") != std::string::npos);
  write(dir / "deep.png", 5, 5, 1, OIIO::TypeDesc::UINT16, std::vector<float>(25, 0.3f));
  REQUIRE(run(q(dir / "deep.png") + " -o " + q(dir / "deep-2.png") + " --scale 2 --filter bspline").code == 0);
  const Read deep = read(dir / "deep-2.png");
  CHECK(deep.spec.format == OIIO::TypeDesc::UINT16);
  CHECK(deep.data[0] == Approx(0.3).margin(1.0 / 65535));
}
