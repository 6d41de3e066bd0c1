// `splinefig resample`: resize an image with a spline basis function as the reconstruction
// filter (docs/cli.md, docs/resample.md).
#include "command.hpp"
#include "number_flags.hpp"
#include "stdio.hpp"

#include <splinefig/image/io.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

using namespace splinefig;
using splinefig::cli::Failure;

struct Options {
  std::string in, out, size, scale, filter, edge = "clamp", bits, format;
  bool interpolating = false, verbose = false;
  int threads = 0;
};

constexpr long kMaxSide = 65536;
constexpr long long kMaxSamples = 1LL << 30;

// "WxH" with whole numbers in 1..65536; "Wx" or "xH" leaves the other side 0, to be set from
// the source's aspect ratio.
std::pair<int, int> parse_size(const std::string& text) {
  const auto x = text.find('x');
  if (x == std::string::npos || text == "x")
    throw Failure("--size: '" + cli::printable(text) + "' is not WxH, Wx or xH (e.g. 640x480, 640x, x480)");
  const std::string w = text.substr(0, x), h = text.substr(x + 1);
  return {w.empty() ? 0 : static_cast<int>(cli::parse_integer(w, "--size width", 1, kMaxSide)),
          h.empty() ? 0 : static_cast<int>(cli::parse_integer(h, "--size height", 1, kMaxSide))};
}

// The side left out of --size Wx or xH, from the source's aspect ratio (rounded, at least 1).
int keep_aspect(int given, int src_given, int src_other, const char* axis) {
  const double d = std::max(1.0, std::round(static_cast<double>(given) * src_other / src_given));
  if (d > kMaxSide) throw Failure(std::string("--size: the ") + axis + " for the source's aspect ratio is more than 65536");
  return static_cast<int>(d);
}

// Progress lines for work on at least 2^22 samples (cli::ProgressLine).
struct Progress : cli::ProgressLine {
  explicit Progress(long long samples) : cli::ProgressLine("resample", samples >= (1LL << 22)) {}
};

// --bits for the output's format: png 8 or 16 (default: 16 for a 16-bit PNG source, else 8);
// jpg 8; exr float; tif 8, 16 or float (default: float for a float or EXR source, 16 for a 16-bit
// source, else 8). 32 stands for float.
int output_bits(const std::string& bits, const std::string& ext, const FileFormat& source) {
  const std::string b = bits.empty() ? "" : bits;
  if (ext == ".exr") {
    if (!b.empty() && b != "float") throw Failure("--bits " + b + ": .exr is written as float");
    return 32;
  }
  if (ext == ".jpg" || ext == ".jpeg") {
    if (!b.empty() && b != "8") throw Failure("--bits " + b + ": JPEG holds 8 bits");
    return 8;
  }
  const bool tiff = ext == ".tif" || ext == ".tiff";
  if (b.empty()) {
    if (tiff) return source.name == "openexr" || source.bits == 32 ? 32 : source.bits == 16 ? 16 : 8;
    return source.name == "png" && source.bits == 16 ? 16 : 8;
  }
  if (b == "8") return 8;
  if (b == "16") return 16;
  if (tiff) return 32;  // b == "float"
  throw Failure("--bits " + cli::printable(b) + ": PNG holds 8 or 16 bits (float needs .exr or .tif)");
}

