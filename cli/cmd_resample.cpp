// `splinefig resample`: resize an image with a spline basis function as the reconstruction
// filter (docs/cli.md, docs/resample.md).
#include "command.hpp"
#include "csv.hpp"

#include <splinefig/image/io.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/kernel.hpp>

#include <cmath>
#include <filesystem>

namespace {

using namespace splinefig;
using splinefig::cli::Failure;

struct Options {
  std::string in, out, size, scale, filter, edge = "clamp";
  bool interpolating = false;
  int threads = 0;
};

constexpr long kMaxSide = 65536;
constexpr long long kMaxSamples = 1LL << 30;

// "WxH" with whole numbers in 1..65536.
std::pair<int, int> parse_size(const std::string& text) {
  const auto x = text.find('x');
  if (x == std::string::npos) throw Failure("--size: '" + text + "' is not WxH (e.g. 640x480)");
  const auto w = cli::parse_integer(text.substr(0, x), "--size width", 1, kMaxSide);
  const auto h = cli::parse_integer(text.substr(x + 1), "--size height", 1, kMaxSide);
  return {static_cast<int>(w), static_cast<int>(h)};
}

int scaled(int src, double s, const char* axis, const std::string& text) {
  const double d = std::round(s * src);
  if (d < 1)
    throw Failure("--scale " + text + ": the " + axis + " of " + std::to_string(src) + " pixels becomes 0");
  if (d > kMaxSide)
    throw Failure("--scale " + text + ": the " + axis + " of " + std::to_string(src) +
                  " pixels becomes more than 65536");
  return static_cast<int>(d);
}

int run(const Options& o) {
  const Kernel filter = cli::parse_spec_flag("--filter", o.filter, [](const std::string& s) { return parse_kernel(s); });
  const auto edge = parse_edge(o.edge);
  if (!edge) throw Failure("--edge: '" + o.edge + "' is not one of clamp, mirror, wrap, black");
  const int threads = cli::check_threads(o.threads);
  if (o.size.empty() == o.scale.empty()) throw Failure("give exactly one of --size WxH and --scale S");
  std::pair<int, int> size{0, 0};
  std::vector<double> scale;
  if (!o.size.empty()) {
    size = parse_size(o.size);
  } else {
    scale = cli::parse_vector(o.scale, "--scale");
    if (scale.size() == 1) scale.push_back(scale[0]);
    if (scale.size() != 2) throw Failure("--scale: '" + o.scale + "' is not S or SX,SY");
    for (double s : scale)
      if (!(s > 0)) throw Failure("--scale: '" + o.scale + "' must be positive");
  }
  {
    std::string ext = std::filesystem::path(o.out).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".png" && ext != ".exr")
      throw Failure("-o " + o.out + ": unsupported output format '" + ext + "' (use .png or .exr)");
  }

  if (same_file(o.out, o.in)) throw Failure("-o " + o.out + ": it is the input " + o.in + " (write to another file)");
  Image src;
  FileFormat format;
  try {
    src = read_image(o.in, ReadMode::linear, &format);
  } catch (const UnreadableImage& e) {
    throw Failure(e.what());
  }
  if (!scale.empty())
    size = {scaled(src.width, scale[0], "width", o.scale), scaled(src.height, scale[1], "height", o.scale)};
  if (static_cast<long long>(size.first) * size.second * src.channels > kMaxSamples)
    throw Failure("output " + std::to_string(size.first) + "x" + std::to_string(size.second) + "x" +
                  std::to_string(src.channels) + " is over the limit of 2^30 samples");

  Image out;
  try {
    ResampleOptions opt;
    opt.edge = *edge;
    opt.interpolating = o.interpolating;
    opt.threads = threads;
    out = resample(src, size.first, size.second, filter, opt);
    WriteOptions w;
    w.bits = format.name == "png" && format.bits == 16 ? 16 : 8;
    write_image(o.out, out, w);
  } catch (const UnwritableImage& e) {
    throw Failure(e.what());
  } catch (const std::invalid_argument& e) {
    throw Failure(e.what());
  }
  return 0;
}

const splinefig::cli::Registration reg{
    "resample", "Resize an image with a spline basis function as the reconstruction filter",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      app.add_option("IN", o->in, "Input image (PNG or EXR)")->required();
      app.add_option("-o,--output", o->out, "Output image (.png or .exr)")->required();
      app.add_option("--size", o->size, "Output size WxH");
      app.add_option("--scale", o->scale, "Scale factor S or SX,SY (output size rounded)");
      app.add_option("--filter", o->filter,
                     std::string("Basis spec (") + splinefig::cli::basis_specs + ") or box, tent, lanczos3")
          ->required();
      app.add_option("--edge", o->edge, "Samples outside the image: clamp (default), mirror, wrap, black");
      app.add_flag("--interpolating", o->interpolating,
                   "Prefilter so that an approximating spline (bspline, tensioned-bspline, beta) "
                   "interpolates the samples");
      app.add_option("--threads", o->threads, "Worker threads (default: all cores; at most 256)");
      app.footer(
          "Output pixel i has its centre i+0.5 at source position x = (i+0.5) S/D; the filter is "
          "widened by f = max(1, S/D); value = sum_j k((x-(j+0.5))/f) p[j] / sum_j k((x-(j+0.5))/f). "
          "8-bit PNG is decoded from sRGB to linear light, filtered, and encoded again.");
      return splinefig::cli::Runner([o] { return run(*o); });
    }};

}  // namespace
