#pragma once
// Rendering a list of specs into a directory: one figure per worker thread, the results
// handed back in spec order (what `splinefig figures` does with the built-in specs).
#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/output.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace splinefig::figures {

struct BatchOptions {
  std::string out_dir;                       // must exist
  std::vector<Format> formats{Format::png};  // each written as NAME.<extension(format)>
  double scale = 1;                          // output pixels per spec pixel
  int threads = 0;                           // <= 0: all hardware threads
  std::string software;                      // image metadata ("splinefig 1.2.3")
  double dpi = 0;                            // spec pixels per inch (output.hpp); 0: none
  long long date = -1;                       // PDF creation date, seconds since 1970; none if < 0
  // Replaces every spec's [canvas] coverage_tolerance (in [0, 1]) when set.
  std::optional<double> coverage_tolerance;
};

struct BatchResult {
  std::string name;                 // the spec's name
  std::optional<FigureInfo> info;   // with the files written; unset when the figure failed
  std::string error;                // one line when it failed
  double wall_ms = 0;
  double cpu_ms = -1;               // the figure's own CPU time, when it ran on one thread
  // How the still figure was rasterized, when a PNG or EXR was written (output.hpp).
  std::optional<render::RasterReport> raster_report;
  // How each frame of its animation was rasterized, when one was written; empty otherwise.
  std::vector<render::RasterReport> frame_reports;
};

// Loads, renders and writes every spec. Figures render in parallel, one per worker: a
// figure's serial parts (text, PNG encoding) dominate, so this beats splitting one figure
// across threads; with one worker the rasterizer gets the threads instead. There are at most
// as many workers as cores, and a worker starts a figure only when its canvas fits beside
// those under way in a memory budget (three quarters of memory_available(), parallel.hpp), so
// the memory held does not grow with `threads`; a figure larger than the budget runs alone. The images do not
// depend on the thread count. `done` is called once per spec, in spec order, one call at a time
// (from whichever thread completed the result, with the batch's lock held: keep it short), as
// soon as the results before it are in. If `done` throws, no further figure is started and the
// exception is rethrown here once the figures under way have finished.
// With PNG among the formats, a spec with [animation] also gets NAME.webp (animation.hpp), drawn
// after its other files, its size checked with the canvas before anything is drawn.
// Before anything is rendered, throws std::runtime_error (one line) if an output would replace
// an input: output_over_input of every NAME.<format> (and NAME.webp with PNG) and of index.json
// and index.html.
void render_batch(const std::vector<SpecFile>& specs, const BatchOptions& options,
                  const std::function<void(BatchResult&)>& done);

// A file a spec reads: the string of a `file` or `KEY_file` key (an image, a points_file, a
// knots_file) at any depth, resolved as load_spec resolves it, against the spec's directory.
struct SpecInput {
  std::string path;   // as resolved
  std::string where;  // "FILE:LINE: image.file = \"pic.png\""
  bool image = false; // a `file` key: an image ([[image]], [[axes.image]]), read by the image I/O module
};
// Every file the spec at `spec_path` names; none for a spec load_spec would refuse to read or
// parse (its own error comes from there).
std::vector<SpecInput> spec_inputs(const std::string& spec_path);
// Whether an output path is an input, by any spelling, symbolic or hard link (same_file): one
// of the specs or a file one of them names. "OUT: it is FILE:LINE: image.file = \"pic.png\", an
// input" for the first such output, else empty.
std::string output_over_input(const std::vector<std::string>& outputs, const std::vector<std::string>& specs);

}  // namespace splinefig::figures
