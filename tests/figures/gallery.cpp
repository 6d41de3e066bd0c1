// The gallery page opens in a real browser, every image loads and the layout is measured. Needs Debian's
// `chromium` (headless, installed by scripts/test); where it is absent ctest reports the test
// as skipped.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

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

namespace {

// Measures the gallery as laid out, with a script of this test's own (not the page's), run in a
// copy of index.html beside it: every card's box and every image's natural and shown size. One
// line per fact in <pre id="probe">, read back from Chromium's --dump-dom.
const char* const kProbe = R"(<script>
window.addEventListener("load", function () {
  var out = ["width " + window.innerWidth];
  // What the page's own script found at load (it ran first): images loaded, overflow, columns.
  ["images-ok", "overflow", "columns"].forEach(function (a) { out.push("page " + a + " " + document.body.getAttribute("data-" + a)); });
  var r = function (e) { var b = e.getBoundingClientRect(); return {l: b.left, t: b.top + window.scrollY, r: b.right, b: b.bottom + window.scrollY}; };
  document.querySelectorAll("section").forEach(function (section) {
    var grid = section.querySelector(".grid") || section;
    var g = r(grid), gap = parseFloat(getComputedStyle(grid).rowGap) || 0;
    var cards = Array.prototype.map.call(section.querySelectorAll("figure"), function (f) { return {id: f.id, box: r(f)}; });
    var lefts = {};
    cards.forEach(function (c) { lefts[Math.round(c.box.l)] = 1; });
    out.push("columns " + section.id + " " + Object.keys(lefts).length);
    for (var i = 0; i < cards.length; ++i)
      for (var j = i + 1; j < cards.length; ++j) {
        var a = cards[i].box, b = cards[j].box;
        if (Math.min(a.r, b.r) - Math.max(a.l, b.l) > 0.5 && Math.min(a.b, b.b) - Math.max(a.t, b.t) > 0.5)
          out.push("overlap " + cards[i].id + " " + cards[j].id);
      }
    // Lanes: the horizontal extents of the cards narrower than the grid. Down each lane the cards
    // that cross it follow one another with no more than the grid's gap between them, the first
    // at the grid's top (room after the last card of a lane is the end of the section).
    var lanes = {};
    cards.forEach(function (c) { if (c.box.r - c.box.l < 0.75 * (g.r - g.l)) lanes[Math.round(c.box.l) + ":" + Math.round(c.box.r)] = c.box; });
    Object.keys(lanes).forEach(function (k) {
      var lane = lanes[k];
      var down = cards.filter(function (c) { return Math.min(c.box.r, lane.r) - Math.max(c.box.l, lane.l) > 1; })
                      .sort(function (a, b) { return a.box.t - b.box.t; });
      var y = g.t, before = "top";
      down.forEach(function (c) {
        if (c.box.t - y > (before == "top" ? 1 : gap + 1)) out.push("hole " + section.id + " " + before + " " + c.id + " " + Math.round(c.box.t - y));
        y = c.box.b; before = c.id;
      });
    });
    section.querySelectorAll("figure").forEach(function (f) {
      var source = f.querySelector(".source");
      out.push("source " + f.id + " " + (source ? source.textContent.trim().length : 0));
      out.push("text " + f.id + " " + f.innerText.replace(/\s+/g, " "));
      f.querySelectorAll("img").forEach(function (img) {
        out.push("img " + f.id + " " + img.naturalWidth + " " + img.clientWidth + " " + img.naturalHeight + " " + img.clientHeight + " " +
                 getComputedStyle(img).imageRendering);
        out.push("alt " + f.id + " " + (img.getAttribute("alt") || "").replace(/\s+/g, " "));
      });
    });
  });
  parent.postMessage(out.join("\n"), "*");
});
</script>
)";

// Headless Chromium keeps a window at least 500 px wide, so the page is measured in an iframe
// of the width asked for; the measurements come back by postMessage.
std::string frame_html(int width) {
  return "<!DOCTYPE html><html><body style=\"margin:0\"><iframe src=\"probe.html\" width=\"" + std::to_string(width) +
         "\" height=\"1400\" style=\"border:0;display:block\"></iframe><pre id=\"probe\"></pre><script>window.addEventListener(\"message\","
         " function (e) { document.getElementById(\"probe\").textContent = e.data; });</script></body></html>\n";
}

struct Measured {
  std::string width;                               // the viewport's width as the page saw it
  std::map<std::string, std::string> page;         // the page's own data-* attributes on <body>
  std::map<std::string, int> columns;             // section -> distinct card lefts
  std::vector<std::string> overlaps, holes;
  std::map<std::string, int> source;              // figure -> length of its source line
  std::map<std::string, std::string> text;        // figure -> the card's visible text
  std::multimap<std::string, std::string> img;    // figure -> "nw cw nh ch rendering"
  std::multimap<std::string, std::string> alt;    // figure -> alt text
};

