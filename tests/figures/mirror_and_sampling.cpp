// Checks that need the figure without its neighbours: the bias figure's mirror property,
// rendered in-process from the built-in spec with one curve kept at a time; and the
// flatness bound of the adaptive curve sampler against dense evaluation.
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/sampling.hpp>
#include <splinefig/figures/spec.hpp>

#include <cmath>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

// The bias figure with only the Beta-spline of bias b1, drawn black and solid (the figure
// dashes the B-spline; a dash pattern runs along the curve, so it has no mirror image), no
// polygon, no legend.
RenderedFigure bias_curve_alone(const std::string& basis) {
  FigureSpec spec = load_spec(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml");
  spec.show_title = false;
  spec.caption_fields.clear();  // they name the curves removed here
  for (auto& item : spec.items) {
    auto* ax = std::get_if<AxesSpec>(&item);
    if (!ax) continue;
    ax->legend = LegendPlace::None;
    std::vector<PlotElement> kept;
    for (auto& e : ax->elements)
      if (auto* c = std::get_if<CurveElement>(&e); c && c->basis_spec == basis) {
        c->color = Color{0, 0, 0, 1};
        c->stroke.dashes = {};  // b1 > 1 is dashed with butt caps in the figure
        c->stroke.cap = render::Cap::Round;
        c->label = {};  // its label, set beside the curve's end in the figure, is no mirror image
        kept.push_back(*c);
      }
    REQUIRE(kept.size() == 1);
    ax->elements = kept;
  }
  return render_figure(spec, {1, 1});
}

// Coverage of black over white in the pixel: 1 - luminance (linear, premultiplied, opaque).
double ink(const Image& im, int x, int y) { return 1.0 - im.pixel(x, y)[1]; }

}  // namespace

TEST_CASE("bias: the curves for b1 = 2 and b1 = 1/2 are mirror images under x -> 6 - x") {
  RenderedFigure two = bias_curve_alone("beta:b1=2,b2=0");
  RenderedFigure half = bias_curve_alone("beta:b1=0.5,b2=0");
  RenderedFigure one = bias_curve_alone("beta:b1=1,b2=0");
  const AxesInfo& ax = two.info.axes.at(0);
  // x range [-0.3, 6.3] is symmetric about 3, so x -> 6 - x is the mirror about the box's
  // centre line: pixel column i <-> left + right - 1 - i.
  REQUIRE(ax.x_range[0] + ax.x_range[1] == Approx(6.0));
  const int left = static_cast<int>(ax.pixel_box[0]), right = static_cast<int>(ax.pixel_box[2]);
  REQUIRE(ax.pixel_box[0] == left);
  REQUIRE(ax.pixel_box[2] == right);
  double worst = 0, worst_self = 0, sum = 0, ink_total = 0;
  for (int y = static_cast<int>(ax.pixel_box[1]); y < static_cast<int>(ax.pixel_box[3]); ++y)
    for (int x = left; x < right; ++x) {
      const int mx = left + right - 1 - x;
      double d = std::abs(ink(two.image, x, y) - ink(half.image, mx, y));
      worst = std::max(worst, d);
      sum += d;
      ink_total += ink(two.image, x, y);
      worst_self = std::max(worst_self, std::abs(ink(two.image, x, y) - ink(two.image, mx, y)));
    }
  INFO("largest mirror difference " << worst << ", total " << sum << " of ink " << ink_total);
  CHECK(worst < 0.03);
  CHECK(sum < 5e-3 * ink_total);
  // Not a vacuous check: b1 = 2 is not symmetric by itself, while the B-spline (b1 = 1) is.
  CHECK(worst_self > 0.5);
  double worst_one = 0;
  for (int y = static_cast<int>(ax.pixel_box[1]); y < static_cast<int>(ax.pixel_box[3]); ++y)
    for (int x = left; x < right; ++x)
      worst_one = std::max(worst_one, std::abs(ink(one.image, x, y) - ink(one.image, left + right - 1 - x, y)));
  CHECK(worst_one < 0.03);
}

TEST_CASE("curves are sampled to within 0.05 px of the true curve") {
  // A loose cardinal spline with a loop-like turn, mapped with different scales on x and y.
  Points knots(2);
  for (auto [x, y] : {std::pair{0.0, 0.0}, {1.0, 3.0}, {1.2, -1.0}, {3.0, 2.0}, {2.0, 2.5}, {5.0, 0.0}})
    knots.push_back(std::array<double, 2>{x, y});
  Curve c = make_curve(parse_basis("cardinal:a=1"), knots, Ends::doubled);
  PixelMap map{{Scale::Linear, -1, 6, 10, 790}, {Scale::Linear, -2, 4, 490, 20}};
  for (double tol : {0.05, 0.025}) {
    std::vector<Vec2> poly = sample_curve(c, map, tol);
    REQUIRE(poly.size() > 10);
    // Every point of the true curve (dense evaluation, 4000 per piece) lies within tol of the
    // polyline, checked against the chords near it.
    double worst = 0;
    std::array<double, 2> p{};
    const int dense = 4000;
    size_t hint = 0;
    for (size_t i = 0; i <= c.segments() * dense; ++i) {
      evaluate(c, static_cast<double>(i) / dense, 0, p);
      Vec2 q = map({p[0], p[1]});
      double best = 1e300;
      size_t lo = hint > 40 ? hint - 40 : 0, hi = std::min(poly.size() - 1, hint + 40);
      for (size_t k = lo; k < hi; ++k) {
        Vec2 a = poly[k], b = poly[k + 1];
        double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
        double t = l2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
        double d = std::hypot(q.x - a.x - t * dx, q.y - a.y - t * dy);
        if (d < best) best = d, hint = k;
      }
      worst = std::max(worst, best);
    }
    INFO("tolerance " << tol << ": " << poly.size() << " points, worst distance " << worst);
    CHECK(worst <= tol);
    // Adaptive, not wasteful: far fewer points than the dense evaluation.
    CHECK(poly.size() < c.segments() * 200);
  }
}
