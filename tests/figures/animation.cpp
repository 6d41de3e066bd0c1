// A spec's [animation] (docs/figures.md): s003-fig15's filmstrips as an animated WebP written by
// `splinefig figures` beside the PNG. The file is decoded by libwebp's own decoder
// (WebPAnimDecoder, libwebpdemux; the writer uses only the encoder) and checked for its frame
// count, delays and loop count, and three of its frames against PNGs rendered by `splinefig
// render` from specs written out here: the in-between frame drawn as [[axes.inbetween]] with
// t = TIME draws it, the keyframes as plain [[axes.series]]. The encoding is lossless, so the
// tolerance is 0 (every 8-bit value equal). The data range of the frames is checked against the
// frames' bounding box computed here (the natural cubic spline through the leg's keyframes,
// written out as in filmstrip.cpp).
#include <catch2/catch.hpp>

#include "skip.hpp"
#include "spec_error_check.hpp"
#include "support.hpp"

#include <splinefig/base/limits.hpp>
#include <splinefig/figures/animation.hpp>

#if SPLINEFIG_HAVE_WEBPDEMUX
#include <webp/demux.h>
#endif

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace figtest;
namespace sf = splinefig::figures;

namespace {

const std::string kLegFrames =
    "frames = [[[0, 4], [0.3, 2], [0, 0], [0.8, 0]], [[2, 4], [2.8, 2.2], [2.9, 0.3], [3.7, 0.1]], "
    "[[4, 4], [4.3, 2], [4, 0], [4.8, 0]]]\n";
const std::vector<std::vector<std::array<double, 2>>> kLeg = {{{0, 4}, {0.3, 2}, {0, 0}, {0.8, 0}},
                                                               {{2, 4}, {2.8, 2.2}, {2.9, 0.3}, {3.7, 0.1}},
                                                               {{4, 4}, {4.3, 2}, {4, 0}, {4.8, 0}}};

// The natural cubic spline through s0, s1, s2 at t = 0, 1, 2 (M1 = 6 (s0 - 2 s1 + s2) / 4).
double natural(double s0, double s1, double s2, double t) {
  const double m1 = 6 * (s0 - 2 * s1 + s2) / 4;
  if (t <= 1) return (1 - t) * s0 + t * s1 + (t * t * t - t) * m1 / 6;
  const double u = t - 1, v = 1 - u;
  return v * s1 + u * s2 + (v * v * v - v) * m1 / 6;
}

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string points(const std::vector<std::array<double, 2>>& pts) {
  std::string s = "[";
  for (const auto& p : pts) s += (s.size() > 1 ? ", [" : "[") + num(p[0]) + ", " + num(p[1]) + "]";
  return s + "]";
}

// Frame i of s003-fig15's animation written out: both panels, the keyframes at 0x4d alpha, then
// the frame at t = i / 6, on the ranges given.
std::string frame_spec(int i, const std::array<double, 2>& xr, const std::array<double, 2>& yr) {
  const double t = i / 6.0;
  char label[64];
  std::snprintf(label, sizeof label, "$t$ = %.2f%s", t, i % 6 == 0 ? ", a key frame" : "");
  // The figure's text sizes in pixels: its points at 1100 px across 6 in.
  char sizes[160];
  const double px_per_pt = 1100.0 / (6 * 72);
  std::snprintf(sizes, sizeof sizes, "title_size = %.17g\npanel_title_size = %.17g\nlabel_size = %.17g\n", 10 * px_per_pt,
                9 * px_per_pt, 9 * px_per_pt);
  std::string s = "title = \"In-between frames from key frames: spline against linear\"\n" + std::string(sizes) +
                  "[canvas]\nwidth = 760\nheight = 420\n[layout]\ncols = 2\n";
  const char* titles[2] = {"relaxed cubic spline through the key frames", "linear in-betweening (the jerky one)"};
  for (int panel = 0; panel < 2; ++panel) {
    s += std::string("[[axes]]\ntitle = \"") + titles[panel] + "\"\nx_range = [" + num(xr[0]) + ", " + num(xr[1]) +
         "]\ny_range = [" + num(yr[0]) + ", " + num(yr[1]) +
         "]\naspect = \"equal\"\nframe = \"none\"\nx_ticks = []\ny_ticks = []\nlegend = \"none\"\nx_label = \"" + label + "\"\n";
    for (const auto& key : kLeg)
      s += "[[axes.series]]\npoints = " + points(key) + "\nstyle = \"line+markers\"\ncolor = \"#0000004d\"\nwidth = 1.5\n";
    if (i % 6 == 0) {
      s += "[[axes.series]]\npoints = " + points(kLeg[static_cast<std::size_t>(i / 6)]) +
           "\nstyle = \"line+markers\"\ncolor = \"#000000\"\nwidth = 1.5\n";
    } else {
      s += "[[axes.inbetween]]\n" + kLegFrames + "t = " + num(t) + "\nwidth = 1.5\n";
      s += panel == 0 ? "color = \"#1f77b4\"\n" : "interpolation = \"linear\"\ncolor = \"#cc79a7\"\ndash = [5, 3]\n";
    }
  }
  return s;
}

#if SPLINEFIG_HAVE_WEBPDEMUX
struct Decoded {
  int width = 0, height = 0, loops = -1;
  std::vector<std::vector<unsigned char>> frames;  // RGBA
  std::vector<int> delays;                         // ms
};

Decoded decode(const std::string& bytes) {
  Decoded d;
  WebPData data{reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  REQUIRE(WebPAnimDecoderOptionsInit(&options));
  options.color_mode = MODE_RGBA;
  options.use_threads = 0;
  WebPAnimDecoder* dec = WebPAnimDecoderNew(&data, &options);
  REQUIRE(dec != nullptr);
  WebPAnimInfo info;
  REQUIRE(WebPAnimDecoderGetInfo(dec, &info));
  d.width = static_cast<int>(info.canvas_width);
  d.height = static_cast<int>(info.canvas_height);
  d.loops = static_cast<int>(info.loop_count);
  int end = 0;
  while (WebPAnimDecoderHasMoreFrames(dec)) {
    uint8_t* rgba = nullptr;
    int timestamp = 0;  // the frame's end
    REQUIRE(WebPAnimDecoderGetNext(dec, &rgba, &timestamp));
    d.frames.emplace_back(rgba, rgba + std::size_t(4) * static_cast<std::size_t>(d.width * d.height));
    d.delays.push_back(timestamp - end);
    end = timestamp;
  }
  CHECK(d.frames.size() == info.frame_count);
  WebPAnimDecoderDelete(dec);
  return d;
}
#endif

}  // namespace

TEST_CASE("s003-fig15's animation spells key frame as the still does") {
  const std::string file = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/s003-fig15.toml";
  const sf::FigureSpec spec = sf::load_spec(file);
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  // The still: every line of its spec that is not a comment (title, caption, labels, legend).
  std::string still;
  {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
      if (line.rfind('#', 0) != 0) still += lower(line) + "\n";
  }
  CHECK(still.find("key frame") != std::string::npos);
  CHECK(still.find("keyframe") == std::string::npos);
  // The animation: each frame's axis labels and titles, and its alt text.
  const int frames = sf::animation_frames(spec);
  REQUIRE(frames == 13);
  int keyed = 0;
  for (int i = 0; i < frames; ++i) {
    const sf::FigureSpec f = sf::animation_frame_spec(spec, i);
    for (const auto& item : f.items)
      if (const auto* ax = std::get_if<sf::AxesSpec>(&item)) {
        for (const std::string& text : {ax->x.label, ax->y.label, ax->title}) {
          INFO("frame " << i << ": " << text);
          CHECK(lower(text).find("keyframe") == std::string::npos);
        }
        if (sf::animation_keyframe(spec, i)) {
          CHECK(ax->x.label.find(", a key frame") != std::string::npos);
          ++keyed;
        }
      }
  }
  CHECK(keyed == 2 * 3);  // t = 0, 1, 2 in both panels
  CHECK(lower(sf::animation_alt(spec)).find("keyframe") == std::string::npos);
}

TEST_CASE("s003-fig15's animation: the frames' range holds every frame, computed by hand") {
  const sf::FigureSpec spec = sf::load_spec(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/s003-fig15.toml");
  REQUIRE(sf::animation_frames(spec) == 13);
  // Every frame of both strips, unshifted: the relaxed one by the natural spline, the linear one
  // between keyframes.
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (int i = 0; i <= 12; ++i) {
    const double t = i / 6.0;
    const std::size_t k = std::min<std::size_t>(1, static_cast<std::size_t>(t));
    const double u = t - static_cast<double>(k);
    for (std::size_t p = 0; p < 4; ++p)
      for (int c = 0; c < 2; ++c) {
        const double rel = natural(kLeg[0][p][c], kLeg[1][p][c], kLeg[2][p][c], t);
        const double lin = (1 - u) * kLeg[k][p][c] + u * kLeg[k + 1][p][c];
        for (double v : {rel, lin}) {
          (c == 0 ? x0 : y0) = std::min(c == 0 ? x0 : y0, v);
          (c == 0 ? x1 : y1) = std::max(c == 0 ? x1 : y1, v);
        }
      }
  }
  const double pad = 0.05 * std::max(x1 - x0, y1 - y0);
  for (int i : {0, 5, 12}) {
    const sf::FigureInfo info = sf::layout_figure(sf::animation_frame_spec(spec, i));
    REQUIRE(info.axes.size() == 2);
    for (const auto& ax : info.axes) {
      // Equal aspect may widen one range; neither may cut a frame.
      CHECK(ax.x_range[0] <= x0 - pad + 1e-9);
      CHECK(ax.x_range[1] >= x1 + pad - 1e-9);
      CHECK(ax.y_range[0] <= y0 - pad + 1e-9);
      CHECK(ax.y_range[1] >= y1 + pad - 1e-9);
      CHECK((ax.x_range[1] - ax.x_range[0]) * (ax.y_range[1] - ax.y_range[0]) <= (x1 - x0 + 2 * pad) * (y1 - y0 + 2 * pad) * 1.6);
    }
  }
}

TEST_CASE("s003-fig15's animation: splinefig figures writes an animated WebP, decoded by libwebp, its frames equal to renders of their time") {
#if !SPLINEFIG_HAVE_WEBPDEMUX
  splinefig::testing_support::skip("libwebpdemux (libwebp-dev) is not installed: the animation was not decoded");
#else
  const fs::path dir = render_builtin("animation", {"s003-fig15"});
  REQUIRE(fs::exists(dir / "s003-fig15.png"));
  REQUIRE(fs::exists(dir / "s003-fig15.webp"));
  const Decoded d = decode(read_file(dir / "s003-fig15.webp"));
  CHECK(d.width == 760);
  CHECK(d.height == 420);
  CHECK(d.loops == 0);
  // 2 keyframe intervals of 6 steps, plus the last: 13 frames, the keyframes held 640 ms.
  REQUIRE(d.frames.size() == 13);
  const std::vector<int> delays{640, 160, 160, 160, 160, 160, 640, 160, 160, 160, 160, 160, 640};
  CHECK(d.delays == delays);
  // index.json and the gallery name it.
  const Json index = parse_json(read_file(dir / "index.json"));
  const Json& f = figure(index, "s003-fig15");
  CHECK(f["animation"]["file"].string == "s003-fig15.webp");
  CHECK(f["animation"]["frames"].number == 13);
  CHECK(f["animation"]["width"].number == 760);
  CHECK(f["animation"]["height"].number == 420);
  CHECK(f["animation"]["alt"].string.rfind("Animation of the leg walking", 0) == 0);
  bool listed = false;
  for (const auto& file : f["files"].array) listed = listed || file.string == "s003-fig15.webp";
  CHECK(listed);
  const std::string html = read_file(dir / "index.html");
  CHECK(html.find("<img src=\"s003-fig15.webp\" width=\"760\" height=\"420\" alt=\"Animation of the leg walking") != std::string::npos);
  // Frames 3 (t = 0.5), 6 (the middle keyframe) and 9 (t = 1.5) against the specs written out,
  // on the range the animation reports (checked against the frames' box in the case above).
  const sf::FigureSpec spec = sf::load_spec(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/s003-fig15.toml");
  for (int i : {3, 6, 9}) {
    INFO("frame " << i);
    const sf::FigureInfo info = sf::layout_figure(sf::animation_frame_spec(spec, i));
    const fs::path toml = dir / ("frame" + std::to_string(i) + ".toml"), png = dir / ("frame" + std::to_string(i) + ".png");
    {
      std::ofstream out(toml);
      out << frame_spec(i, info.axes[0].x_range, info.axes[0].y_range);
    }
    const Result r = run(exe() + " render " + toml.string() + " -o " + png.string());
    REQUIRE(r.code == 0);
    const Png expected = load_png(png);
    REQUIRE(expected.width == d.width);
    REQUIRE(expected.height == d.height);
    REQUIRE(expected.channels == 4);
    const auto& got = d.frames[static_cast<std::size_t>(i)];
    int worst = 0;
    std::size_t differing = 0;
    for (std::size_t k = 0; k < got.size(); ++k) {
      const int diff = std::abs(int(got[k]) - int(expected.data[k]));
      worst = std::max(worst, diff);
      differing += diff != 0;
    }
    CHECK(differing == 0);
    CHECK(worst == 0);
  }
  // Neighbouring frames differ (the leg moves).
  CHECK(d.frames[3] != d.frames[4]);
#endif
}

TEST_CASE("s003-fig15's animation: the same bytes whatever the thread count") {
  const fs::path a = render_builtin("animation-t1", {"s003-fig15"}, "--threads 1");
  const fs::path b = render_builtin("animation-t2", {"s003-fig15"}, "--threads 2");
  const std::string one = read_file(a / "s003-fig15.webp");
  CHECK(one.size() > 1000);
  CHECK(one.compare(0, 4, "RIFF") == 0);
  CHECK(one.compare(8, 4, "WEBP") == 0);
  CHECK(one == read_file(b / "s003-fig15.webp"));
}

TEST_CASE("[animation]: what it needs, one line each") {
  struct Case {
    std::string text, expect;
  };
  const std::string strip = "[[axes]]\nx_range = [0, 30]\ny_range = [0, 5]\n[[axes.inbetween]]\n" + kLegFrames + "steps = 6\n";
  const std::string curve = "[[axes]]\n[[axes.interp]]\npoints = [[0, 0], [1, 1], [2, 0]]\n";
  const std::vector<Case> cases{
      {curve + "[animation]\n", "a.toml:4: animation: the spec has no filmstrip to animate"},
      {"[layout]\ncols = 2\n" + strip + curve + "[animation]\npanels = [1]\n", "a.toml:13: animation.panels: axes[1] holds no filmstrip"},
      {strip + "[animation]\npanels = [1]\n", "a.toml:8: animation.panels: expected indices of the spec's [[axes]], 0 to 0"},
      {strip + "[animation]\npanels = [0, 0]\n", "a.toml:8: animation.panels: axes[0] is named twice"},
      {strip + "[animation]\npanels = []\n", "a.toml:8: animation.panels: names no axes"},
      {strip + "[animation]\ndelay = 5\n", "a.toml:8: animation.delay: expected whole milliseconds in [20, 60000]"},
      {strip + "[animation]\ndelay = 100.5\n", "a.toml:8: animation.delay: expected whole milliseconds in [20, 60000]"},
      {strip + "[animation]\nkey_delay = -1\n", "a.toml:8: animation.key_delay: expected whole milliseconds in [20, 60000]"},
      {strip + "[animation]\nwidth = 20000\n", "a.toml:8: animation.width:"},
      {strip + "[animation]\nframes = 3\n", "a.toml:8: animation.frames: unknown key"},
      {strip + "[animation]\n[animation]\n", "a.toml:"},
      // Filmstrips of 13 and 7 frames cannot play together.
      {strip + "[[axes.inbetween]]\n" + kLegFrames + "steps = 3\n[animation]\n",
       "a.toml:10: animation: its filmstrips differ in frame count (13 and 7)"},
      // 64 steps over 2 intervals (129 frames) of 4096 x 1024 px: over 2^28 pixels in all, refused
      // before anything is drawn.
      {"[[axes]]\n[[axes.inbetween]]\n" + kLegFrames + "steps = 64\n[animation]\nwidth = 4096\nheight = 1024\n",
       "a.toml:7: animation.height: 129 frames of 4096 x 1024 px, over the limit of 2^28 pixels in all"},
  };
  check_spec_errors(cases, "a.toml");
  // key_delay = 0 is the documented "as delay".
  CHECK(spec_error(strip + "[animation]\nkey_delay = 0\n", "a.toml").empty());
}

TEST_CASE("[animation]: the limits after --scale are checked before any frame is drawn") {
  const fs::path dir = scratch("animation-scale");
  {
    std::ofstream out(dir / "big.toml");
    out << "[canvas]\nwidth = 100\nheight = 100\n[[axes]]\n[[axes.inbetween]]\n" << kLegFrames
        << "steps = 64\n[animation]\nwidth = 1000\nheight = 1000\n";
  }
  fs::create_directories(dir / "out");
  const Result r = run(exe() + " figures --specs " + dir.string() + " --out " + (dir / "out").string() + " --scale 2");
  CHECK(r.code != 0);
  CHECK(r.out.find("big.toml:8: animation: 129 frames of 2000 x 2000 px, over the limit of 2^28 pixels in all") != std::string::npos);
  CHECK(!fs::exists(dir / "out" / "big.webp"));
  for (const auto& e : fs::directory_iterator(dir / "out")) CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
}

TEST_CASE("[animation]: a WebP that cannot be written is named, leaves no temporary file and keeps the PNG") {
  const fs::path dir = scratch("animation-unwritable");
  fs::create_directories(dir / "s003-fig15.webp");  // a directory where the file would go
  const Result r = run(exe() + " figures --only s003-fig15 --out " + dir.string());
  CHECK(r.code == 2);
  CHECK(r.out.find("s003-fig15.webp") != std::string::npos);
  CHECK(fs::is_directory(dir / "s003-fig15.webp"));
  CHECK(fs::is_empty(dir / "s003-fig15.webp"));
  CHECK(fs::exists(dir / "s003-fig15.png"));
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
}

TEST_CASE("render -o NAME.webp writes the spec's animation, the bytes figures writes, and refuses a spec without one") {
  const fs::path dir = render_builtin("animation-render", {"s003-fig15"});
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/s003-fig15.toml";
  Result r = run(exe() + " render " + spec + " -o " + (dir / "alone.webp").string() + " --threads 1");
  REQUIRE(r.code == 0);
  CHECK(read_file(dir / "alone.webp") == read_file(dir / "s003-fig15.webp"));
  const std::string still = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/s003-fig17.toml";
  r = run(exe() + " render " + still + " -o " + (dir / "none.webp").string());
  CHECK(r.code == 2);
  CHECK(r.out.find("a .webp output is the spec's [animation], and " + still + " has none") != std::string::npos);
  CHECK(!fs::exists(dir / "none.webp"));
  r = run(exe() + " render " + spec + " -o " + (dir / "x.webp").string() + " --format png");
  CHECK(r.code == 2);
  CHECK(r.out.find("names another format (.webp)") != std::string::npos);
  CHECK(!fs::exists(dir / "x.webp"));
}
