// Image files through OpenImageIO. PNG: 8-bit sRGB, straight alpha. EXR: float32 linear RGBA,
// premultiplied (the OpenEXR convention). Written to a temporary file in the target's directory
// and renamed over the target only when complete; an interrupt while writing removes the
// temporary file, so no reader ever sees a partial image.
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/version.hpp>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace splinefig::render {
namespace {

std::string lower_ext(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

// The temporary file being written, removed by the signal handler on SIGINT/SIGTERM.
char g_temp_path[4096];
std::atomic<bool> g_temp_active{false};
extern "C" void remove_temp_and_reraise(int sig) {
  if (g_temp_active.load()) ::unlink(g_temp_path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

struct TempGuard {
  void (*old_int)(int);
  void (*old_term)(int);
  std::string path;
  explicit TempGuard(std::string p) : path(std::move(p)) {
    std::snprintf(g_temp_path, sizeof g_temp_path, "%s", path.c_str());
    g_temp_active = true;
    old_int = std::signal(SIGINT, remove_temp_and_reraise);
    old_term = std::signal(SIGTERM, remove_temp_and_reraise);
  }
  ~TempGuard() {
    std::signal(SIGINT, old_int);
    std::signal(SIGTERM, old_term);
    g_temp_active = false;
    std::error_code ec;
    std::filesystem::remove(path, ec);  // no-op after a successful rename
  }
};

}  // namespace

void write_image(const Image& image, const std::string& path, const WriteOptions& options) {
  const std::string ext = lower_ext(path);
  const bool png = ext == ".png";
  if (!png && ext != ".exr") throw std::runtime_error(path + ": unsupported image extension '" + ext + "' (use .png or .exr)");
  if (image.width < 1 || image.height < 1 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw std::runtime_error(path + ": image has no pixels or a wrong buffer size");

  std::filesystem::path target(path);
  std::filesystem::path dir = target.parent_path();
  std::string temp = (dir / ("." + target.stem().string() + ".tmp" + std::to_string(::getpid()) + ext)).string();

  OIIO::ImageSpec spec(image.width, image.height, 4, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.attribute("Software", options.software.empty() ? std::string("splinefig ") + SPLINEFIG_VERSION : options.software);
  if (!options.description.empty()) spec.attribute("ImageDescription", options.description);
  if (png) {
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("oiio:UnassociatedAlpha", 1);  // our bytes are already straight alpha
  } else {
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("compression", "zip");
  }

  std::vector<unsigned char> bytes;
  const void* data = image.rgba.data();
  if (png) {
    bytes.resize(image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
      const float a = std::clamp(image.rgba[i + 3], 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c) {
        float v = a > 0 ? image.rgba[i + c] / a : 0.0f;  // straight alpha
        v = linear_to_srgb(std::clamp(v, 0.0f, 1.0f));
        bytes[i + c] = static_cast<unsigned char>(std::lround(v * 255.0f));
      }
      bytes[i + 3] = static_cast<unsigned char>(std::lround(a * 255.0f));
    }
    data = bytes.data();
  }

  TempGuard guard(temp);
  auto out = OIIO::ImageOutput::create(temp);
  if (!out) throw std::runtime_error(path + ": cannot create an image writer: " + OIIO::geterror());
  if (!out->open(temp, spec)) throw std::runtime_error(path + ": cannot open for writing: " + out->geterror());
  if (!out->write_image(png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT, data)) {
    std::string err = out->geterror();
    out->close();
    throw std::runtime_error(path + ": write failed: " + err);
  }
  if (!out->close()) throw std::runtime_error(path + ": write failed: " + out->geterror());
  out.reset();
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) throw std::runtime_error(path + ": cannot rename the finished file into place: " + ec.message());
}

}  // namespace splinefig::render
