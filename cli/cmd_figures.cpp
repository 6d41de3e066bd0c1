// `splinefig figures [--out DIR] [--only NAME...] [--format png,exr,svg,pdf] [--scale S] [--dpi N]`: renders
// every built-in figure spec (figures/specs), then index.json and the gallery index.html.
// With --only, the index keeps the entries of the figures that were not rendered again.
// The index is written only after every image of the run: a figure that fails keeps its
// previous entry (and its previous images), and a run that renders nothing leaves the index alone.
#include "command.hpp"
#include "raster_report.hpp"

#include <splinefig/figures/batch.hpp>
#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/version.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace {

namespace fig = splinefig::figures;
namespace fs = std::filesystem;
using splinefig::cli::Failure;
using splinefig::cli::printable;

struct FiguresArgs {
  std::string out = "out/figures";
  std::vector<std::string> only;
  std::string format = "png";
  double scale = 1;
  double dpi = 0;
  int threads = 0;
  std::string specs;
  double coverage_tolerance = -1;  // not given: each spec's
  bool verbose = false;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= s.size()) {
    size_t comma = s.find(',', start);
    if (comma == std::string::npos) comma = s.size();
    out.push_back(s.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

// The flags checked and turned into batch options.
fig::BatchOptions batch_options(const FiguresArgs& a, const CLI::App& app) {
  splinefig::cli::check_output_scale(a.scale, splinefig::cli::typed_number(app, "--scale", a.scale).said);
  fig::BatchOptions o;
  o.out_dir = a.out;
  o.scale = a.scale;
  o.threads = splinefig::cli::check_threads(a.threads);
  o.software = std::string("splinefig ") + SPLINEFIG_VERSION;
  o.dpi = splinefig::cli::check_dpi(a.dpi, splinefig::cli::typed_number(app, "--dpi", a.dpi).said);
  o.date = fig::source_date_epoch();
  if (app.get_option("--coverage-tolerance")->count() > 0)
    o.coverage_tolerance = splinefig::cli::check_coverage_tolerance(
        a.coverage_tolerance, splinefig::cli::typed_number(app, "--coverage-tolerance", a.coverage_tolerance).said);
  o.formats.clear();
  for (const auto& f : split(a.format)) {
    const auto format = fig::format_named(f);
    if (!format) throw Failure("--format " + a.format + ": \"" + f + "\" is not png, exr, svg or pdf");
    if (std::find(o.formats.begin(), o.formats.end(), *format) == o.formats.end()) o.formats.push_back(*format);
  }
  return o;
}

// Every spec of the directory; `only` names some of them.
std::vector<fig::SpecFile> all_specs(const FiguresArgs& a) {
  const std::string dir = a.specs.empty() ? fig::builtin_specs_dir() : a.specs;
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (!a.specs.empty() && !fs::is_directory(st))
    throw Failure("--specs " + printable(a.specs) + ": " +
                  (fs::exists(st)                               ? std::string("not a directory (give the directory of the specs)")
                   : ec && st.type() != fs::file_type::not_found ? "cannot open it (" + ec.message() + ")"
                                                                 : std::string("no such directory")));
  if (dir.empty() || !fs::is_directory(st))
    throw Failure("cannot find the built-in figure specs (set SPLINEFIG_SPECS_DIR or use --specs DIR)");
  std::vector<fig::SpecFile> specs = fig::list_specs(dir);
  for (const auto& n : a.only)
    if (std::none_of(specs.begin(), specs.end(), [&](const fig::SpecFile& s) { return s.name == n; })) {
      std::string list;
      for (const auto& s : specs) list += (list.empty() ? "" : ", ") + s.name;
      throw Failure("--only " + n + ": no such figure (known: " + list + ")");
    }
  return specs;
}

std::vector<fig::SpecFile> selected(std::vector<fig::SpecFile> specs, const std::vector<std::string>& only) {
  if (only.empty()) return specs;
  std::erase_if(specs, [&](const fig::SpecFile& s) { return std::find(only.begin(), only.end(), s.name) == only.end(); });
  return specs;
}

// "  name      12.3 ms (CPU 11 ms)"
std::string progress_line(const fig::BatchResult& r) {
  char buf[160];
  std::string cpu = r.cpu_ms >= 0 ? " (CPU " + std::to_string(std::lround(r.cpu_ms)) + " ms)" : "";
  std::snprintf(buf, sizeof buf, "  %-18s %7.1f ms%s", r.name.c_str(), r.wall_ms, cpu.c_str());
  return buf;
}

int run(const FiguresArgs& a, const CLI::App& app) {
  const fig::BatchOptions options = batch_options(a, app);
  const std::vector<fig::SpecFile> specs = all_specs(a);
  const std::vector<fig::SpecFile> chosen = selected(specs, a.only);
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (!fs::is_directory(a.out, ec))
    throw Failure("--out " + printable(a.out) + ": cannot create the directory" + (ec ? " (" + ec.message() + ")" : ""));

  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  std::vector<fig::FigureInfo> done;
  std::set<std::string> failed_names;
  int failed = 0;
  fig::render_batch(chosen, options, [&](fig::BatchResult& r) {
    if (r.info) {
      std::printf("%s\n", progress_line(r).c_str());
      std::fflush(stdout);
      if (a.verbose && r.raster_report)
        std::fprintf(stderr, "splinefig figures: %s: %s\n", r.name.c_str(), splinefig::cli::describe_raster(*r.raster_report).c_str());
      if (a.verbose)
        for (const std::string& line : splinefig::cli::describe_frames(r.frame_reports))
          std::fprintf(stderr, "splinefig figures: %s.webp: %s\n", r.name.c_str(), line.c_str());
      done.push_back(std::move(*r.info));
    } else {
      ++failed;
      failed_names.insert(r.name);
      std::cerr << "splinefig figures: " << splinefig::cli::printable(r.error) << "\n";
    }
  });
  if (!done.empty()) {
    // A run with --only keeps the previous entries of the figures it did not render; a whole
    // run keeps, of the previous entries, only those that failed now.
    std::function<bool(const fig::FigureInfo&)> keep;
    if (!a.only.empty()) keep = [](const fig::FigureInfo&) { return true; };
    else if (failed) keep = [&](const fig::FigureInfo& f) { return failed_names.count(f.name) > 0; };
    fig::update_index(a.out, done, specs, keep, {SPLINEFIG_VERSION, options.date}, [](const std::string& why) {
      std::cerr << "splinefig figures: " << splinefig::cli::printable(why) << "\n";
    });
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  std::printf("%zu figure%s in %.2f s (%.2f s CPU) -> %s/index.html\n", done.size(), done.size() == 1 ? "" : "s", total,
              cpu, a.out.c_str());
  if (failed) throw Failure(std::to_string(failed) + " of " + std::to_string(chosen.size()) + " figures failed");
  return 0;
}

const splinefig::cli::Registration reg{
    "figures", "Regenerate the built-in figures, index.json and the gallery index.html", [](CLI::App& app) {
      auto a = std::make_shared<FiguresArgs>();
      app.add_option("--out", a->out, "Output directory")->type_name("PATH")->capture_default_str();
      app.add_option("--only", a->only, "Only these figures (names as in figures/specs; repeat or comma-separate)")->type_name("NAME")
          ->delimiter(',');
      splinefig::cli::choices(app.add_option("--format", a->format, "Comma-separated: png, exr, svg, pdf")->type_name("NAME,...")->capture_default_str(),
                              {"png", "exr", "svg", "pdf"});
      app.add_option("--scale", a->scale, "Output pixels per spec pixel (2 for print)")->capture_default_str();
      app.add_option("--dpi", a->dpi, "Spec pixels per inch, written to the files (PNG pHYs, EXR, PDF page and SVG size; 0: from the spec's print_width, else none)")
          ->type_name("FLOAT")->capture_default_str();
      app.add_option("--threads", a->threads, "Rendering threads (0: all cores; at most 256)")->type_name("INT")->capture_default_str();
      app.add_option("--coverage-tolerance", a->coverage_tolerance,
                     "Coverage error accepted where a dense stroke is drawn from its pieces, in [0, 1] (0: exact everywhere); replaces every spec's [canvas] coverage_tolerance")
          ->type_name("FLOAT");
      app.add_flag("-v,--verbose", a->verbose, "Say on stderr, per figure and per run of its animation's frames drawn alike, how it was rasterized: exactly, or which items had bands drawn within the coverage tolerance");
      app.add_option("--specs", a->specs, "Directory of specs to render instead of the built-in ones")->type_name("PATH");
      app.footer("Example: splinefig figures --out out/figures --only bias,arclength --scale 2 --format png,svg");
      return splinefig::cli::Runner([a, &app] { return run(*a, app); });
    }};

}  // namespace
