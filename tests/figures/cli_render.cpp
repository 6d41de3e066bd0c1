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

TEST_CASE("splinefig figures --specs: good specs render, a bad one is reported and left out") {
  auto dir = scratch("figures-specs");
  fs::create_directories(dir / "specs");
  std::ofstream(dir / "specs" / "good.toml") << "title = \"Good\"\ncaption = \"fine\"\n[canvas]\nwidth = 64\nheight = 48\n"
                                                "[[polyline]]\npoints = [[4, 4], [60, 44]]\nwidth = 2\n";
  std::ofstream(dir / "specs" / "bad.toml") << "[canvas]\nwidth = 64\nheight = 48\n[[polyline]]\npoints = []\n";
  auto r = run(exe() + " figures --specs " + (dir / "specs").string() + " --out " + (dir / "out").string());
  CHECK(r.code != 0);
  CHECK(r.out.find("bad.toml:5: polyline[0].points: empty polyline") != std::string::npos);
  CHECK(r.out.find("1 of 2 figures failed") != std::string::npos);
  CHECK(r.out.find("  good ") != std::string::npos);  // the progress line
  CHECK(fs::exists(dir / "out" / "good.png"));
  CHECK_FALSE(fs::exists(dir / "out" / "bad.png"));
  Json index = parse_json(read_file(dir / "out" / "index.json"));
  REQUIRE(index["figures"].size() == 1);
  CHECK(index["figures"][0]["name"].string == "good");
  CHECK(index["figures"][0]["width"].number == 64);
  CHECK(index["figures"][0]["axes"].size() == 0);
}
