#pragma once
// PNG encoding with libpng itself (the library OpenImageIO's PNG writer is built on), so that
// writing a PNG, the format of nearly every file splinefig writes, does not load the image I/O
// module and OpenImageIO's hundreds of shared libraries; libpng is loaded with FreeType anyway.
#include "codec.hpp"

#include <string>
#include <vector>

namespace splinefig::detail {

// Encodes `image` (u8 or u16, 1 to 4 channels: grey, grey + alpha, RGB, RGBA, straight alpha,
// sRGB-encoded values) into `file`: an sRGB chunk, tEXt Software and Description (from the
// string attributes "Software" and "ImageDescription"), pHYs from "XResolution"/"YResolution"
// in pixels per inch, oFFs when the data window does not start at 0, and the pixels at zlib
// level "png:compressionLevel" with the row filter "png:filter" (libpng's PNG_FILTER_* bits).
// False with a message in `error` on failure; never throws.
bool encode_png(const CodecImage& image, std::vector<unsigned char>& file, std::string& error) noexcept;

}  // namespace splinefig::detail
