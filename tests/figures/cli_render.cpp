// `splinefig render`: PNG and EXR out, --scale, and the same bytes for any --threads.
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace figtest;

TEST_CASE("splinefig render writes PNG and EXR, scaled, identical across thread counts") {
  auto dir = scratch("render-ok");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bbasis.toml";
  auto r = run(exe() + " render " + spec + " -o " + (dir / "a.png").string() + " --threads 1");
  REQUIRE(r.code == 0);
  CHECK(r.out.empty());
  r = run(exe() + " render " + spec + " -o " + (dir / "b.png").string() + " --threads 2");
  REQUIRE(r.code == 0);
  CHECK(read_file(dir / "a.png") == read_file(dir / "b.png"));
  r = run(exe() + " render " + spec + " -o " + (dir / "c.exr").string() + " --scale 0.5");
  REQUIRE(r.code == 0);
  auto in = OIIO::ImageInput::open((dir / "c.exr").string());
  REQUIRE(in);
  CHECK(in->spec().width == 400);
  CHECK(in->spec().height == 250);
  CHECK(in->spec().nchannels == 4);
  CHECK(in->spec().format == OIIO::TypeDesc::FLOAT);
  Png png = load_png(dir / "a.png");
  CHECK(png.width == 800);
  CHECK(png.height == 500);
  // Only the two images and nothing half-written beside them.
  int files = 0;
  for ([[maybe_unused]] auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 3);
}
