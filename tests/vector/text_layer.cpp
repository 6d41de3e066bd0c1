// The text of SVG and PDF files: each label's glyph outlines are what is seen, and an invisible
// text layer over them is what a reader searches, selects and hears. Read back by tools that
// are not splinefig: poppler (pdftotext, pdfinfo, pdftoppm), librsvg (rsvg-convert) and
// Python's xml.etree. The file titles are plain text, and no PDF is dated 1970.
#include "figures/support.hpp"
#include "skip.hpp"

#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/vector/vector.hpp>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <regex>
#include <variant>

namespace fig = splinefig::figures;
namespace render = splinefig::render;

namespace {

bool have(const std::string& tool) { return figtest::run("command -v " + tool).code == 0; }

// cbasis's labels, written by hand from figures/specs/cbasis.toml: the title (its "$a$" is math
// markup), the axis labels ("s" and "$k(s)$", turned 90 degrees) and tick labels (with the
// minus sign U+2212).
const std::string kTitle = "Cardinal spline basis function (Catmull-Rom, a = 0.5)";
const std::vector<std::string> kLabels = {kTitle, "k(s)", "s", "\u22120.2", "0.8", "\u22121"};

fig::FigureScene cbasis() {
  return fig::figure_scene(fig::load_spec(fig::builtin_specs_dir() + "/cbasis.toml"), 1);
}

void write(const figtest::fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }
void write(const figtest::fs::path& p, const std::vector<unsigned char>& bytes) {
  std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// The scene's text items alone, as text (outlines and layer) or as their outlines only (what
// the writers drew before the layer).
render::Scene text_only(const render::Scene& s, bool as_text) {
  render::Scene out(s.width(), s.height());
  for (const render::DrawItem& item : s.items())
    if (const auto* t = std::get_if<render::TextItem>(&item)) {
      if (as_text) out.text(t->text, t->anchor, t->style);
      else out.fill_path(*t->outline, render::FillRule::NonZero, t->style.color);
    }
  return out;
}

// A PNG's pixels as 8-bit values.
std::vector<unsigned char> pixels(const std::string& png) {
  auto in = OIIO::ImageInput::open(png);
  REQUIRE(in);
  const OIIO::ImageSpec& sp = in->spec();
  std::vector<unsigned char> px(static_cast<std::size_t>(sp.width) * sp.height * sp.nchannels);
  REQUIRE(in->read_image(0, 0, 0, sp.nchannels, OIIO::TypeDesc::UINT8, px.data()));
  return px;
}

// How many of two same-sized images' bytes differ.
long differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double xa, double ya, double xb, double yb) {
    x0 = std::min(x0, xa), y0 = std::min(y0, ya), x1 = std::max(x1, xb), y1 = std::max(y1, yb);
  }
};

}  // namespace

TEST_CASE("pdftotext finds a figure's title, axis labels and tick labels in its PDF") {
  if (!have("pdftotext")) return splinefig::testing_support::skip("pdftotext is not installed");
  const auto dir = figtest::scratch("text-layer-pdf");
  write(dir / "c.pdf", splinefig::vector::to_pdf(cbasis().scene));
  // pdftotext's layout (its default): lines as read, turned text turned back.
  const auto r = figtest::run("pdftotext " + (dir / "c.pdf").string() + " -");
  REQUIRE(r.code == 0);
  INFO(r.out);
  std::vector<std::string> lines;
  std::istringstream in(r.out);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  for (const std::string& label : kLabels) {
    INFO(label);
    CHECK(std::find(lines.begin(), lines.end(), label) != lines.end());
  }
}

