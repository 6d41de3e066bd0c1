// The gallery page opens in a real browser and every image loads. Needs Debian's
// `chromium` (headless, installed by scripts/test); where it is absent ctest reports the test
// as skipped.
#include <catch2/catch.hpp>

#include "skip.hpp"
#include "support.hpp"

using namespace figtest;

namespace {

std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    Result r = run(std::string("command -v ") + name);
    if (r.code == 0 && !r.out.empty()) return r.out.substr(0, r.out.find('\n'));
  }
  return "";
}

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("the gallery loads every figure in headless Chromium") {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    splinefig::testing_support::skip("chromium is not installed: the gallery was not checked in a browser");
    return;
  }
  // Every built-in figure; a figure that fails to render is left out of the gallery (the
  // other tests catch it), so the exit code is not checked here.
  auto dir = scratch("gallery");
  run(exe() + " figures --out " + dir.string());
  Json index = parse_json(read_file(dir / "index.json"));
  const size_t figures = index["figures"].size();
  REQUIRE(figures >= 10);
  const std::string flags = " --headless --no-sandbox --disable-gpu --allow-file-access-from-files"
                            " --virtual-time-budget=10000 --window-size=1280,1800 ";
  const std::string url = "file://" + fs::absolute(dir / "index.html").string();
  Result dom = run(chromium + flags + "--dump-dom " + url + " 2>/dev/null");
  REQUIRE(dom.code == 0);
  CHECK(dom.out.find("data-images-ok=\"yes\"") != std::string::npos);
  // Each card's still, and the animated WebP of a figure with [animation] (s003-fig15's) under it.
  size_t animations = 0;
  for (const auto& f : index["figures"].array) animations += f.object.count("animation");
  CHECK(animations >= 1);
  CHECK(count(dom.out, "data-loaded=\"yes\"") == figures + animations);
  CHECK(count(dom.out, "data-loaded=\"no\"") == 0);
  // A screenshot to look at (build/test-figures/gallery-*/gallery.png).
  run(chromium + flags + "--screenshot=" + (dir / "gallery.png").string() + " " + url);
  CHECK(fs::exists(dir / "gallery.png"));
}

TEST_CASE("the gallery fits phones to wide screens: no horizontal overflow at 390, 800, 1280 and 1920 px") {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    splinefig::testing_support::skip("chromium is not installed: the gallery's layout was not checked");
    return;
  }
  auto dir = scratch("gallery-widths");
  run("SOURCE_DATE_EPOCH=1700000000 " + exe() + " figures --format png,svg --out " + dir.string());
  const std::string html = read_file(dir / "index.html");
  CHECK(html.find("<meta name=\"viewport\"") != std::string::npos);
  CHECK(html.find("srcset=\"cbasis.png 1x, cbasis.svg 2x\"") != std::string::npos);
  CHECK(html.find("<a href=\"cbasis.svg\">SVG</a>") != std::string::npos);
  CHECK(html.find("2023-11-14") != std::string::npos);
  CHECK(html.find("id=\"filters\"") != std::string::npos);
  CHECK(html.find("id=\"companions\"") != std::string::npos);
  CHECK(html.find("<figure id=\"filter-zoneplate\" class=\"natural\">") != std::string::npos);  // "at 1:1"
  // Each card names the source figure it reproduces, and its image's alt text is its title and
  // caption; index.json carries the source of every figure.
  CHECK(html.find("<span class=\"source\">Smith, Spline Tutorial Notes (1983), Figure CBASIS</span>") != std::string::npos);
  CHECK(html.find("<span class=\"source\">the curve notes (Cubic spline curves), Fig. 9</span>") != std::string::npos);
  CHECK(html.find("alt=\"Cardinal spline basis function (Catmull-Rom, a = 0.5): ") != std::string::npos);
  const Json index = parse_json(read_file(dir / "index.json"));
  REQUIRE(index["figures"].size() >= 30);
  for (size_t i = 0; i < index["figures"].size(); ++i) {
    INFO(index["figures"][i]["name"].string);
    CHECK_FALSE(index["figures"][i]["source"].string.empty());
  }
  const std::string url = "file://" + fs::absolute(dir / "index.html").string();
  for (int w : {390, 800, 1280, 1920}) {
    const std::string flags = " --headless --no-sandbox --disable-gpu --allow-file-access-from-files"
                              " --virtual-time-budget=10000 --window-size=" + std::to_string(w) + ",1400 ";
    Result dom = run(chromium + flags + "--dump-dom " + url + " 2>/dev/null");
    INFO(w << " px");
    REQUIRE(dom.code == 0);
    CHECK(dom.out.find("data-images-ok=\"yes\"") != std::string::npos);
    CHECK(dom.out.find("data-overflow=\"no\"") != std::string::npos);
    // At most two cards side by side; one below about 950 px (a phone, a narrow window).
    CHECK(dom.out.find(w < 950 ? "data-columns=\"1\"" : "data-columns=\"2\"") != std::string::npos);
    // Screenshots to look at (build/test-figures/gallery-widths-*/gallery-<w>.png).
    run(chromium + flags + "--screenshot=" + (dir / ("gallery-" + std::to_string(w) + ".png")).string() + " " + url);
  }
}
