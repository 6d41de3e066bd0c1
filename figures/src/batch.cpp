// Figures rendered in parallel, their results handed back in spec order (see batch.hpp).
#include <splinefig/figures/batch.hpp>
#include <splinefig/base/parallel.hpp>
#include <splinefig/figures/animation.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/image/atomic_file.hpp>
#include <splinefig/image/io.hpp>

#include "load/toml_reader.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

namespace splinefig::figures {
namespace {

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// The bytes a figure of `pixels` holds while it is rendered and written, for the batch's memory
// budget: its float RGBA canvas (16 a pixel) and, for a raster file, the file's integer pixels
// and encoded bytes (at most 8 a pixel together); a vector file holds the scene only.
std::uint64_t figure_bytes(double pixels, const BatchOptions& o) {
  const bool raster = std::any_of(o.formats.begin(), o.formats.end(), [](Format f) { return f == Format::png || f == Format::exr; });
  return static_cast<std::uint64_t>(pixels * (raster ? 24 : 4));
}

// Whether the batch writes PNG files, and with them each [animation]'s WebP.
bool writes_png(const BatchOptions& o) { return std::find(o.formats.begin(), o.formats.end(), Format::png) != o.formats.end(); }

// The bytes an animation holds while one frame is drawn and encoded: the frame's float RGBA
// canvas and 8-bit values (20 a pixel), and the encoder's current, previous and candidate
// canvases (12 a pixel).
std::uint64_t animation_bytes(const FigureSpec& spec, const BatchOptions& o) {
  if (!spec.animation || !writes_png(o)) return 0;
  return static_cast<std::uint64_t>(std::round(spec.animation->width * o.scale) * std::round(spec.animation->height * o.scale) * 32);
}

BatchResult render_one(const SpecFile& s, const BatchOptions& o, int raster_threads, MemoryBudget& budget) {
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = thread_cpu_ms();
  BatchResult result;
  result.name = s.name;
  std::string canvas;  // the scaled canvas, for a message about memory
  try {
    FigureSpec spec = load_spec(s.path);
    if (o.coverage_tolerance) spec.canvas.coverage_tolerance = *o.coverage_tolerance;
    {
      const double w = std::round(spec.canvas.width * o.scale), h = std::round(spec.canvas.height * o.scale);
      char buf[128];
      std::snprintf(buf, sizeof buf, "%.0f x %.0f px at --scale %g, %.0f MiB as a float RGBA image", w, h, o.scale,
                    std::ceil(w * h * 16 / (1 << 20)));
      canvas = buf;
    }
    check_scaled_canvas(spec, o.scale, "--scale");
    if (writes_png(o)) check_animation_size(spec, o.scale);
    // Waits until the figure's bytes fit beside those of the figures under way.
    const MemoryBudget::Grant grant = budget.acquire(
        figure_bytes(std::round(spec.canvas.width * o.scale) * std::round(spec.canvas.height * o.scale), o) +
        animation_bytes(spec, o));
    FigureScene fig = figure_scene(spec, o.scale);
    FigureFileOptions w;
    w.scale = o.scale;
    w.dpi = o.dpi > 0 ? o.dpi : spec.canvas.print_dpi();  // else the spec's printed size
    w.threads = raster_threads;
    w.software = o.software;
    w.title = file_title(spec);
    w.date = o.date;
    render::RasterReport report;
    w.report = &report;
    std::optional<Image> raster;
    for (const auto& format : o.formats) {
      const std::string file = s.name + "." + extension(format);
      write_figure_file(fig, (std::filesystem::path(o.out_dir) / file).string(), format, w, raster);
      fig.info.files.push_back(file);
    }
    if (raster) result.raster_report = std::move(report);
    // The filmstrips' animation beside the PNG, drawn after the still figure's files.
    if (spec.animation && writes_png(o)) {
      raster.reset();
      const std::string file = s.name + ".webp";
      AnimationInfo a = write_animation(spec, (std::filesystem::path(o.out_dir) / file).string(), o.scale, raster_threads,
                                        &result.frame_reports);
      a.file = file;
      fig.info.files.push_back(file);
      fig.info.animation = std::move(a);
    }
    result.info = std::move(fig.info);
  } catch (const std::bad_alloc&) {
    // One line naming the figure and its size, not a bare "std::bad_alloc".
    result.error = s.path + (canvas.empty() ? ": out of memory reading the spec" : ": out of memory rendering the figure (" + canvas + ")");
  } catch (const std::exception& e) {
    // Every failure names its spec first, as render does: a spec error is located there
    // already ("PATH:LINE: KEY: ..."); the others (an item past the sweep's work limit, an
    // output that cannot be written, ...) get the path in front.
    const std::string what = e.what();
    const bool named = what.size() > s.path.size() && what.compare(0, s.path.size(), s.path) == 0 && what[s.path.size()] == ':';
    result.error = named ? what : s.path + ": " + what;
  }
  result.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (raster_threads == 1) result.cpu_ms = thread_cpu_ms() - c0;
  return result;
}

// The spec's text by load_spec's rules (a regular file of at most kMaxSpecBytes), or nothing.
std::optional<std::string> spec_text(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.find('\0') != std::string::npos || !fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text;
  std::array<char, 1 << 16> buf;
  while (in.read(buf.data(), buf.size()) || in.gcount() > 0) {
    text.append(buf.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSpecBytes) return std::nullopt;
  }
  if (in.bad()) return std::nullopt;
  return text;
}

bool names_a_file(std::string_view key) { return key == "file" || (key.size() > 5 && key.ends_with("_file")); }

void collect_inputs(const toml::node& node, const std::string& key, const std::string& spec,
                    const std::filesystem::path& base, std::vector<SpecInput>& out) {
  if (const toml::table* t = node.as_table()) {
    for (const auto& [k, v] : *t) {
      const std::string name(k.str());
      const std::string path = key.empty() ? name : key + "." + name;
      if (const auto* s = v.as_string(); s && names_a_file(name) && !s->get().empty()) {
        std::filesystem::path p(s->get());
        if (p.is_relative()) p = base / p;
        out.push_back({p.string(), detail::location_of(spec, v.source()).with_key(path).str() + " = \"" + s->get() + "\"",
                       name == "file"});
      } else {
        collect_inputs(v, path, spec, base, out);
      }
    }
  } else if (const toml::array* a = node.as_array()) {
    for (const auto& v : *a) collect_inputs(v, key, spec, base, out);
  }
}

// The first output that is an input of the specs (`inputs` their spec_inputs): see
// output_over_input.
std::string output_over(const std::vector<std::string>& outputs, const std::vector<std::string>& specs,
                        const std::vector<std::vector<SpecInput>>& inputs) {
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const std::string& spec = specs[i];
    for (const std::string& out : outputs) {
      if (same_file(out, spec)) return out + ": it is the spec " + spec + ", an input";
      for (const SpecInput& in : inputs[i])
        if (same_file(out, in.path)) return out + ": it is " + in.where + ", an input";
    }
  }
  return {};
}

// Whether the batch may load the image I/O module: a format other than those written without it
// (PNG by libpng, SVG, PDF), or a spec with an image read from a file.
bool needs_image_io(const std::vector<std::vector<SpecInput>>& inputs, const BatchOptions& o) {
  for (const auto& f : o.formats)
    if (f == Format::exr) return true;
  for (const auto& spec : inputs)
    for (const SpecInput& in : spec)
      if (in.image) return true;
  return false;
}

}  // namespace

