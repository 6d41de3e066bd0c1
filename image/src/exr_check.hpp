#pragma once
// Internal: the attribute structure of an OpenEXR file's header(s) walked before the file is
// opened for decoding. OpenEXR allocates an attribute's declared size before reading it, so a
// few hundred bytes declaring a 2 GB attribute would exhaust memory: every declared size must
// fit in the file. Throws UnreadableImage.
#include <string>

namespace splinefig {

bool has_exr_signature(const std::string& path);
void check_exr_header(const std::string& path);

}  // namespace splinefig
