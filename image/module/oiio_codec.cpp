// The image codec module (see ../src/codec.hpp): OpenImageIO's readers and writers behind the
// small function table that image/ loads on the first read or write.
#include "../src/codec.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <exception>
#include <memory>
#include <new>

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

bool encode(const char* path, const CodecImage& im, std::vector<unsigned char>& file, std::string& error) noexcept {
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
    OIIO::Filesystem::IOVecOutput memory(file);
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
      fail(error, OIIO::geterror());
      return false;
    }
    if (!out->set_ioproxy(&memory)) {
      fail(error, "cannot encode this format in memory");
      return false;
    }
    if (!out->open(path, spec)) {
      fail(error, out->geterror());
      return false;
    }
    const bool ok = out->write_image(type, im.data);
    const bool closed = out->close();
    if (!ok || !closed || out->has_error()) {
      fail(error, out->geterror());
      return false;
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

}  // namespace

extern "C" __attribute__((visibility("default"))) const ImageCodec* splinefig_image_codec_v1() { return &codec; }
