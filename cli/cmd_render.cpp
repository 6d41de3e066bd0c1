// `splinefig render SPEC.toml -o OUT.(png|exr|svg|pdf|webp) [--scale S] [--dpi N] [--threads N]
// [--coverage-tolerance T] [-v]`:
// one figure spec (docs/spec.md) rendered to one file, the format chosen by the extension
// (.webp: the spec's [animation], an animated WebP).
#include "command.hpp"
#include "raster_report.hpp"
#include "stdio.hpp"

#include <splinefig/figures/animation.hpp>
#include <splinefig/figures/batch.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/version.hpp>
#include <splinefig/base/extension.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace {

namespace fig = splinefig::figures;

// The files a spec read from stdin names (fig::spec_inputs, on a scratch copy of its bytes),
// resolved as render reads them, from the current directory, and placed as "stdin:LINE".
std::vector<fig::SpecInput> stdin_spec_inputs(const std::string& text) {
  splinefig::cli::Scratch scratch;
  const std::string path = scratch.file("stdin.toml");
  {
    std::ofstream f(path, std::ios::binary);
    if (!f.write(text.data(), static_cast<std::streamsize>(text.size())) || !f.flush())
      throw splinefig::cli::Failure("cannot save stdin in " + path);
  }
  std::vector<fig::SpecInput> inputs = fig::spec_inputs(path);
  const std::string dir = std::filesystem::path(path).parent_path().string() + "/";
  for (fig::SpecInput& in : inputs) {
    if (in.path.rfind(dir, 0) == 0) in.path = in.path.substr(dir.size());
    in.where = splinefig::cli::said_as(in.where, path, "stdin");
  }
  return inputs;
}

struct RenderArgs {
  std::string spec, out, format;
  double scale = 1;
  double dpi = 0;
  int threads = 0;
  double coverage_tolerance = -1;  // not given: the spec's
  bool verbose = false;
};

