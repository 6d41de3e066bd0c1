// A user's program that uses every installed library once, each checked against a value known
// without splinefig: Catmull-Rom k(0) = 1 and B-spline k(0) = 2/3 (spline), the B-spline kernel's
// integral 1 (kernel), a square covering pixel (1,1) exactly (renderer), an image that survives a
// PNG round trip (image), a constant image resampled to a constant (resample), an image equal to
// itself (compare), and a figure spec drawn at its canvas size (figures).
#include <splinefig/compare/compare.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/basis_kernel.hpp>
#include <splinefig/version.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace sf = splinefig;

int main(int argc, char** argv) {
  int failures = 0;
  auto check = [&](bool ok, const char* what) {
    std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
    failures += ok ? 0 : 1;
  };
  const double c = sf::kernel(sf::parse_basis("catmull-rom"), 0.0);
  const double b = sf::kernel(sf::parse_basis("bspline"), 0.0);
  check(std::fabs(c - 1.0) < 1e-15 && std::fabs(b - 2.0 / 3.0) < 1e-15, "spline: k(0)");

  const sf::Kernel k = sf::parse_kernel("bspline");
  check(std::fabs(k.integral() - 1.0) < 1e-15, "kernel: integral of the B-spline");

  sf::render::Scene scene(4, 4, {0, 0, 0, 0});
  scene.fill_polygon({{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}, sf::render::FillRule::NonZero, {1, 1, 1, 1});
  const sf::Image img = sf::render::rasterize(scene, 1);
  check(img.at(1, 1, 3) == 1.0f && img.at(0, 0, 3) == 0.0f && img.at(2, 1, 3) == 0.0f, "renderer: exact coverage");

  const std::string dir = argc > 1 ? argv[1] : std::filesystem::temp_directory_path().string();
  const std::string png = (std::filesystem::path(dir) / "consumer.png").string();
  sf::write_image(png, img);
  const sf::Image back = sf::read_image(png, sf::ReadMode::linear);
  check(back.width == 4 && back.height == 4 && back.at(1, 1, 3) == 1.0f && back.at(0, 0, 3) == 0.0f,
        "image: PNG round trip");

  sf::Image flat(8, 8, 1);
  for (float& v : flat.pixels) v = 0.25f;
  const sf::Image big = sf::resample(flat, 16, 16, k);
  bool constant = true;
  for (float v : big.pixels) constant = constant && std::fabs(v - 0.25f) < 1e-6f;
  check(constant, "resample: a constant stays constant");

  // The PNG read back matches the render (0 and 1 survive 8 bits exactly); an empty image does
  // not (alpha differs by 1 at pixel (1,1)).
  const sf::compare::Comparison same = sf::compare::compare_images(img, back, {});
  const sf::compare::Comparison other = sf::compare::compare_images(img, sf::Image::zeros(4, 4, 4), {});
  check(same.verdict == sf::compare::Verdict::match && other.verdict == sf::compare::Verdict::failure,
        "compare: the PNG round trip matches the render, an empty image does not");

  const sf::figures::FigureSpec spec = sf::figures::parse_spec(
      "[canvas]\nwidth = 240\nheight = 160\n[axes]\nx_range = [-2, 2]\ny_range = [0, 1]\n"
      "[[axes.kernel]]\nbasis = \"catmull-rom\"\n",
      "consumer");
  const sf::figures::RenderedFigure fig = sf::figures::render_figure(spec);
  check(fig.image.width == 240 && fig.image.height == 160, "figures: a spec drawn at its size");

  std::printf("splinefig %s: %d failure(s)\n", SPLINEFIG_VERSION, failures);
  return failures == 0 ? 0 : 1;
}
