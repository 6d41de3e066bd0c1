// `splinefig render SPEC.toml -o OUT.(png|exr) [--scale S] [--threads N]`: one figure spec
// (docs/spec.md) rendered to one image.
#include "command.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/version.hpp>

#include <filesystem>
#include <memory>

namespace {

struct RenderArgs {
  std::string spec, out;
  double scale = 1;
  int threads = 0;
};

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

const splinefig::cli::Registration reg{
    "render", "Render one TOML figure spec to a PNG or EXR image", [](CLI::App& app) {
      auto a = std::make_shared<RenderArgs>();
      app.add_option("spec", a->spec, "Figure spec (TOML, see docs/spec.md)")->type_name("PATH")->required();
      app.add_option("-o,--output", a->out, "Output image: .png (8-bit sRGB) or .exr (float linear)")->type_name("PATH")->required();
      app.add_option("--scale", a->scale, "Output pixels per spec pixel")->capture_default_str();
      app.add_option("--threads", a->threads, "Rendering threads (0: all cores; at most 256)")->type_name("INT")->capture_default_str();
      app.footer("Example: splinefig render figures/specs/bias.toml -o bias.png --scale 2");
      return splinefig::cli::Runner([a] {
        using splinefig::cli::Failure;
        namespace fig = splinefig::figures;
        const std::string ext = extension_of(a->out);
        if (ext != ".png" && ext != ".exr") throw Failure("-o " + a->out + ": the output must end in .png or .exr");
        if (splinefig::same_file(a->out, a->spec)) throw Failure("-o " + a->out + ": it is the spec " + a->spec);
        splinefig::cli::check_input_file(a->spec);
        splinefig::cli::check_output_scale(a->scale);
        const int threads = splinefig::cli::check_threads(a->threads);
        try {
          fig::FigureSpec spec = fig::load_spec(a->spec);
          fig::check_scaled_canvas(spec, a->scale, "--scale");
          fig::RenderedFigure r = fig::render_figure(spec, {a->scale, threads});
          splinefig::WriteOptions w;
          w.software = std::string("splinefig ") + SPLINEFIG_VERSION;
          w.description = spec.title.empty() ? spec.name : spec.name + ": " + spec.title;
          splinefig::write_image(a->out, r.image, w);
        } catch (const fig::SpecFileError& e) {
          throw Failure(e.what());
        }
        return 0;
      });
    }};

}  // namespace
