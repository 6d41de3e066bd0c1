#pragma once
// Internal: the PNG header's declared size checked against the image limits (io.hpp) from its
// first 29 bytes, before anything is inflated. Throws UnreadableImage.
#include <string>

namespace splinefig {

void check_png_header(const std::string& path);

}  // namespace splinefig
