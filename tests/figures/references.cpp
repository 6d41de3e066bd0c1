// Every built-in figure against its reference PNG (tests/reference/figures/NAME.png).
// Tolerance: a pixel fails when a channel is off by more than 0.1; at most 0.01% of the
// pixels (40 of an 800x500 figure) may fail, and no shift is forgiven - a curve moved by one
// pixel changes thousands of pixels by far more and fails. Regenerate with
// SPLINEFIG_UPDATE_REFERENCES=1 and look at every changed image before committing it.
#include <catch2/catch.hpp>

#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/testing.hpp>

#include <filesystem>

using namespace splinefig;

namespace {

void check_reference(const std::string& name) {
  const std::string src = SPLINEFIG_SOURCE_DIR;
  figures::FigureSpec spec = figures::load_spec(src + "/figures/specs/" + name + ".toml");
  figures::RenderedFigure r = figures::render_figure(spec, {1, 0});
  const Image& img = r.image;
  testing::Tolerance tol;
  tol.fail = 0.1f;
  tol.failpercent = 0.01f;
  tol.warn = 0.02f;
  tol.warnpercent = 0.1f;
  CHECK_THAT(img, testing::MatchesReference(src + "/tests/reference/figures/" + name + ".png", tol));
}

}  // namespace

TEST_CASE("figure cbasis matches its reference") { check_reference("cbasis"); }
TEST_CASE("figure cbasis-a matches its reference") { check_reference("cbasis-a"); }
TEST_CASE("figure bbasis matches its reference") { check_reference("bbasis"); }
TEST_CASE("figure bbasis-a matches its reference") { check_reference("bbasis-a"); }
TEST_CASE("figure bias matches its reference") { check_reference("bias"); }
TEST_CASE("figure bias-kernels matches its reference") { check_reference("bias-kernels"); }
TEST_CASE("figure tension matches its reference") { check_reference("tension"); }
TEST_CASE("figure ends matches its reference") { check_reference("ends"); }
TEST_CASE("figure multiplicity matches its reference") { check_reference("multiplicity"); }
TEST_CASE("figure arclength matches its reference") { check_reference("arclength"); }

TEST_CASE("a figure moved by one pixel fails its reference") {
  // The tolerance above must catch a 1-px misplacement: shift the cbasis kernel by one pixel
  // (an explicit axes box one pixel to the right) and expect the comparison to fail.
  const std::string src = SPLINEFIG_SOURCE_DIR;
  figures::FigureSpec spec = figures::load_spec(src + "/figures/specs/cbasis.toml");
  figures::FigureInfo info = figures::layout_figure(spec);
  auto& ax = std::get<figures::AxesSpec>(spec.items.back());
  const auto& b = info.axes.at(0).pixel_box;
  ax.box = std::array<double, 4>{b[0] + 1, b[1], b[2] + 1, b[3]};
  figures::RenderedFigure r = figures::render_figure(spec, {1, 0});
  const Image& img = r.image;
  Image expected = read_image(src + "/tests/reference/figures/cbasis.png");
  compare::Options o;
  o.thresholds.fail = 0.1f;
  o.thresholds.failpercent = 0.01f;
  auto stored = testing::detail::as_stored(img, src + "/tests/reference/figures/cbasis.png", false);
  CHECK(compare::compare_images(expected, stored, o).verdict == compare::Verdict::failure);
}

TEST_CASE("figures are identical for any thread count") {
  const std::string src = SPLINEFIG_SOURCE_DIR;
  for (const char* name : {"bias", "ends"}) {
    figures::FigureSpec spec = figures::load_spec(src + "/figures/specs/" + name + ".toml");
    figures::RenderedFigure one = figures::render_figure(spec, {1, 1});
    figures::RenderedFigure two = figures::render_figure(spec, {1, 2});
    figures::RenderedFigure five = figures::render_figure(spec, {1, 5});
    CHECK(one.image.pixels == two.image.pixels);
    CHECK(one.image.pixels == five.image.pixels);
  }
}