TEST_CASE("the PDF's text lies over its outlines, turned labels too (pdftotext -bbox)") {
  if (!have("pdftotext")) return splinefig::testing_support::skip("pdftotext is not installed");
  const auto dir = figtest::scratch("text-layer-bbox");
  const fig::FigureScene f = cbasis();
  write(dir / "c.pdf", splinefig::vector::to_pdf(f.scene));
  const auto r = figtest::run("pdftotext -bbox " + (dir / "c.pdf").string() + " -");
  REQUIRE(r.code == 0);
  // Words in points (72 per inch; the scene's pixel is 1/96 inch).
  const std::regex word("<word xMin=\"([-0-9.]+)\" yMin=\"([-0-9.]+)\" xMax=\"([-0-9.]+)\" yMax=\"([-0-9.]+)\">([^<]*)</word>");
  std::multimap<std::string, Box> words;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), word); it != std::sregex_iterator(); ++it) {
    const double k = 96.0 / 72;
    Box b;
    b.add(std::stod((*it)[1]) * k, std::stod((*it)[2]) * k, std::stod((*it)[3]) * k, std::stod((*it)[4]) * k);
    words.emplace((*it)[5], b);
  }
  // The ink of the labels' outlines, by their strings: the title's runs, and k(s)'s.
  Box title, ks;
  for (const render::DrawItem& item : f.scene.items())
    if (const auto* t = std::get_if<render::TextItem>(&item)) {
      Box* b = t->style.angle == 90 ? &ks : t->anchor.y < 40 ? &title : nullptr;
      if (b)
        for (const render::Vec2& p : t->outline->points()) b->add(p.x, p.y, p.x, p.y);
    }
  REQUIRE(words.count("Cardinal") == 1);
  REQUIRE(words.count("0.5)") == 1);
  const Box cardinal = words.find("Cardinal")->second, last = words.find("0.5)")->second;
  // k(s)'s words (a word per run: k and s are italic), at the left margin.
  Box w;
  for (const char* k : {"k", "(", "s", ")"})
    for (auto [it, end] = words.equal_range(k); it != end; ++it)
      if (it->second.x1 < 40) w.add(it->second.x0, it->second.y0, it->second.x1, it->second.y1);
  // The title: from its first glyph's left side to its last one's right, within the side
  // bearings (2 px); across, the words' boxes (ascent to descent) hold the outlines' ink.
  CHECK(std::abs(cardinal.x0 - title.x0) < 2);
  CHECK(std::abs(last.x1 - title.x1) < 2);
  CHECK(cardinal.y0 <= title.y0 + 1);
  CHECK(cardinal.y1 >= title.y1 - 1);
  // k(s), turned: a tall box over the tall ink.
  CHECK(w.y1 - w.y0 > w.x1 - w.x0);
  CHECK(std::abs(w.y0 - ks.y0) < 2);
  CHECK(std::abs(w.y1 - ks.y1) < 2);
  CHECK(w.x0 <= ks.x0 + 1);
  CHECK(w.x1 >= ks.x1 - 1);
}

TEST_CASE("the SVG holds each label as the text content of a transparent <text> (xml.etree)") {
  if (!have("python3")) return splinefig::testing_support::skip("python3 is not installed");
  const auto dir = figtest::scratch("text-layer-svg");
  write(dir / "c.svg", splinefig::vector::to_svg(cbasis().scene));
  write(dir / "read.py",
        "import sys, xml.etree.ElementTree as E\n"
        "ns = '{http://www.w3.org/2000/svg}'\n"
        "root = E.parse(sys.argv[1]).getroot()\n"
        "for t in root.iter(ns + 'text'):\n"
        "    assert t.get('fill-opacity') == '0', t.attrib\n"
        "    sys.stdout.buffer.write((''.join(t.itertext()) + '\\n').encode())\n"
        "for p in root.iter(ns + 'path'):\n"
        "    assert p.get('aria-label') is None\n");
  const auto r = figtest::run("python3 " + (dir / "read.py").string() + " " + (dir / "c.svg").string());
  INFO(r.out);
  REQUIRE(r.code == 0);
  std::vector<std::string> texts;
  std::istringstream in(r.out);
  for (std::string l; std::getline(in, l);) texts.push_back(l);
  for (const std::string& label : kLabels) {
    INFO(label);
    CHECK(std::find(texts.begin(), texts.end(), label) != texts.end());
  }
}

