// Raster content in a PDF is embedded at its own pixels, marked not to be interpolated, and
// placed so that a viewer shows it pixel for pixel: poppler (pdftoppm at the figure's 96 dpi)
// draws a nearest-sampled image exactly as splinefig's PNG does, and filter-zoneplate's PDF
// under poppler stays close to its PNG on the whole (the rest being the peers' own edges).
#include "figures/support.hpp"
#include "skip.hpp"

#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace fig = splinefig::figures;
using splinefig::Image;

namespace {

bool have(const std::string& tool) { return figtest::run("command -v " + tool).code == 0; }

struct Written {
  std::string png, pdf;
  int width, height;
};

// The spec's PNG and PDF (96 dpi), written from one scene.
Written write_both(const fig::FigureSpec& spec, const figtest::fs::path& dir, const std::string& stem) {
  const fig::FigureScene f = fig::figure_scene(spec, 1);
  std::optional<Image> raster;
  Written w{(dir / (stem + ".png")).string(), (dir / (stem + ".pdf")).string(), f.info.width, f.info.height};
  fig::write_figure_file(f, w.png, fig::Format::png, {}, raster);
  fig::write_figure_file(f, w.pdf, fig::Format::pdf, {}, raster);
  return w;
}

// The PDF at 96 dpi by poppler.
Image poppler(const Written& w) {
  const std::string out = w.pdf.substr(0, w.pdf.size() - 4) + ".poppler";
  const auto r = figtest::run("pdftoppm -png -singlefile -r 96 " + w.pdf + " " + out);
  INFO(r.out);
  REQUIRE(r.code == 0);
  Image im = splinefig::read_image(out + ".png", splinefig::ReadMode::as_stored);
  REQUIRE(im.width == w.width);
  REQUIRE(im.height == w.height);
  return im;
}

// Largest and mean difference of the colour channels over [x0, x1) x [y0, y1).
std::pair<double, double> differ(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
  double worst = 0, sum = 0;
  long n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(a.pixel(x, y)[std::min(c, a.channels - 1)] - b.pixel(x, y)[std::min(c, b.channels - 1)]);
        worst = std::max(worst, d), sum += d, ++n;
      }
  return {worst, sum / static_cast<double>(n)};
}

}  // namespace

TEST_CASE("a nearest-sampled image in a PDF is drawn by poppler pixel for pixel as in the PNG") {
  if (!have("pdftoppm")) {
    splinefig::testing_support::skip("pdftoppm is not installed");
    return;
  }
  // A 48 x 40 image of steps and a ramp (no two neighbours alike) at (20, 64) px on a 96 dpi
  // page: its edges fall at 15 and 48 pt, which poppler maps to a hair either side of a pixel.
  std::string data = "[";
  for (int y = 0; y < 40; ++y) {
    data += y ? ", [" : "[";
    for (int x = 0; x < 48; ++x) {
      if (x) data += ", ";
      data += std::to_string(((x / 3 + y / 3) % 2) ? 0.9 : 0.02 * ((x * 7 + y * 3) % 40));
    }
    data += "]";
  }
  data += "]";
  const std::string text = "[canvas]\nwidth = 120\nheight = 130\n[[image]]\nat = [20, 64]\ndata = " + data + "\n";
  const auto dir = figtest::scratch("pdf-images");
  const Written w = write_both(fig::parse_spec(text, "img.toml"), dir, "img");
  const Image ours = splinefig::read_image(w.png, splinefig::ReadMode::as_stored);
  const Image peer = poppler(w);
  // Inside the image and a pixel around it: the same 8-bit values (a rounding apart).
  const auto [worst, mean] = differ(ours, peer, 19, 63, 69, 105);
  INFO("largest difference " << worst << ", mean " << mean);
  CHECK(worst <= 1.5 / 255);
  // The PDF says so too: the image is 48 x 40 and not interpolated.
  const auto list = figtest::run("pdfimages -list " + w.pdf);
  if (list.code == 0) {
    INFO(list.out);
    CHECK(list.out.find("48    40") != std::string::npos);
    CHECK(list.out.find(" no ") != std::string::npos);
  }
}

TEST_CASE("filter-zoneplate's PDF under poppler is within 0.006 of its PNG on average") {
  if (!have("pdftoppm")) {
    splinefig::testing_support::skip("pdftoppm is not installed");
    return;
  }
  const auto dir = figtest::scratch("pdf-zoneplate");
  const Written w = write_both(fig::load_spec(fig::builtin_specs_dir() + "/filter-zoneplate.toml"), dir, "zp");
  const Image ours = splinefig::read_image(w.png, splinefig::ReadMode::as_stored);
  const Image peer = poppler(w);
  const auto [worst, mean] = differ(ours, peer, 0, 0, w.width, w.height);
  INFO("largest difference " << worst << ", mean " << mean);
  // The tiles pixel for pixel; what is left is the peers' antialiasing of the titles' edges.
  CHECK(mean <= 0.006);
  // Each tile's inside exactly: the catmull-rom tile at (20, 64), 256 px square.
  const auto [tile_worst, tile_mean] = differ(ours, peer, 21, 65, 275, 319);
  INFO("catmull-rom tile: largest " << tile_worst << ", mean " << tile_mean);
  CHECK(tile_worst <= 1.5 / 255);
}
