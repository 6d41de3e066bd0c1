#pragma once
// Figures: a spec laid out and drawn. render_figure() turns a FigureSpec into an image
// plus the facts that image-based tests and index.json need (docs/figures.md): where each
// axes' plot box is in pixels, its data ranges, and the colour of every labelled series.
#include <splinefig/figures/figure_info.hpp>
#include <splinefig/figures/spec.hpp>

#include <string>
#include <vector>

namespace splinefig::figures {

struct RenderOptions {
  double scale = 1;  // output pixels per spec pixel
  int threads = 0;   // <= 0: all hardware threads
};

struct RenderedFigure {
  Image image;
  FigureInfo info;
};

// Throws SpecFileError if the scaled canvas is too large, std::runtime_error if an image
// element cannot be read.
RenderedFigure render_figure(const FigureSpec& spec, const RenderOptions& options = {});

// The figure as renderer scenes at `scale` output pixels per spec pixel: `scene` with every
// position exact (what vector/ writes as SVG or PDF), and `raster`, the same items with the
// axis-aligned hairlines (spines, ticks, grid and zero lines) moved onto the pixel grid, so that
// a 1-px tick is one pixel column at full ink (what render_figure, PNG, EXR and the animation
// rasterize).
struct FigureScene {
  render::Scene scene;
  FigureInfo info;
  render::Scene raster;
};
FigureScene figure_scene(const FigureSpec& spec, double scale = 1);

// The figure of the spec file at `path`, rendered: load_spec() then render_figure(), for tests
// that check a spec against a reference in one line,
//   CHECK_THAT(render_spec_to_image("fig.toml"), MatchesReference("fig.png"));
// Throws SpecFileError (a bad spec, a canvas too large at options.scale) as those do.
Image render_spec_to_image(const std::string& path, const RenderOptions& options = {});

// The layout alone (no rasterization): the same info render_figure() reports.
FigureInfo layout_figure(const FigureSpec& spec, double scale = 1);

// Checks the scaled canvas against the size limits; throws SpecFileError naming `what`.
void check_scaled_canvas(const FigureSpec& spec, double scale, const std::string& what);

}  // namespace splinefig::figures
