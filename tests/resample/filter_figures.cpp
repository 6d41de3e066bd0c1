// The filter figures (docs/figures.md), rendered by `splinefig figures`: three against reference
// PNGs, and every one checked for what it must show: the curves where the analysis puts them,
// and the blur and aliasing of each filter measured in the rendered tiles.
#include <catch2/catch.hpp>

#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <numbers>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

constexpr double pi = std::numbers::pi;

// Each test case renders into its own directory: ctest runs them in parallel, and `figures`
// writes index.json next to the images.
fs::path render(const std::string& names, const std::string& where) {
  const fs::path dir = fs::path(SPLINEFIG_BINARY_DIR) / "test-resample-figures" / where;
  fs::create_directories(dir);
  const std::string cmd = std::string("\"") + SPLINEFIG_EXE + "\" figures --out \"" + dir.string() + "\" --only " + names + " > /dev/null";
  REQUIRE(std::system(cmd.c_str()) == 0);
  return dir;
}

struct Picture {
  int width = 0, height = 0, channels = 0;
  std::vector<float> px;  // sRGB-encoded values in [0, 1]
  std::array<float, 3> rgb(int x, int y) const {
    const float* p = &px[(static_cast<size_t>(y) * width + x) * channels];
    return {p[0], p[1], p[2]};
  }
};

Picture load(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  REQUIRE(in);
  Picture p{in->spec().width, in->spec().height, in->spec().nchannels, {}};
  p.px.resize(static_cast<size_t>(p.width) * p.height * p.channels);
  REQUIRE(in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::FLOAT, p.px.data()));
  return p;
}

// The first array of numbers after `key` following the figure's name in index.json.
std::vector<double> index_numbers(const fs::path& dir, const std::string& figure, const std::string& key) {
  std::ifstream in(dir / "index.json");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  size_t at = text.find("\"" + figure + "\"");
  REQUIRE(at != std::string::npos);
  at = text.find("\"" + key + "\"", at);
  REQUIRE(at != std::string::npos);
  const size_t open = text.find('[', at), close = text.find(']', open);
  std::vector<double> v;
  std::stringstream nums(text.substr(open + 1, close - open - 1));
  for (std::string item; std::getline(nums, item, ',');) v.push_back(std::stod(item));
  return v;
}

// Is there a pixel of colour `hex` within `r` pixels of (x, y)?
bool colour_near(const Picture& p, double x, double y, const char* hex, int r = 3) {
  const float want[3] = {std::stoi(std::string(hex + 1, 2), nullptr, 16) / 255.0f,
                         std::stoi(std::string(hex + 3, 2), nullptr, 16) / 255.0f,
                         std::stoi(std::string(hex + 5, 2), nullptr, 16) / 255.0f};
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const auto c = p.rgb(static_cast<int>(x) + dx, static_cast<int>(y) + dy);
      if (std::abs(c[0] - want[0]) < 0.06 && std::abs(c[1] - want[1]) < 0.06 && std::abs(c[2] - want[2]) < 0.06) return true;
    }
  return false;
}

// Root-mean-square deviation from the mean over the pixels of a tile [x0, x0+n) x [y0, y0+n)
// whose distance from (cx, cy) is at least `rmin`.
double rms(const Picture& p, int x0, int y0, int n, double cx, double cy, double rmin) {
  double s = 0, s2 = 0, count = 0;
  for (int y = y0; y < y0 + n; ++y)
    for (int x = x0; x < x0 + n; ++x) {
      if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) < rmin) continue;
      const double v = p.rgb(x, y)[0];
      s += v;
      s2 += v * v;
      count += 1;
    }
  return std::sqrt(std::max(0.0, s2 / count - (s / count) * (s / count)));
}

}  // namespace

TEST_CASE("filter figures: the response and step plots show the analysis") {
  // (Their references are checked with the other figures, tests/figures/references.cpp.)
  const fs::path dir = render("filter-kernels filter-response filter-step", "plots");
  // The B-spline's response is drawn at 20 log10 sinc(f)^4 dB: at f = 0.75 (-41.8 dB), where
  // no other curve passes.
  {
    const Picture p = load(dir / "filter-response.png");
    const auto box = index_numbers(dir, "filter-response", "pixel_box");
    const auto xr = index_numbers(dir, "filter-response", "x_range");
    const auto yr = index_numbers(dir, "filter-response", "y_range");
    const double f = 0.75, db = 20 * std::log10(std::pow(std::sin(pi * f) / (pi * f), 4));
    const double x = box[0] + (f - xr[0]) / (xr[1] - xr[0]) * (box[2] - box[0]);
    const double y = box[3] - (db - yr[0]) / (yr[1] - yr[0]) * (box[3] - box[1]);
    CHECK(colour_near(p, x, y, "#0072b2", 5));  // the B-spline's blue (dashed: a gap is at most 4 px)
    CHECK_FALSE(colour_near(p, x, y - 25, "#0072b2", 5));
  }
  // Catmull-Rom's step overshoots to 1 + 2/27 (filter analysis), drawn there in its vermillion.
  {
    const Picture p = load(dir / "filter-step.png");
    const auto box = index_numbers(dir, "filter-step", "pixel_box");
    const auto xr = index_numbers(dir, "filter-step", "x_range");
    const auto yr = index_numbers(dir, "filter-step", "y_range");
    const splinefig::Kernel cr = splinefig::parse_kernel("catmull-rom");
    double tmax = 3, vmax = 0;
    for (double t = 3; t <= 5; t += 1e-4)
      if (splinefig::step_value(cr, t - 4) > vmax) vmax = splinefig::step_value(cr, t - 4), tmax = t;
    CHECK(vmax == Approx(1 + 2.0 / 27).margin(1e-6));
    const double x = box[0] + (tmax - xr[0]) / (xr[1] - xr[0]) * (box[2] - box[0]);
    const double y = box[3] - (vmax - yr[0]) / (yr[1] - yr[0]) * (box[3] - box[1]);
    CHECK(colour_near(p, x, y, "#d55e00"));
  }
}

TEST_CASE("filter figures: the zone plate tiles show each filter's blur and aliasing") {
  const fs::path dir = render("filter-zoneplate filter-downsample", "zoneplates");
  // Tiles are 256 px at left = 20 + 280 c, top = 64 + 300 r (the specs' explicit boxes).
  auto tile = [](int i) { return std::pair{20 + 280 * (i % 4), 64 + 300 * (i / 4)}; };
  {
    // Upsampled: catmull-rom 0, cardinal a=1 1, bspline 2, bspline prefiltered 3. The B-spline
    // blurs the rings; its prefilter restores their contrast.
    const Picture p = load(dir / "filter-zoneplate.png");
    auto contrast = [&](int i) { return rms(p, tile(i).first, tile(i).second, 256, 0, 0, 0); };
    CHECK(contrast(2) < 0.8 * contrast(0));
    CHECK(contrast(3) > 0.95 * contrast(0));
    CHECK(contrast(1) > contrast(0));
  }
  {
    // Reduced 8x: beyond twice the new Nyquist radius (8 output pixels = 16 shown) the tile
    // should be flat; what varies there is aliasing. Order: box 5 > catmull-rom 0 > bspline 2.
    const Picture p = load(dir / "filter-downsample.png");
    auto alias = [&](int i) {
      const auto [x0, y0] = tile(i);
      return rms(p, x0, y0, 256, x0 + 128, y0 + 128, 40);
    };
    CHECK(alias(5) > 2 * alias(0));
    CHECK(alias(0) > alias(2));
    CHECK(alias(2) < 0.01);
  }
}
