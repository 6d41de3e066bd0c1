// `splinefig diff` beyond idiff: --json, --diff-image, --triptych, --mask, --linear, --ssim,
// --flip, and bad flags or outputs (a one-line message, non-zero exit, no partial file).
#include "support.hpp"

#include <splinefig/image/io.hpp>

#include <catch2/catch.hpp>

#include <filesystem>

using namespace splinefig;
using namespace test_support;
namespace fs = std::filesystem;

namespace {

std::string q(const std::string& p) { return "'" + p + "'"; }

// 20 x 16 RGB 8-bit: a grey ramp; `patch` adds a 4 x 4 square of +40/255 at (12, 4).
std::string ramp_png(const std::string& name, bool patch) {
  const std::string path = scratch(name);
  std::vector<float> v(20 * 16 * 3);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 20; ++x)
      for (int c = 0; c < 3; ++c) {
        int level = 10 * x + 2 * y;
        if (patch && x >= 12 && x < 16 && y >= 4 && y < 8) level += 40;
        v[std::size_t((y * 20 + x) * 3 + c)] = float(level) / 255.0f;
      }
  write_raw(path, 20, 16, 3, v, OIIO::TypeUInt8);
  return path;
}

}  // namespace

TEST_CASE("diff --json reports the numbers and the verdict as JSON") {
  const std::string a = ramp_png("cli_a.png", false), b = ramp_png("cli_b.png", true);
  const Run r = run_splinefig("diff --json " + q(a) + " " + q(b));
  CHECK(r.code == 2);
  for (const char* key : {"\"verdict\": \"FAILURE\"", "\"exit_code\": 2", "\"mean_error\": ", "\"psnr\": ",
                          "\"threshold\": 1e-06", "\"pixels_over\": 16",
                          "\"sizes_differ\": false", "\"failures\": []"})
    CHECK(r.out.find(key) != std::string::npos);
  CHECK(r.out.front() == '{');
  const Run same = run_splinefig("diff --json " + q(a) + " " + q(a));
  CHECK(same.code == 0);
  CHECK(same.out.find("\"psnr\": \"inf\"") != std::string::npos);
}

TEST_CASE("diff --diff-image and --triptych write pictures of the difference") {
  const std::string a = ramp_png("cli_a.png", false), b = ramp_png("cli_b.png", true);
  const std::string d = scratch("cli_diff.png"), t = scratch("cli_triptych.png");
  fs::remove(d);
  fs::remove(t);
  const Run r = run_splinefig("diff --diff-image " + q(d) + " --triptych " + q(t) + " --scale 4 " + q(a) + " " + q(b));
  CHECK(r.code == 2);
  const Image di = read_image(d), ti = read_image(t);
  CHECK(di.width == 20);
  CHECK(di.at(13, 5, 0) == Approx(std::lround(4.0 * 40.0) / 255.0).epsilon(1e-6));  // |a-b| * 4
  CHECK(di.at(2, 2, 1) == 0.0f);
  CHECK(ti.width == 3 * 20 + 4);
  CHECK(ti.height == 16);
}

TEST_CASE("diff --mask leaves out the masked pixels") {
  const std::string a = ramp_png("cli_a.png", false), b = ramp_png("cli_b.png", true);
  const std::string mask = scratch("cli_mask.png"), bad_mask = scratch("cli_mask_small.png");
  std::vector<float> m(20 * 16, 1.0f);
  for (int y = 4; y < 8; ++y)
    for (int x = 12; x < 16; ++x) m[std::size_t(y * 20 + x)] = 0.0f;
  write_raw(mask, 20, 16, 1, m, OIIO::TypeUInt8);
  write_raw(bad_mask, 4, 4, 1, std::vector<float>(16, 1.0f), OIIO::TypeUInt8);
  CHECK(run_splinefig("diff --mask " + q(mask) + " " + q(a) + " " + q(b)).code == 0);
  const Run r = run_splinefig("diff --mask " + q(bad_mask) + " " + q(a) + " " + q(b));
  CHECK(r.code != 0);
  CHECK(r.err.find("--mask") != std::string::npos);
}

TEST_CASE("diff --linear compares in linear light") {
  // sRGB 20/255 against 21/255 differ by 1/255 = 0.0039 encoded and by
  // ((21/255 + 0.055)/1.055)^2.4 - ((20/255 + 0.055)/1.055)^2.4 = 0.00050362 in linear light.
  const std::string a = scratch("lin_a.png"), b = scratch("lin_b.png");
  write_raw(a, 4, 4, 1, std::vector<float>(16, 20.0f / 255.0f), OIIO::TypeUInt8);
  write_raw(b, 4, 4, 1, std::vector<float>(16, 21.0f / 255.0f), OIIO::TypeUInt8);
  CHECK(run_splinefig("diff --fail 0.001 --warn 0.001 " + q(a) + " " + q(b)).code == 2);
  const Run r = run_splinefig("diff -v --linear --fail 0.001 --warn 0.001 " + q(a) + " " + q(b));
  CHECK(r.code == 0);
  CHECK(r.out.find("  Mean error = 0.00050362") != std::string::npos);
}

TEST_CASE("diff --ssim and --flip fail a comparison whose metric is out of bounds") {
  const std::string a = ramp_png("cli_a.png", false), b = ramp_png("cli_b.png", true);
  const Run ok = run_splinefig("diff --fail 1 --ssim 0.5 --flip 0.5 " + q(a) + " " + q(b));
  CHECK(ok.code == 0);
  const Run bad = run_splinefig("diff --fail 1 --ssim 0.9999 " + q(a) + " " + q(b));
  CHECK(bad.code == 2);
  CHECK(bad.out.find("  SSIM = ") != std::string::npos);
  CHECK(bad.out.find("is below 0.9999") != std::string::npos);
  CHECK(run_splinefig("diff --fail 1 --flip 0.0001 " + q(a) + " " + q(b)).code == 2);
}

TEST_CASE("diff rejects bad flags and unwritable outputs with one line, leaving no file") {
  const std::string a = ramp_png("cli_a.png", false);
  for (const char* flags : {"--fail nan", "--failpercent 101", "--shift -2", "--ssim 2"}) {
    const Run r = run_splinefig(std::string("diff ") + flags + " " + q(a) + " " + q(a));
    INFO(flags << ": " << r.err);
    CHECK(r.code != 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  const std::string out = scratch("no-such-dir/diff.png");
  const Run r = run_splinefig("diff --diff-image " + q(out) + " " + q(a) + " " + q(a));
  CHECK(r.code == 4);
  CHECK(r.err.find(out) != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("diff refuses an output that names an input, by any spelling, before writing anything") {
  const std::string a = ramp_png("alias_a.png", false), b = ramp_png("alias_b.png", true);
  const std::string link = scratch("alias_link.png"), hard = scratch("alias_hard.png");
  fs::remove(link);
  fs::remove(hard);
  fs::create_symlink(a, link);
  fs::create_hard_link(b, hard);
  const std::string a_bytes = read_text(a), b_bytes = read_text(b);
  const std::string dotted = (fs::path(a).parent_path() / "." / fs::path(a).filename()).string();
  for (const std::string& args : {"--diff-image " + q(a), "--triptych " + q(dotted), "--diff-image " + q(link),
                                  "--triptych " + q(hard)}) {
    INFO(args);
    const Run r = run_splinefig("diff " + q(a) + " " + q(b) + " " + args);
    CHECK(r.code == 4);
    CHECK(r.err.find("it is the input") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.out.empty());
  }
  CHECK(read_text(a) == a_bytes);
  CHECK(read_text(b) == b_bytes);
}
