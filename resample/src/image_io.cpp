// PNG and EXR in and out through OpenImageIO (conventions in image_io.hpp).
#include <splinefig/resample/image_io.hpp>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace splinefig {
namespace {

namespace fs = std::filesystem;

std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

constexpr long kMaxSide = 65536;
constexpr long long kMaxSamples = 1LL << 30;

}  // namespace

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double linear_to_srgb(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

LoadedImage read_image(const std::string& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // PNG alpha as stored (straight)
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    const std::string err = one_line(OIIO::geterror());
    throw ImageIOError(path + ": cannot read image" + (err.empty() ? "" : " (" + err + ")"));
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || spec.width > kMaxSide ||
      spec.height > kMaxSide ||
      static_cast<long long>(spec.width) * spec.height * spec.nchannels > kMaxSamples)
    throw ImageIOError(path + ": image size " + std::to_string(spec.width) + "x" +
                       std::to_string(spec.height) + "x" + std::to_string(spec.nchannels) +
                       " is outside the limits (1..65536 per side, at most 2^30 samples)");
  LoadedImage out;
  out.image = Image(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.image.pixels.data()))
    throw ImageIOError(path + ": cannot read its pixels (" + one_line(in->geterror()) + ")");
  ImageFormat& fmt = out.format;
  fmt.channel_names = spec.channelnames;
  fmt.alpha_channel = spec.alpha_channel;
  const std::string name = in->format_name();
  in->close();
  if (name == "png") {
    fmt.srgb = true;
    fmt.bits = spec.format.basetype == OIIO::TypeDesc::UINT16 ? 16 : 8;
    std::array<float, 256> lut{};
    for (int i = 0; i < 256; ++i) lut[static_cast<size_t>(i)] = static_cast<float>(srgb_to_linear(i / 255.0));
    const int C = spec.nchannels, a = fmt.alpha_channel;
    for (size_t p = 0; p < out.image.pixels.size(); p += static_cast<size_t>(C)) {
      float* px = out.image.pixels.data() + p;
      const float alpha = a >= 0 ? px[a] : 1.0f;
      for (int c = 0; c < C; ++c) {
        if (c == a) continue;
        const double v = px[c];
        const float lin = fmt.bits == 8 ? lut[static_cast<size_t>(std::lround(v * 255))]
                                        : static_cast<float>(srgb_to_linear(v));
        px[c] = lin * alpha;
      }
    }
  }
  return out;
}

void write_image(const std::string& path, const Image& img, const ImageFormat& like) {
  const std::string ext = lower_extension(path);
  const bool png = ext == ".png";
  if (!png && ext != ".exr")
    throw ImageIOError(path + ": unsupported output format '" + ext + "' (use .png or .exr)");
  const int C = img.channels;
  if (png && C > 4)
    throw ImageIOError(path + ": PNG holds 1 to 4 channels; this image has " + std::to_string(C));
  const int bits = png ? (like.bits == 16 ? 16 : 8) : 32;
  OIIO::ImageSpec spec(img.width, img.height, C,
                       bits == 8 ? OIIO::TypeDesc::UINT8 : bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::FLOAT);
  if (static_cast<int>(like.channel_names.size()) == C) spec.channelnames = like.channel_names;
  spec.alpha_channel = like.alpha_channel < C ? like.alpha_channel : -1;

  std::vector<float> data;
  const float* pixels = img.pixels.data();
  if (png) {
    // Straight alpha, sRGB-encoded, clamped to [0, 1]; OpenImageIO rounds to the integer type.
    data.assign(img.pixels.begin(), img.pixels.end());
    const int a = spec.alpha_channel;
    for (size_t p = 0; p < data.size(); p += static_cast<size_t>(C)) {
      float* px = data.data() + p;
      const double alpha = a >= 0 ? std::clamp<double>(px[a], 0, 1) : 1.0;
      for (int c = 0; c < C; ++c) {
        if (c == a) continue;
        double v = alpha > 0 ? px[c] / alpha : 0.0;
        if (!(v > 0)) v = 0;  // also NaN
        px[c] = static_cast<float>(linear_to_srgb(std::min(v, 1.0)));
      }
      if (a >= 0) px[a] = static_cast<float>(alpha);
    }
    pixels = data.data();
    spec.attribute("oiio:UnassociatedAlpha", 1);
  }

  static std::atomic<int> counter{0};
  const fs::path final_path(path);
  const fs::path dir = final_path.has_parent_path() ? final_path.parent_path() : fs::path(".");
  std::string tmp_name = ".";
  tmp_name += final_path.filename().string();
  tmp_name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ext;
  const fs::path tmp = dir / tmp_name;
  auto fail = [&](const std::string& why) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw ImageIOError(path + ": cannot write image (" + one_line(why) + ")");
  };
  auto out = OIIO::ImageOutput::create(path);
  if (!out) fail(OIIO::geterror());
  if (!out->open(tmp.string(), spec)) fail(out->geterror());
  if (!out->write_image(OIIO::TypeDesc::FLOAT, pixels)) {
    const std::string err = out->geterror();
    out->close();
    fail(err);
  }
  if (!out->close()) fail(out->geterror());
  std::error_code ec;
  fs::rename(tmp, final_path, ec);
  if (ec) fail(ec.message());
}

}  // namespace splinefig