std::string unescape(std::string s) {
  for (auto [from, to] : {std::pair<std::string, std::string>{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}}) {
    for (size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  }
  return s;
}

Measured measure(const std::string& chromium, const fs::path& dir, int width, const fs::path& screenshot = {}) {
  std::string html = read_file(dir / "index.html");
  const size_t body = html.rfind("</body>");
  REQUIRE(body != std::string::npos);
  html.insert(body, kProbe);
  const fs::path probe = dir / "probe.html";
  std::ofstream(probe) << html;
  const fs::path frame = dir / "probe-frame.html";
  std::ofstream(frame) << frame_html(width);
  const std::string flags = " --headless --no-sandbox --disable-gpu --allow-file-access-from-files --hide-scrollbars"
                            " --virtual-time-budget=10000 --window-size=" + std::to_string(std::max(width, 500) + 40) + ",1500 ";
  Result dom = run(chromium + flags + "--dump-dom file://" + fs::absolute(frame).string() + " 2>/dev/null");
  REQUIRE(dom.code == 0);
  // A screenshot of the page in its frame, to look at.
  if (!screenshot.empty()) run(chromium + flags + "--screenshot=" + screenshot.string() + " file://" + fs::absolute(frame).string());
  const size_t from = dom.out.find("<pre id=\"probe\">"), to = dom.out.find("</pre>", from);
  INFO("the measurements came back from the page");
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  std::istringstream lines(unescape(dom.out.substr(from + 16, to - from - 16)));
  Measured m;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream in(line);
    std::string what, id, rest;
    in >> what >> id;
    std::getline(in >> std::ws, rest);
    if (what == "width") m.width = id;
    else if (what == "page") m.page[id] = rest;
    else if (what == "columns") m.columns[id] = std::stoi(rest);
    else if (what == "overlap") m.overlaps.push_back(id + " " + rest);
    else if (what == "hole") m.holes.push_back(id + " " + rest);
    else if (what == "source") m.source[id] = std::stoi(rest);
    else if (what == "text") m.text[id] = rest;
    else if (what == "img") m.img.emplace(id, rest);
    else if (what == "alt") m.alt.emplace(id, rest);
  }
  return m;
}

}  // namespace

TEST_CASE("the gallery as laid out in Chromium at 1280 and 390 px: two columns at most, no holes, pixel-exact images at their size, alt texts and sources") {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    splinefig::testing_support::skip("chromium is not installed: the gallery's layout was not measured");
    return;
  }
  auto dir = scratch("gallery-measured");
  run(exe() + " figures --format png,svg --out " + dir.string());
  const Json index = parse_json(read_file(dir / "index.json"));
  REQUIRE(index["figures"].size() >= 30);
  // The figures whose point is their pixels (aliasing): the two zone plates, at least.
  std::set<std::string> pixel_exact;
  for (const auto& f : index["figures"].array)
    if (f.has("pixel_exact") && f["pixel_exact"].boolean) pixel_exact.insert(f["name"].string);
  CHECK(pixel_exact.count("filter-downsample") == 1);
  CHECK(pixel_exact.count("filter-zoneplate") == 1);
  for (int width : {1280, 390}) {
    INFO(width << " px");
    const Measured m = measure(chromium, dir, width);
    CHECK(m.width == std::to_string(width));
    REQUIRE(m.source.size() == index["figures"].size());
    for (const auto& [section, columns] : m.columns) {
      INFO(section);
      CHECK(columns >= 1);
      CHECK(columns <= (width < 950 ? 1 : 2));
    }
    for (const auto& o : m.overlaps) FAIL_CHECK("cards overlap: " << o);
    for (const auto& h : m.holes) FAIL_CHECK("an empty cell between cards (section, card before, card after, px): " << h);
    for (const auto& f : index["figures"].array) {
      const std::string& name = f["name"].string;
      INFO(name);
      // A line naming the source figure, and no internal name (the file stem, a seed) in the card.
      CHECK(m.source.at(name) > 0);
      // (A name that is a word of its own title or caption, "bias", is prose there.)
      const bool word = f["title"].string.find(name) != std::string::npos || f["caption"].string.find(name) != std::string::npos;
      const std::string& text = m.text.at(name);
      if (!word) CHECK(text.find(name) == std::string::npos);
      CHECK(text.find("seed") == std::string::npos);
      auto [a, b] = m.alt.equal_range(name);
      CHECK(a != b);
      for (auto it = a; it != b; ++it) {
        CHECK(it->second.size() >= 20);  // a description, not a word
        if (!word) CHECK(it->second.find(name) == std::string::npos);
      }
      auto [i, j] = m.img.equal_range(name);
      REQUIRE(i != j);
      if (!pixel_exact.count(name)) continue;
      // The still (the first image): one image pixel to one CSS pixel at 1280 px; on a phone
      // either the same (the frame scrolls) or, if ever scaled, without smoothing.
      std::istringstream in(i->second);
      int nw = 0, cw = 0, nh = 0, ch = 0;
      std::string rendering;
      in >> nw >> cw >> nh >> ch >> rendering;
      INFO(i->second);
      CHECK(nw == f["width"].number);
      if (width == 1280 || rendering != "pixelated") {
        CHECK(cw == nw);
        CHECK(ch == nh);
      }
    }
  }
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
  CHECK(html.find("<figure id=\"filter-zoneplate\" class=\"pixel-exact wide\">") != std::string::npos);  // [gallery] pixel_exact
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
  // Headless Chromium keeps its window at least 500 px wide, so the page is laid out in a frame
  // of each width (measure()), and the width it saw is checked: 390 px is a phone's.
  for (int w : {390, 800, 1280, 1920}) {
    INFO(w << " px");
    // Screenshots to look at (build/test-figures/gallery-widths-*/gallery-<w>.png).
    Measured m = measure(chromium, dir, w, dir / ("gallery-" + std::to_string(w) + ".png"));
    CHECK(m.width == std::to_string(w));
    CHECK(m.page.count("images-ok") == 1);
    CHECK(m.page["images-ok"] == "yes");
    CHECK(m.page["overflow"] == "no");
    // At most two cards side by side; one below about 950 px (a phone, a narrow window).
    CHECK(m.page["columns"] == (w < 950 ? "1" : "2"));
  }
}
