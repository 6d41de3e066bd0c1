#pragma once
// The image codec: decoding and encoding image files through OpenImageIO, which lives in a
// shared module of its own (image/module/, libsplinefig_image_oiio.so) that codec.cpp opens on
// the first read or write, so that a process which touches no image file never loads
// OpenImageIO and its hundreds of shared libraries.
//
// The table below is everything the module offers; the checks and conversions around it stay
// in read_image.cpp and write_image.cpp. The module is built from the same tree with the same
// compiler, so the table passes standard library types; `abi` guards against a stale module.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace splinefig::detail {

inline constexpr int image_codec_abi = 2;

// What an opened file holds (subimage 0, MIP level 0).
struct CodecHeader {
  int width = 0, height = 0, depth = 1, channels = 0;
  int x = 0, y = 0;
  int alpha_channel = -1;
  bool deep = false;
  bool floating = false;       // float or half values
  int bits = 8;                // bits per stored value
  std::string color_space;     // "oiio:ColorSpace"
  std::vector<std::string> channel_names;
  std::string format_name;     // "png", "openexr", ...
};

enum class CodecType { u8, u16, f32 };

// An image to encode: `data` holds width * height * channels values of `type`.
struct CodecImage {
  int width = 0, height = 0, channels = 0, x = 0, y = 0;
  int alpha_channel = -1;
  std::vector<std::string> channel_names;  // empty: the format's defaults
  CodecType type = CodecType::u8;
  const void* data = nullptr;
  std::vector<std::pair<std::string, std::string>> string_attributes;
  std::vector<std::pair<std::string, int>> int_attributes;
  std::vector<std::pair<std::string, float>> float_attributes;  // e.g. XResolution
};

// Every function reports failure by returning false (or null) with a message in `error`; none
// throws.
struct ImageCodec {
  int abi;
  // Opens `path` for reading; `unassociated` asks for straight alpha. Null on failure.
  void* (*open)(const char* path, bool unassociated, CodecHeader& header, std::string& error);
  // Reads all channels of the opened file as float into `pixels`; `straight` tells whether the
  // values delivered are unassociated.
  bool (*read)(void* input, float* pixels, bool& straight, std::string& error);
  void (*close)(void* input);
  // Encodes `image` into `file` in `format`: OpenImageIO's format name ("openexr", "tiff",
  // "jpeg"; a file name's extension also names one).
  bool (*encode)(const char* format, const CodecImage& image, std::vector<unsigned char>& file, std::string& error);
};

// The module's one exported symbol.
#define SPLINEFIG_IMAGE_CODEC_SYMBOL "splinefig_image_codec_v1"
using ImageCodecEntry = const ImageCodec* (*)();

// The loaded codec. Opens the module on the first call (thread-safe); throws std::runtime_error
// with a one-line message naming the places searched when it cannot be loaded.
const ImageCodec& image_codec();

}  // namespace splinefig::detail