std::vector<SpecInput> spec_inputs(const std::string& spec_path) {
  std::vector<SpecInput> out;
  const auto text = spec_text(spec_path);
  if (!text) return out;
  // The same checks as load_spec before the parser sees the text (key depth: its stack).
  if (!detail::utf8_problem(*text, spec_path).empty() || !detail::key_depth_problem(*text, spec_path).empty()) return out;
  toml::table doc;
  try {
    doc = toml::parse(*text, spec_path);
  } catch (const toml::parse_error&) {
    return out;
  }
  const std::string dir = std::filesystem::path(spec_path).parent_path().string();
  collect_inputs(doc, "", spec_path, dir.empty() ? "." : dir, out);
  return out;
}

std::string output_over_input(const std::vector<std::string>& outputs, const std::vector<std::string>& specs) {
  std::vector<std::vector<SpecInput>> inputs;
  for (const std::string& spec : specs) inputs.push_back(spec_inputs(spec));
  return output_over(outputs, specs, inputs);
}

void render_batch(const std::vector<SpecFile>& specs, const BatchOptions& options,
                  const std::function<void(BatchResult&)>& done) {
  // Figures at once: at most one per core (more would add canvases in memory, not speed), and
  // only as many as the memory budget holds (render_one waits for it). With one worker the
  // rasterizer gets the threads instead.
  const int workers = static_cast<int>(std::min<std::size_t>(
      {specs.size(), static_cast<std::size_t>(worker_count(options.threads)), static_cast<std::size_t>(worker_count(0))}));
  const int raster_threads = workers > 1 ? 1 : options.threads;
  // The files each spec reads (its image and data files), from its parsed TOML.
  std::vector<std::vector<SpecInput>> inputs;
  for (const SpecFile& s : specs) inputs.push_back(spec_inputs(s.path));
  // No output may replace a file a spec reads, nor a spec, nor index.json and index.html: all
  // refused before anything is rendered or written.
  {
    std::vector<std::string> outputs, paths;
    for (const SpecFile& s : specs) {
      paths.push_back(s.path);
      for (const auto& format : options.formats)
        outputs.push_back((std::filesystem::path(options.out_dir) / (s.name + "." + extension(format))).string());
      if (writes_png(options)) outputs.push_back((std::filesystem::path(options.out_dir) / (s.name + ".webp")).string());
    }
    for (const char* index : {"index.json", "index.html"}) outputs.push_back((std::filesystem::path(options.out_dir) / index).string());
    if (std::string bad = output_over(outputs, paths, inputs); !bad.empty())
      throw std::runtime_error(bad + " (render into another --out)");
  }
  // The image I/O module first, if the batch may use it: a library it loads starts threads of its
  // own when loaded, and under a thread limit those must not find the budget taken by the workers.
  if (needs_image_io(inputs, options)) preload_image_io();
  // The canvases held at once: three quarters of the memory left to the process
  // (memory_available), less each worker's thread stack and malloc arena (8 and 64 MiB of
  // address space).
  const std::uint64_t available = memory_available(), per_worker = std::uint64_t(72) << 20;
  const std::uint64_t reserved = per_worker * static_cast<std::uint64_t>(workers);
  MemoryBudget budget(available > reserved ? (available - reserved) / 4 * 3 : 0);
  // Each result is kept until those before it are in; then the thread that completed it hands
  // it and every following one that is ready to `done`, in spec order, under the lock.
  std::vector<std::optional<BatchResult>> results(specs.size());
  std::mutex mutex;
  std::size_t handed = 0;  // results[0, handed) went to done
  parallel_for(specs.size(), workers, [&](std::size_t i, int) {
    BatchResult r = render_one(specs[i], options, raster_threads, budget);
    std::lock_guard<std::mutex> lock(mutex);
    results[i] = std::move(r);
    for (; handed < results.size() && results[handed]; ++handed) {
      done(*results[handed]);
      results[handed].reset();
    }
  });
}

}  // namespace splinefig::figures
