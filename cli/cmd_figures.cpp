// `splinefig figures [--out DIR] [--only NAME...] [--format png,exr] [--scale S]`: renders
// every built-in figure spec (figures/specs), then index.json and the gallery index.html.
#include "command.hpp"

#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/version.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>
#include <ctime>
#include <time.h>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

namespace {

struct FiguresArgs {
  std::string out = "out/figures";
  std::vector<std::string> only;
  std::string format = "png";
  double scale = 1;
  int threads = 0;
  std::string specs;
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

int run(const FiguresArgs& a) {
  using splinefig::cli::Failure;
  namespace fig = splinefig::figures;
  namespace fs = std::filesystem;
  if (!(a.scale > 0) || a.scale > 64) throw Failure("--scale " + std::to_string(a.scale) + ": must be in (0, 64]");
  if (a.threads < 0) throw Failure("--threads: must not be negative");
  std::vector<std::string> formats;
  for (const auto& f : split(a.format)) {
    if (f != "png" && f != "exr") throw Failure("--format " + a.format + ": \"" + f + "\" is not png or exr");
    if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
  }
  const std::string dir = a.specs.empty() ? fig::builtin_specs_dir() : a.specs;
  if (dir.empty() || !fs::is_directory(dir))
    throw Failure("cannot find the built-in figure specs (set SPLINEFIG_SPECS_DIR or use --specs DIR)");
  std::vector<fig::SpecFile> specs = fig::list_specs(dir);
  if (!a.only.empty()) {
    std::set<std::string> known;
    for (const auto& s : specs) known.insert(s.name);
    for (const auto& n : a.only)
      if (!known.count(n)) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        throw Failure("--only " + n + ": no such figure (known: " + list + ")");
      }
    std::erase_if(specs, [&](const fig::SpecFile& s) {
      return std::find(a.only.begin(), a.only.end(), s.name) == a.only.end();
    });
  }
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (!fs::is_directory(a.out)) throw Failure("--out " + a.out + ": cannot create the directory");

  // Figures render in parallel, one per worker; a figure's own serial parts (text, PNG
  // encoding) dominate, so this beats splitting each figure's rasterization across threads.
  // With one figure (or --threads 1) the rasterizer gets all the threads instead. The images
  // do not depend on the thread count; progress lines come out in spec order.
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const std::clock_t cpu_start = std::clock();
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const size_t workers = std::min<size_t>(specs.size(), a.threads > 0 ? static_cast<unsigned>(a.threads) : hw);
  const int raster_threads = workers > 1 ? 1 : a.threads;
  struct Outcome {
    bool finished = false;
    std::optional<fig::FigureInfo> info;
    std::string line;   // progress line or error message
  };
  std::vector<Outcome> outcomes(specs.size());
  std::mutex mutex;
  std::condition_variable ready;
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < specs.size(); i = next++) {
      const fig::SpecFile& s = specs[i];
      const auto t0 = clock::now();
      timespec c0{};
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
      Outcome o;
      try {
        fig::FigureSpec spec = fig::load_spec(s.path);
        fig::check_scaled_canvas(spec, a.scale, "--scale");
        fig::RenderedFigure r = fig::render_figure(spec, {a.scale, raster_threads});
        splinefig::WriteOptions w;
        w.software = std::string("splinefig ") + SPLINEFIG_VERSION;
        w.description = spec.title.empty() ? spec.name : spec.name + ": " + spec.title;
        for (const auto& f : formats) {
          std::string file = s.name + "." + f;
          splinefig::write_image((fs::path(a.out) / file).string(), r.image, w);
          r.info.files.push_back(file);
        }
        const double ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
        timespec c1{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
        const double cpu_ms = (c1.tv_sec - c0.tv_sec) * 1e3 + (c1.tv_nsec - c0.tv_nsec) * 1e-6;
        char buf[160];
        std::snprintf(buf, sizeof buf, "  %-18s %7.1f ms%s", s.name.c_str(), ms,
                      raster_threads == 1 ? (" (CPU " + std::to_string(static_cast<int>(std::lround(cpu_ms))) + " ms)").c_str()
                                          : "");
        o.line = buf;
        o.info = std::move(r.info);
      } catch (const std::exception& e) {
        o.line = std::string("splinefig figures: ") + e.what();
      }
      o.finished = true;
      std::lock_guard<std::mutex> lock(mutex);
      outcomes[i] = std::move(o);
      ready.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (size_t k = 0; k < workers; ++k) pool.emplace_back(work);
  std::vector<fig::FigureInfo> done;
  int failed = 0;
  for (size_t i = 0; i < specs.size(); ++i) {
    std::unique_lock<std::mutex> lock(mutex);
    ready.wait(lock, [&] { return outcomes[i].finished; });
    if (outcomes[i].info) {
      std::printf("%s\n", outcomes[i].line.c_str());
      std::fflush(stdout);
      done.push_back(std::move(*outcomes[i].info));
    } else {
      ++failed;
      std::cerr << outcomes[i].line << "\n";
    }
  }
  for (auto& t : pool) t.join();
  fig::write_text_file((fs::path(a.out) / "index.json").string(), fig::index_json(done));
  fig::write_text_file((fs::path(a.out) / "index.html").string(), fig::gallery_html(done));
  const double total = std::chrono::duration<double>(clock::now() - start).count();
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  std::printf("%zu figure%s in %.2f s (%.2f s CPU) -> %s/index.html\n", done.size(), done.size() == 1 ? "" : "s", total,
              cpu, a.out.c_str());
  if (failed) throw Failure(std::to_string(failed) + " of " + std::to_string(specs.size()) + " figures failed");
  return 0;
}

const splinefig::cli::Registration reg{
    "figures", "Regenerate the built-in figures, index.json and the gallery index.html", [](CLI::App& app) {
      auto a = std::make_shared<FiguresArgs>();
      app.add_option("--out", a->out, "Output directory (default out/figures)");
      app.add_option("--only", a->only, "Only these figures (names as in figures/specs; repeat or comma-separate)")
          ->delimiter(',');
      app.add_option("--format", a->format, "Comma-separated: png, exr (default png)");
      app.add_option("--scale", a->scale, "Output pixels per spec pixel (default 1; 2 for print)");
      app.add_option("--threads", a->threads, "Rendering threads (default: all cores)");
      app.add_option("--specs", a->specs, "Directory of specs to render instead of the built-in ones");
      return splinefig::cli::Runner([a] { return run(*a); });
    }};

}  // namespace