TEST_CASE("the text layer adds no ink: librsvg and poppler draw the same pixels as for the outlines alone") {
  const auto dir = figtest::scratch("text-layer-ink");
  const render::Scene& full = cbasis().scene;
  const render::Scene text = text_only(full, true), outlines = text_only(full, false);
  bool ran = false;
  if (have("rsvg-convert")) {
    ran = true;
    write(dir / "t.svg", splinefig::vector::to_svg(text));
    write(dir / "o.svg", splinefig::vector::to_svg(outlines));
    for (const char* s : {"t", "o"})
      REQUIRE(figtest::run("rsvg-convert -z 2 -o " + (dir / (std::string(s) + "-svg.png")).string() + " " +
                           (dir / (std::string(s) + ".svg")).string()).code == 0);
    const auto a = pixels((dir / "t-svg.png").string()), b = pixels((dir / "o-svg.png").string());
    REQUIRE(a.size() == b.size());
    CHECK(std::count(a.begin(), a.end(), 255) < static_cast<long>(a.size()));  // some ink
    CHECK(differing(a, b) == 0);
  }
  if (have("pdftoppm")) {
    ran = true;
    write(dir / "t.pdf", splinefig::vector::to_pdf(text));
    write(dir / "o.pdf", splinefig::vector::to_pdf(outlines));
    for (const char* s : {"t", "o"})
      REQUIRE(figtest::run("pdftoppm -png -singlefile -r 192 " + (dir / (std::string(s) + ".pdf")).string() + " " +
                           (dir / (std::string(s) + "-pdf")).string()).code == 0);
    const auto a = pixels((dir / "t-pdf.png").string()), b = pixels((dir / "o-pdf.png").string());
    REQUIRE(a.size() == b.size());
    CHECK(std::count(a.begin(), a.end(), 255) < static_cast<long>(a.size()));
    CHECK(differing(a, b) == 0);
  }
  if (!ran) splinefig::testing_support::skip("neither rsvg-convert nor pdftoppm is installed");
}

TEST_CASE("file titles are plain text: the PNG description, SVG <title> and PDF Title") {
  const auto dir = figtest::scratch("text-layer-titles");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml";
  for (const char* ext : {"png", "svg", "pdf"}) {
    const auto r = figtest::run(figtest::exe() + " render " + spec + " -o " + (dir / (std::string("c.") + ext)).string());
    INFO(r.out);
    REQUIRE(r.code == 0);
  }
  // The title alone: the file stem is an internal name (tests/figures/visible_names.cpp).
  const std::string want = kTitle;
  auto in = OIIO::ImageInput::open((dir / "c.png").string());
  REQUIRE(in);
  CHECK(in->spec().get_string_attribute("ImageDescription") == want);
  CHECK(figtest::read_file(dir / "c.svg").find("<title>" + want + "</title>") != std::string::npos);
  if (!have("pdfinfo")) return splinefig::testing_support::skip("pdfinfo is not installed (the PDF Title is unchecked)");
  const auto r = figtest::run("pdfinfo " + (dir / "c.pdf").string());
  INFO(r.out);
  CHECK(r.out.find("Title:           " + want + "\n") != std::string::npos);
}

TEST_CASE("a PDF without SOURCE_DATE_EPOCH, or with 0, has no creation date, never 1970") {
  const auto dir = figtest::scratch("text-layer-date");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml";
  for (const std::string env : {"env -u SOURCE_DATE_EPOCH", "env SOURCE_DATE_EPOCH=0", "env SOURCE_DATE_EPOCH="}) {
    INFO(env);
    const std::string out = (dir / "c.pdf").string();
    const auto r = figtest::run(env + " " + figtest::exe() + " render " + spec + " -o " + out);
    REQUIRE(r.code == 0);
    const std::string pdf = figtest::read_file(out);
    CHECK(pdf.find("CreationDate") == std::string::npos);
    CHECK(pdf.find("1970") == std::string::npos);
  }
  // The library's default (Options::date unset) likewise.
  const auto bytes = splinefig::vector::to_pdf(render::Scene(4, 4));
  const std::string pdf(bytes.begin(), bytes.end());
  CHECK(pdf.find("CreationDate") == std::string::npos);
  CHECK(pdf.find("1970") == std::string::npos);
}
