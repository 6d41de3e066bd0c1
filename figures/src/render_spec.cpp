// A spec file straight to its image (figure.hpp).
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

namespace splinefig::figures {

Image render_spec_to_image(const std::string& path, const RenderOptions& options) {
  const FigureSpec spec = load_spec(path);
  return render_figure(spec, options).image;
}

}  // namespace splinefig::figures
