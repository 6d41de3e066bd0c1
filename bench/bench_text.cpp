// Text: glyphs per second, splinefig's outlines through its exact-area rasterizer against Cairo's
// text (FreeType glyphs, Cairo's own rasterizer and glyph cache) on the same labels.
//   text/layout            measure_text of a 24-character label (shaping cached: the common case)
//   text/path              text_path of the label: outlines placed in canvas pixels
//   text/scene/<size>      200 labels of 24 characters, 1024x1024, Scene::text + rasterize (1 thread)
//   text/flatten/<size>    the geometry of text/scene alone: text_path + flatten (1e-4 px)
//   text/empty-canvas      text/scene without the labels (clearing and returning the canvas)
//   text/cairo/<size>      the same labels with cairo_show_text (DejaVu Sans, antialiased)
// Counter glyphs_per_s: drawn glyphs per second of wall time.
#include <splinefig/renderer/text_outlines.hpp>

#include <benchmark/benchmark.h>
#include <cairo.h>

#include <string>

namespace sr = splinefig::render;

namespace {

constexpr int kSize = 1024, kLabels = 200;
const std::string kLabel = "Spline k(s) = 0.25, t \xe2\x88\x92 1";  // 24 characters, U+2212 inside

int glyphs_in(const std::string& s) {
  int n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80 && c != ' ';
  return n;
}

void BM_layout(benchmark::State& st) {
  sr::TextStyle style;
  for (auto _ : st) benchmark::DoNotOptimize(sr::measure_text(kLabel, style));
  st.counters["glyphs_per_s"] = benchmark::Counter(static_cast<double>(glyphs_in(kLabel)) * st.iterations(), benchmark::Counter::kIsRate);
}

void BM_path(benchmark::State& st) {
  sr::TextStyle style;
  for (auto _ : st) benchmark::DoNotOptimize(sr::text_path(kLabel, {10.25, 20.5}, style));
  st.counters["glyphs_per_s"] = benchmark::Counter(static_cast<double>(glyphs_in(kLabel)) * st.iterations(), benchmark::Counter::kIsRate);
}

void BM_scene(benchmark::State& st) {
  const double size = static_cast<double>(st.range(0));
  sr::TextStyle style;
  style.size = size;
  for (auto _ : st) {
    sr::Scene s(kSize, kSize);
    for (int i = 0; i < kLabels; ++i) s.text(kLabel, {3.0 + (i % 4) * 250.3, 20.0 + (i / 4) * 20.1}, style);
    benchmark::DoNotOptimize(sr::rasterize(s, 1));
  }
  st.counters["glyphs_per_s"] =
      benchmark::Counter(static_cast<double>(glyphs_in(kLabel)) * kLabels * st.iterations(), benchmark::Counter::kIsRate);
}

// The geometry part of BM_scene: outlines placed and flattened within the arc tolerance.
void BM_flatten(benchmark::State& st) {
  sr::TextStyle style;
  style.size = static_cast<double>(st.range(0));
  std::size_t verts = 0;
  for (auto _ : st) {
    verts = 0;
    for (int i = 0; i < kLabels; ++i) {
      const auto flat = sr::text_path(kLabel, {3.0 + (i % 4) * 250.3, 20.0 + (i / 4) * 20.1}, style).flatten(1e-4);
      for (const auto& c : flat.contours) verts += c.size();
    }
    benchmark::DoNotOptimize(verts);
  }
  st.counters["vertices_per_glyph"] = static_cast<double>(verts) / (glyphs_in(kLabel) * kLabels);
  st.counters["glyphs_per_s"] =
      benchmark::Counter(static_cast<double>(glyphs_in(kLabel)) * kLabels * st.iterations(), benchmark::Counter::kIsRate);
}

void BM_empty(benchmark::State& st) {  // the canvas alone: what BM_scene costs without text
  for (auto _ : st) {
    sr::Scene s(kSize, kSize);
    benchmark::DoNotOptimize(sr::rasterize(s, 1));
  }
}

void BM_cairo(benchmark::State& st) {
  const double size = static_cast<double>(st.range(0));
  cairo_surface_t* surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSize, kSize);
  cairo_t* cr = cairo_create(surf);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  for (auto _ : st) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    for (int i = 0; i < kLabels; ++i) {
      cairo_move_to(cr, 3.0 + (i % 4) * 250.3, 20.0 + (i / 4) * 20.1);
      cairo_show_text(cr, kLabel.c_str());
    }
    cairo_surface_flush(surf);
    benchmark::DoNotOptimize(cairo_image_surface_get_data(surf));
  }
  st.counters["glyphs_per_s"] =
      benchmark::Counter(static_cast<double>(glyphs_in(kLabel)) * kLabels * st.iterations(), benchmark::Counter::kIsRate);
  cairo_destroy(cr);
  cairo_surface_destroy(surf);
}

}  // namespace

BENCHMARK(BM_layout)->Name("text/layout");
BENCHMARK(BM_path)->Name("text/path");
BENCHMARK(BM_scene)->Name("text/scene")->Arg(12)->Arg(48)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_flatten)->Name("text/flatten")->Arg(12)->Arg(48)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_empty)->Name("text/empty-canvas")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_cairo)->Name("text/cairo")->Arg(12)->Arg(48)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
