// A spec read and checked whole (spec.hpp): the loader's FigureSpec (load/), then its caption
// fields worked out once (layout/caption_text.hpp), so that a field its element cannot give is
// an error of the spec, found when it is loaded.
#include <splinefig/figures/spec.hpp>

#include "layout/caption_text.hpp"
#include "load/spec_parse.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace splinefig::figures {

FigureSpec parse_spec(std::string_view text, const std::string& name, const std::string& base_dir) {
  FigureSpec spec = detail::read_spec(text, name, base_dir);
  detail::caption_text(spec);  // every caption field names an element it applies to
  return spec;
}

// The rules for a spec read by name, the same for the command line, `figures` and Python: a
// regular file (a directory is no empty spec; a FIFO or /dev/zero would block or never end),
// readable, at most kMaxSpecBytes, read no further than that even if it grows meanwhile.
FigureSpec load_spec(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.find('\0') != std::string::npos) throw SpecFileError("a spec path holding a NUL character");
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) {
    const int err = ec ? ec.value() : ENOENT;
    throw SpecFileError(path + ": cannot read the spec file (" + std::strerror(err) + ")");
  }
  if (fs::is_directory(st)) throw SpecFileError(path + ": is a directory, not a file");
  if (!fs::is_regular_file(st)) throw SpecFileError(path + ": not a regular file (a FIFO, socket or device)");
  if (const auto bytes = fs::file_size(path, ec); !ec && bytes > kMaxSpecBytes)
    throw SpecFileError(path + ": the spec file has " + std::to_string(bytes) + " bytes (limit 64 MiB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SpecFileError(path + ": cannot read the spec file (" + std::strerror(errno ? errno : EIO) + ")");
  std::string text;
  std::array<char, 1 << 16> buf;
  while (in.read(buf.data(), buf.size()) || in.gcount() > 0) {
    text.append(buf.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSpecBytes) throw SpecFileError(path + ": the spec file has more than 64 MiB (limit 64 MiB)");
  }
  if (in.bad()) throw SpecFileError(path + ": cannot read the spec file (a read error)");
  std::string dir = fs::path(path).parent_path().string();
  return parse_spec(text, path, dir.empty() ? "." : dir);
}

}  // namespace splinefig::figures
