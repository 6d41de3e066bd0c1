// The image codec module (see ../src/codec.hpp): OpenImageIO's readers and writers behind the
// small function table that image/ loads on the first read or write.
#include "../src/codec.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>
#include <string>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace {

using splinefig::detail::CodecHeader;
using splinefig::detail::CodecImage;
using splinefig::detail::CodecType;
using splinefig::detail::ImageCodec;

void fail(std::string& error, const std::string& what) { error = what; }  // the caller words an empty one

void* open_input(const char* path, bool unassociated, CodecHeader& header, std::string& error) noexcept {
  try {
    OIIO::ImageSpec config;
    if (unassociated) config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
      fail(error, OIIO::geterror());
      return nullptr;
    }
    const OIIO::ImageSpec& spec = in->spec();
    header.width = spec.width;
    header.height = spec.height;
    header.depth = spec.depth;
    header.channels = spec.nchannels;
    header.x = spec.x;
    header.y = spec.y;
    header.alpha_channel = spec.alpha_channel;
    header.deep = spec.deep;
    header.floating = spec.format.is_floating_point();
    header.bits = int(spec.format.size()) * 8;
    header.color_space = spec.get_string_attribute("oiio:ColorSpace");
    header.channel_names = spec.channelnames;
    header.format_name = in->format_name();
    return in.release();
  } catch (const std::bad_alloc&) {
    fail(error, "image too large to hold in memory");
  } catch (const std::exception& e) {
    fail(error, e.what());
  }
  return nullptr;
}

bool read_pixels(void* input, float* pixels, bool& straight, std::string& error) noexcept {
  auto* in = static_cast<OIIO::ImageInput*>(input);
  try {
    const bool ok = in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeFloat, pixels);
    const std::string msg = in->has_error() ? in->geterror() : std::string();
    if (!ok || !msg.empty()) {
      fail(error, msg.empty() ? std::string("cannot read pixel data") : msg);
      return false;
    }
    straight = in->spec().get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
    return true;
  } catch (const std::bad_alloc&) {
    fail(error, "image too large to hold in memory");
  } catch (const std::exception& e) {
    fail(error, e.what());
  }
  return false;
}

void close_input(void* input) noexcept {
  std::unique_ptr<OIIO::ImageInput> in(static_cast<OIIO::ImageInput*>(input));
  if (in) in->close();
}

bool encode(const char* format, const CodecImage& im, std::vector<unsigned char>& file, std::string& error) noexcept {
  try {
    const OIIO::TypeDesc type = im.type == CodecType::f32   ? OIIO::TypeDesc::FLOAT
                                : im.type == CodecType::u16 ? OIIO::TypeDesc::UINT16
                                                            : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(im.width, im.height, im.channels, type);
    spec.x = spec.full_x = im.x;
    spec.y = spec.full_y = im.y;
    if (int(im.channel_names.size()) == im.channels) spec.channelnames = im.channel_names;
    spec.alpha_channel = im.alpha_channel;
    for (const auto& [name, value] : im.string_attributes) spec.attribute(name, value);
    for (const auto& [name, value] : im.int_attributes) spec.attribute(name, value);
    for (const auto& [name, value] : im.float_attributes) spec.attribute(name, value);
    auto out = OIIO::ImageOutput::create(format);
    if (!out) {
      fail(error, OIIO::geterror());
      return false;
    }
    // libtiff rewrites its directory in place, which OpenImageIO 2.4's in-memory output does not
    // keep (the file's first directory comes out incomplete): TIFF is encoded into a private
    // temporary file with OpenImageIO's own file output and read back. Every other format is
    // encoded in memory.
    std::string scratch;
    OIIO::Filesystem::IOVecOutput memory(file);
    if (std::string(out->format_name()) == "tiff") {
      const char* dir = std::getenv("TMPDIR");
      std::string name = std::string(dir && *dir ? dir : "/tmp") + "/splinefig-encode-XXXXXX.tif";
      const int fd = ::mkstemps(name.data(), 4);
      if (fd < 0) {
        fail(error, "cannot create a temporary file to encode TIFF in " + name + ": " + std::strerror(errno));
        return false;
      }
      ::close(fd);
      scratch = name;
    } else if (!out->set_ioproxy(&memory)) {
      fail(error, "cannot encode this format in memory");
      return false;
    }
    struct Remove {
      const std::string& name;
      ~Remove() {
        if (!name.empty()) ::unlink(name.c_str());
      }
    } remove_scratch{scratch};
    // In memory the name only labels the output; TIFF goes to its scratch file.
    if (!out->open(scratch.empty() ? std::string("image.") + format : scratch, spec)) {
      fail(error, out->geterror());
      return false;
    }
    const bool ok = out->write_image(type, im.data);
    const bool closed = out->close();
    std::string message = out->geterror();
    // OpenImageIO 2.4's TIFF writer reports an Exif directory it did not add after writing the
    // image completely; the file is whole (tests/image/tiff.cpp decodes it), so that report alone
    // is not a failure.
    if (message == "failed TIFFWriteCustomDirectory() of the Exif data") message.clear();
    if (!ok || !closed || !message.empty()) {
      // The TIFF's scratch file stopped at the file-size limit (ulimit -f) or on a full disk:
      // said as a failed write of the output is said, not in libtiff's words about scanlines.
      struct stat st {};
      struct statvfs fs {};
      rlimit size_limit{};
      if (!scratch.empty() && ::stat(scratch.c_str(), &st) == 0) {
        if (::getrlimit(RLIMIT_FSIZE, &size_limit) == 0 && size_limit.rlim_cur != RLIM_INFINITY &&
            rlim_t(st.st_size) >= size_limit.rlim_cur)
          message = std::string("write failed (") + std::strerror(EFBIG) + ")";
        else if (::statvfs(scratch.c_str(), &fs) == 0 && fs.f_bavail == 0)
          message = "cannot encode the TIFF in " + scratch + " (" + std::strerror(ENOSPC) + ")";
      }
      fail(error, message);
      return false;
    }
    if (!scratch.empty()) {
      std::ifstream in(scratch, std::ios::binary);
      file.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      if (!in.good() && !in.eof()) {
        fail(error, "cannot read back the encoded TIFF from " + scratch);
        return false;
      }
    }
    return true;
  } catch (const std::bad_alloc&) {
    fail(error, "out of memory");
  } catch (const std::exception& e) {
    fail(error, e.what());
  }
  return false;
}

constexpr ImageCodec codec{splinefig::detail::image_codec_abi, open_input, read_pixels, close_input, encode};

// Under an address-space or data limit (ulimit -v, ulimit -d), OpenEXR compresses and
// decompresses on the calling thread: in its worker threads an allocation that the limit
// refuses ended in SIGSEGV (copyFromFrameBuffer on a buffer that was never allocated) where
// on the calling thread it is an error OpenImageIO reports. The bytes written are the same.
void single_threaded_under_a_limit() {
  rlimit as{}, data{};
  const bool limited = (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) ||
                       (getrlimit(RLIMIT_DATA, &data) == 0 && data.rlim_cur != RLIM_INFINITY);
  if (limited) {
    OIIO::attribute("exr_threads", -1);  // -1: OpenEXR without worker threads
    OIIO::attribute("threads", 1);
  }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const ImageCodec* splinefig_image_codec_v1() {
  static const bool once = (single_threaded_under_a_limit(), true);
  (void)once;
  return &codec;
}
