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

TEST_CASE("splinefig figures --only updates its entries in index.json and index.html and keeps the others") {
  auto dir = scratch("figures-only-index");
  fs::create_directories(dir / "specs");
  auto write_spec = [&](const std::string& name, const std::string& title, int width) {
    std::ofstream(dir / "specs" / (name + ".toml"))
        << "title = \"" << title << "\"\n[canvas]\nwidth = " << width << "\nheight = 40\n"
        << "[[polyline]]\npoints = [[4, 4], [40, 36]]\n";
  };
  write_spec("one", "One", 48);
  write_spec("two", "Two", 56);
  write_spec("three", "Three", 64);
  const std::string base = exe() + " figures --specs " + (dir / "specs").string() + " --out " + (dir / "out").string();
  auto r = run(base);
  REQUIRE(r.code == 0);
  // Only "two" again, after its spec changed: its entry changes, the others stay as they were.
  write_spec("two", "Two again", 60);
  r = run(base + " --only two");
  REQUIRE(r.code == 0);
  CHECK(r.out.find("1 figure in") != std::string::npos);
  Json index = parse_json(read_file(dir / "out" / "index.json"));
  REQUIRE(index["figures"].size() == 3);
  CHECK(index["figures"][0]["name"].string == "one");
  CHECK(index["figures"][0]["width"].number == 48);
  CHECK(index["figures"][0]["title"].string == "One");
  CHECK(index["figures"][1]["name"].string == "three");
  CHECK(index["figures"][2]["name"].string == "two");
  CHECK(index["figures"][2]["title"].string == "Two again");
  CHECK(index["figures"][2]["width"].number == 60);
  REQUIRE(index["figures"][0]["files"].size() == 1);
  CHECK(index["figures"][0]["files"][0].string == "one.png");
  const std::string html = read_file(dir / "out" / "index.html");
  for (const char* id : {"id=\"one\"", "id=\"two\"", "id=\"three\"", "Two again"}) {
    INFO(id);
    CHECK(html.find(id) != std::string::npos);
  }
  // A whole run writes the index afresh: a spec that is gone leaves it.
  fs::remove(dir / "specs" / "three.toml");
  r = run(base);
  REQUIRE(r.code == 0);
  index = parse_json(read_file(dir / "out" / "index.json"));
  CHECK(index["figures"].size() == 2);
}

TEST_CASE("splinefig figures --only with an unreadable index.json writes a new one and says so") {
  auto dir = scratch("figures-only-bad-index");
  fs::create_directories(dir / "specs");
  fs::create_directories(dir / "out");
  std::ofstream(dir / "specs" / "one.toml") << "[canvas]\nwidth = 32\nheight = 32\n";
  std::ofstream(dir / "out" / "index.json") << "{\"figures\": [ {\"name\": ";
  auto r = run(exe() + " figures --specs " + (dir / "specs").string() + " --out " + (dir / "out").string() + " --only one");
  CHECK(r.code == 0);
  CHECK(r.out.find("index.json") != std::string::npos);
  Json index = parse_json(read_file(dir / "out" / "index.json"));
  REQUIRE(index["figures"].size() == 1);
  CHECK(index["figures"][0]["name"].string == "one");
}

TEST_CASE("splinefig figures: a run with failures keeps the previous index entries of what failed") {
  auto dir = scratch("figures-failed-run-index");
  fs::create_directories(dir / "specs");
  auto write_spec = [&](const std::string& name, const std::string& title, int width) {
    std::ofstream(dir / "specs" / (name + ".toml"))
        << "title = \"" << title << "\"\n[canvas]\nwidth = " << width << "\nheight = 400\n"
        << "[[polyline]]\npoints = [[4, 4], [40, 36]]\n";
  };
  write_spec("one", "One", 480);
  write_spec("two", "Two", 560);
  const std::string base = exe() + " figures --specs " + (dir / "specs").string() + " --out " + (dir / "out").string();
  auto r = run(base);
  REQUIRE(r.code == 0);
  const std::string json = read_file(dir / "out" / "index.json");
  const std::string html = read_file(dir / "out" / "index.html");
  const std::string png = read_file(dir / "out" / "one.png");
  // 480 x 64 = 30720 px a side: every figure fails; nothing of the previous run changes.
  r = run(base + " --scale 64");
  CHECK(r.code != 0);
  CHECK(r.out.find("2 of 2 figures failed") != std::string::npos);
  CHECK(read_file(dir / "out" / "index.json") == json);
  CHECK(read_file(dir / "out" / "index.html") == html);
  CHECK(read_file(dir / "out" / "one.png") == png);
  // One figure fails, the other renders: the failed one keeps its previous entry and image.
  std::ofstream(dir / "specs" / "one.toml") << "[canvas]\nwidth = 64\nheight = 48\n[[polyline]]\npoints = []\n";
  write_spec("two", "Two again", 500);
  r = run(base);
  CHECK(r.code != 0);
  CHECK(r.out.find("1 of 2 figures failed") != std::string::npos);
  Json index = parse_json(read_file(dir / "out" / "index.json"));
  REQUIRE(index["figures"].size() == 2);
  CHECK(index["figures"][0]["name"].string == "one");
  CHECK(index["figures"][0]["title"].string == "One");
  CHECK(index["figures"][0]["width"].number == 480);
  CHECK(index["figures"][1]["title"].string == "Two again");
  CHECK(read_file(dir / "out" / "one.png") == png);
  CHECK(read_file(dir / "out" / "index.html").find("Two again") != std::string::npos);
}