// For a format without alpha (JPEG): the image composited over white, its alpha dropped. The
// values are linear and premultiplied, so over white a colour becomes c + (1 - alpha).
Image over_white(const Image& im) {
  if (im.alpha_channel < 0) return im;
  const int a = im.alpha_channel, C = im.channels;
  Image out = Image::zeros(im.width, im.height, C - 1, im.encoding);
  std::size_t o = 0;
  for (std::size_t p = 0; p < im.pixels.size(); p += static_cast<std::size_t>(C)) {
    const float alpha = std::clamp(im.pixels[p + static_cast<std::size_t>(a)], 0.0f, 1.0f);
    for (int c = 0; c < C; ++c)
      if (c != a) out.pixels[o++] = im.pixels[p + static_cast<std::size_t>(c)] + (1.0f - alpha);
  }
  return out;
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
  const bool to_stdout = cli::is_stdio(o.out), from_stdin = cli::is_stdio(o.in);
  std::string ext = to_stdout ? "" : std::filesystem::path(o.out).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!o.format.empty()) {
    std::string f = "." + o.format;
    for (auto& c : f) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (f != ".png" && f != ".exr" && f != ".tif" && f != ".tiff" && f != ".jpg" && f != ".jpeg")
      throw Failure("--format " + cli::printable(o.format) + ": not one of png, jpg, tif, exr");
    const auto kind = [](const std::string& e) { return e == ".jpeg" ? ".jpg" : e == ".tiff" ? ".tif" : e; };
    if (!ext.empty() && kind(ext) != kind(f))
      throw Failure("--format " + o.format + ": -o " + o.out + " names another format (" + ext + ")");
    ext = f;
  }
  if (ext.empty() && to_stdout) ext = ".png";
  const bool jpeg = ext == ".jpg" || ext == ".jpeg";
  if (ext != ".png" && ext != ".exr" && ext != ".tif" && ext != ".tiff" && !jpeg)
    throw Failure("-o " + o.out + ": unsupported output format '" + ext + "' (use .png, .jpg, .tif or .exr)");
  if (!o.bits.empty() && o.bits != "8" && o.bits != "16" && o.bits != "float")
    throw Failure("--bits: '" + cli::printable(o.bits) + "' is not 8, 16 or float");

  if (!to_stdout && !from_stdin && same_file(o.out, o.in)) throw Failure("-o " + o.out + ": it is the input " + o.in + " (write to another file)");
  Image src;
  FileFormat format;
  cli::Scratch scratch;
  const std::string in = from_stdin ? cli::stdin_image(scratch) : o.in;
  try {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(in, ec);
    const Progress reading(ec ? 0 : static_cast<long long>(bytes) * 4);  // compressed: a fourth of the samples
    reading.say("reading " + o.in);
    src = read_image(in, ReadMode::linear, &format);
  } catch (const UnreadableImage& e) {
    throw Failure(from_stdin ? cli::said_as(e.what(), in, "stdin") : e.what(), e);
  }
  const int bits = output_bits(o.bits, ext, format);
  if (size.first == 0) size.first = keep_aspect(size.second, src.height, src.width, "width");
  if (size.second == 0) size.second = keep_aspect(size.first, src.width, src.height, "height");
  if (!scale.empty())
    size = {scaled(src.width, scale[0], "width", o.scale), scaled(src.height, scale[1], "height", o.scale)};
  if (static_cast<long long>(size.first) * size.second * src.channels > kMaxSamples)
    throw Failure("output " + std::to_string(size.first) + "x" + std::to_string(size.second) + "x" +
                  std::to_string(src.channels) + " is over the limit of 2^30 samples");

  Image out;
  try {
    const Progress progress(static_cast<long long>(size.first) * size.second * src.channels +
                            static_cast<long long>(src.width) * src.height * src.channels);
    ResampleOptions opt;
    opt.edge = *edge;
    opt.interpolating = o.interpolating;
    opt.threads = threads;
    progress.say("filtering " + std::to_string(src.width) + "x" + std::to_string(src.height) + " to " +
                 std::to_string(size.first) + "x" + std::to_string(size.second));
    out = resample(src, size.first, size.second, filter, opt);
    progress.say("writing " + o.out);
    WriteOptions w;
    w.bits = bits;
    const std::string path = to_stdout ? scratch.file("stdout" + ext) : o.out;
    try {
      write_image(path, jpeg ? over_white(out) : out, *image_format_of("x" + ext), w);
    } catch (const UnwritableImage& e) {
      throw Failure(to_stdout ? cli::said_as(e.what(), path, "stdout") : e.what(), e);
    }
    if (to_stdout) cli::file_to_stdout(scratch, path);
  } catch (const std::invalid_argument& e) {
    throw Failure(e.what());
  }
  if (o.verbose)
    std::fprintf(stderr, "splinefig resample: %s %dx%d -> %s %dx%d (%s, %s, --filter %s, --edge %s%s)\n",
                 cli::printable(o.in).c_str(), src.width, src.height, cli::printable(o.out).c_str(), size.first,
                 size.second, std::to_string(src.channels).append(src.channels == 1 ? " channel" : " channels").c_str(),
                 bits == 32 ? "float" : (std::to_string(bits) + "-bit").c_str(), cli::printable(o.filter).c_str(),
                 o.edge.c_str(), o.interpolating ? ", interpolating" : "");
  return 0;
}

const splinefig::cli::Registration reg{
    "resample", "Resize an image with a spline basis function as the reconstruction filter",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      app.add_option("IN", o->in, "Input image (PNG, EXR, TIFF or JPEG); - reads it from stdin")->type_name("PATH")->required();
      app.add_option("-o,--output", o->out, "Output image: .png, .jpg (alpha composited over white), .tif or .exr; - writes to stdout (--format, default png)")->type_name("PATH")->required();
      splinefig::cli::choices(
          app.add_option("--format", o->format, "Output format png, jpg, tif or exr, for -o - or a name without one of those extensions")
              ->type_name("NAME"),
          {"png", "jpg", "tif", "exr"});
      app.add_option("--size", o->size, "Output size WxH; Wx or xH keeps the aspect ratio")->type_name("WxH");
      app.add_option("--scale", o->scale, "Scale factor S or SX,SY (output size rounded)")->type_name("FLOAT[,FLOAT]");
      app.add_option("--filter", o->filter,
                     std::string("Basis spec (") + splinefig::cli::basis_specs + ") or box, tent, lanczos3")
          ->type_name("SPEC")
          ->required();
      splinefig::cli::choices(app.add_option("--edge", o->edge, "Samples outside the image: clamp, mirror, wrap, black")
                                  ->type_name("NAME")
                                  ->capture_default_str(),
                              {"clamp", "mirror", "wrap", "black"});
      splinefig::cli::choices(app.add_option("--bits", o->bits,
                                             "Output bits: .png 8 or 16 (when not given: 16 for a 16-bit PNG input, else 8), .jpg 8, "
                                             ".exr float, .tif 8, 16 or float (when not given: as the input's)")
                                  ->type_name("8|16|float"),
                              {"8", "16", "float"});
      app.add_flag("--interpolating", o->interpolating,
                   "Prefilter so that an approximating spline (bspline, tensioned-bspline, beta) "
                   "interpolates the samples");
      app.add_option("--threads", o->threads, "Worker threads (0: all cores; at most 256)")
          ->type_name("INT")
          ->capture_default_str();
      app.add_flag("-v,--verbose", o->verbose, "Print one line of what was done on stderr");
      app.footer(
          "Output pixel i has its centre i+0.5 at source position x = (i+0.5) S/D; the filter is "
          "widened by f = max(1, S/D); value = sum_j k((x-(j+0.5))/f) p[j] / sum_j k((x-(j+0.5))/f). "
          "8-bit PNG is decoded from sRGB to linear light, filtered, and encoded again. On a terminal, "
          "large images show a progress line on stderr.\n\n"
          "Example: splinefig resample photo.png -o half.png --size 300x --filter catmull-rom -v");
      return splinefig::cli::Runner([o] { return run(*o); });
    }};

}  // namespace