const splinefig::cli::Registration reg{
    "render", "Render one TOML figure spec to a PNG, EXR, SVG or PDF file", [](CLI::App& app) {
      auto a = std::make_shared<RenderArgs>();
      app.add_option("spec", a->spec, "Figure spec (TOML, see docs/spec.md); - reads it from stdin, its relative paths then from the current directory")->type_name("PATH")->required();
      app.add_option("-o,--output", a->out, "Output: .png (8-bit sRGB), .exr (float linear), .svg or .pdf (vector, exact curves), .webp (the spec's [animation]); - writes to stdout")
          ->type_name("PATH")->required();
      splinefig::cli::choices(
          app.add_option("--format", a->format, "Output format png, exr, svg or pdf, for -o - (png when not given) or a name without one of those extensions")
              ->type_name("NAME"),
          {"png", "exr", "svg", "pdf"});
      app.add_option("--scale", a->scale, "Output pixels per spec pixel")->capture_default_str();
      app.add_option("--dpi", a->dpi, "Spec pixels per inch, written to the file (PNG pHYs, EXR, PDF page and SVG size; 0: from the spec's print_width, else none)")
          ->type_name("FLOAT")->capture_default_str();
      app.add_option("--threads", a->threads, "Rendering threads (0: all cores; at most 256)")->type_name("INT")->capture_default_str();
      app.add_option("--coverage-tolerance", a->coverage_tolerance,
                     "Coverage error accepted where a dense stroke is drawn from its pieces, in [0, 1] (0: exact everywhere); replaces the spec's [canvas] coverage_tolerance")
          ->type_name("FLOAT");
      app.add_flag("-v,--verbose", a->verbose, "Say on stderr how the picture was rasterized: exactly, or which items had bands drawn within the coverage tolerance");
      app.footer("Example: splinefig render figures/specs/bias.toml -o bias.svg --scale 2");
      return splinefig::cli::Runner([a, &app] {
        using splinefig::cli::Failure;
        const bool to_stdout = splinefig::cli::is_stdio(a->out), from_stdin = splinefig::cli::is_stdio(a->spec);
        // The format: --format, else the extension, else png for stdout (one value, never an
        // optional read after the checks: GCC 12 at -O2 warns about that).
        bool has_ext = false;
        fig::Format ext = fig::Format::png;
        // .webp: the spec's [animation] (docs/spec.md), an animated WebP; no --format names it.
        const bool animation = !to_stdout && splinefig::lower_extension(a->out) == "webp";
        if (animation && !a->format.empty())
          throw Failure("--format " + a->format + ": -o " + a->out + " names another format (.webp)");
        if (!to_stdout && !animation)
          if (const std::optional<fig::Format> f = fig::format_of_path(a->out)) {
            has_ext = true;
            ext = *f;
          }
        fig::Format chosen = fig::Format::png;
        if (!a->format.empty()) {
          const std::optional<fig::Format> named = fig::format_named(a->format);
          if (!named) throw Failure("--format " + splinefig::cli::printable(a->format) + ": not one of png, exr, svg, pdf");
          if (has_ext && ext != *named)
            throw Failure("--format " + a->format + ": -o " + a->out + " names another format (." +
                          fig::extension(ext) + ")");
          chosen = *named;
        } else if (has_ext) {
          chosen = ext;
        } else if (!to_stdout && !animation) {
          throw Failure("-o " + a->out + ": the output must end in .png, .exr, .svg or .pdf (or give --format)");
        }
        const fig::Format* const format = &chosen;
        if (!to_stdout && !from_stdin && splinefig::same_file(a->out, a->spec))
          throw Failure("-o " + a->out + ": it is the spec " + a->spec);
        splinefig::cli::check_output_scale(a->scale, splinefig::cli::typed_number(app, "--scale", a->scale).said);
        const int threads = splinefig::cli::check_threads(a->threads);
        const bool tolerance_given = app.get_option("--coverage-tolerance")->count() > 0;
        if (tolerance_given)
          splinefig::cli::check_coverage_tolerance(
              a->coverage_tolerance, splinefig::cli::typed_number(app, "--coverage-tolerance", a->coverage_tolerance).said);
        const double dpi = splinefig::cli::check_dpi(a->dpi, splinefig::cli::typed_number(app, "--dpi", a->dpi).said);
        const std::string spec_name = from_stdin ? "stdin" : a->spec;
        std::string need;  // the scaled canvas, for a message about memory (as figures says it)
        try {
          const std::string text = from_stdin ? splinefig::cli::read_stdin_bytes("the spec", splinefig::kMaxSpecBytes) : "";
          fig::FigureSpec spec = from_stdin ? fig::parse_spec(text, "stdin", ".") : fig::load_spec(a->spec);
          if (tolerance_given) spec.canvas.coverage_tolerance = a->coverage_tolerance;
          // An output never replaces an input: the spec or a file it names.
          if (std::string bad = to_stdout || from_stdin ? "" : fig::output_over_input({a->out}, {a->spec}); !bad.empty())
            throw Failure("-o " + bad + " (write to another file)");
          if (from_stdin && !to_stdout)
            for (const fig::SpecInput& in : stdin_spec_inputs(text))
              if (splinefig::same_file(a->out, in.path))
                throw Failure("-o " + a->out + ": it is " + in.where + ", an input (write to another file)");
          {
            const double cw = std::round(spec.canvas.width * a->scale), ch = std::round(spec.canvas.height * a->scale);
            char buf[128];
            std::snprintf(buf, sizeof buf, "%.0f x %.0f px at --scale %g, %.0f MiB as a float RGBA image", cw, ch, a->scale,
                          std::ceil(cw * ch * 16 / (1 << 20)));
            need = buf;
          }
          fig::check_scaled_canvas(spec, a->scale, "--scale");
          if (animation) {
            if (!spec.animation)
              throw Failure("-o " + a->out + ": a .webp output is the spec's [animation], and " + spec_name + " has none");
            fig::check_animation_size(spec, a->scale);
            std::vector<splinefig::render::RasterReport> frames;
            fig::write_animation(spec, a->out, a->scale, threads, a->verbose ? &frames : nullptr);
            if (a->verbose)
              for (const std::string& line : splinefig::cli::describe_frames(frames))
                std::fprintf(stderr, "splinefig render: %s: %s\n", splinefig::cli::printable(spec_name).c_str(), line.c_str());
            return 0;
          }
          const fig::FigureScene f = fig::figure_scene(spec, a->scale);
          fig::FigureFileOptions w;
          w.scale = a->scale;
          w.dpi = dpi > 0 ? dpi : spec.canvas.print_dpi();  // else the spec's printed size
          w.threads = threads;
          w.software = std::string("splinefig ") + SPLINEFIG_VERSION;
          w.title = fig::file_title(spec);
          w.date = fig::source_date_epoch();
          splinefig::render::RasterReport report;
          w.report = &report;
          std::optional<splinefig::Image> raster;
          try {
            splinefig::cli::Scratch scratch;
            const std::string path = to_stdout ? scratch.file(std::string("stdout.") + fig::extension(*format)) : a->out;
            try {
              fig::write_figure_file(f, path, *format, w, raster);
            } catch (const splinefig::UnwritableFile& e) {
              if (!to_stdout) throw;
              throw Failure(splinefig::cli::said_as(e.what(), path, "stdout"), e);
            }
            if (to_stdout) splinefig::cli::file_to_stdout(scratch, path);
          } catch (const std::length_error& e) {  // an item past the rasterizer's work limit
            throw Failure(a->spec + ": " + e.what());
          }
          if (a->verbose)
            std::fprintf(stderr, "splinefig render: %s: %s\n", splinefig::cli::printable(spec_name).c_str(),
                         raster ? splinefig::cli::describe_raster(report).c_str()
                                : "not rasterized (the vector file keeps the exact curves)");
        } catch (const std::bad_alloc&) {
          // One line naming the spec and what it needed, not a bare "std::bad_alloc".
          throw Failure(spec_name + ": out of memory " +
                        (need.empty() ? std::string("reading the spec") : "rendering the figure (" + need + ")"));
        }
        return 0;
      });
    }};

}  // namespace
