// Standard output written whole (see stdio.hpp).
#include "stdio.hpp"

namespace splinefig::cli {

void write_stdout(std::string_view text) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
    throw Failure(std::string("cannot write to standard output (") + std::strerror(errno ? errno : EIO) + ")", ErrorKind::unwritable);
}


}  // namespace splinefig::cli
