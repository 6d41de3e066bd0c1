#pragma once
// `-` for standard input and output where a command reads or writes a file (docs/cli.md):
// the bytes of stdin are held in a private scratch directory and read from there as the file
// would be; an output for stdout is written whole into the scratch directory first and only
// then copied to stdout, so that a failure leaves stdout empty (as far as a pipe allows).
#include "command.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

namespace splinefig::cli {

inline bool is_stdio(const std::string& path) { return path == "-"; }

// Writes text to stdout and flushes; throws Failure if the write fails (disk full, closed pipe).
// Commands build their output in memory and write it at once, so a failed command prints
// nothing on stdout.
void write_stdout(std::string_view text);

// A directory of its own under TMPDIR (or /tmp), removed with everything in it when it goes.
// A failure to hold stdin or stdout in it is an unwritable error (exit 2, diff's 4).
class Scratch {
 public:
  Scratch() = default;
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  ~Scratch() { remove(); }
  // Removes the directory now (before a write to stdout that SIGPIPE may end).
  void remove() {
    std::error_code ec;
    if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
    dir_.clear();
  }
  // The path of `name` in the directory, made at the first call.
  std::string file(const std::string& name) {
    if (dir_.empty()) {
      const char* t = std::getenv("TMPDIR");
      std::string templ = std::string(t && *t ? t : "/tmp") + "/splinefig-XXXXXX";
      if (!::mkdtemp(templ.data()))
        throw Failure("cannot make a scratch directory in " + templ.substr(0, templ.size() - 17) + " (" +
                          std::strerror(errno) + ")", ErrorKind::unwritable);
      dir_ = templ;
    }
    return (dir_ / name).string();
  }

 private:
  std::filesystem::path dir_;
};

// All of stdin as bytes, at most `limit` of them (a larger input is refused, so that /dev/zero
// cannot fill the memory); `what` names the input in errors ("the spec", "the image"), which are
// unreadable errors (exit 2, diff's 4).
inline std::string read_stdin_bytes(const std::string& what, std::size_t limit) {
  std::string bytes;
  char buf[1 << 16];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, stdin)) > 0) {
    bytes.append(buf, n);
    if (bytes.size() > limit)
      throw Failure("-: " + what + " on stdin is over " + std::to_string(limit >> 20) + " MiB", ErrorKind::unreadable);
  }
  if (std::ferror(stdin)) throw Failure(std::string("-: cannot read stdin (") + std::strerror(errno ? errno : EIO) + ")", ErrorKind::unreadable);
  return bytes;
}

// The extension of the image format whose signature `bytes` start with, or "" for none known.
inline const char* image_extension_of(std::string_view b) {
  if (b.starts_with("\x89PNG\r\n\x1a\n")) return ".png";
  if (b.starts_with("v/1\x01")) return ".exr";
  if (b.starts_with("\xff\xd8\xff")) return ".jpg";
  if (b.starts_with(std::string_view("II*\0", 4)) || b.starts_with(std::string_view("MM\0*", 4))) return ".tif";
  return "";
}

// The image on stdin saved as a file of `scratch` named for its format, for read_image; stdin
// that holds no image is an unreadable error.
inline std::string stdin_image(Scratch& scratch) {
  const std::string bytes = read_stdin_bytes("the image", std::size_t(1) << 31);
  if (bytes.empty()) throw Failure("-: stdin is empty (an image was expected)", ErrorKind::unreadable);
  const char* ext = image_extension_of(bytes);
  if (!*ext) throw Failure("-: stdin is not a PNG, EXR, JPEG or TIFF image", ErrorKind::unreadable);
  const std::string path = scratch.file(std::string("stdin") + ext);
  std::ofstream f(path, std::ios::binary);
  if (!f.write(bytes.data(), static_cast<std::streamsize>(bytes.size())) || !f.flush())
    throw Failure("cannot save stdin in " + path + " (" + std::strerror(errno ? errno : EIO) + ")", ErrorKind::unwritable);
  return path;
}

// `text` with every occurrence of the scratch path `from` said as `to` ("stdin", "stdout").
inline std::string said_as(std::string text, const std::string& from, const std::string& to) {
  if (from.empty()) return text;
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) text.replace(at, from.size(), to);
  return text;
}

// Copies the finished file `path` of `scratch` to stdout, the scratch directory removed first
// (write_stdout: a failed write is one line).
inline void file_to_stdout(Scratch& scratch, const std::string& path) {
  std::string bytes;
  {
    std::ifstream f(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    if (f.bad() || !f.is_open()) throw Failure("cannot read back " + path, ErrorKind::unwritable);
  }
  scratch.remove();
  write_stdout(bytes);
}

}  // namespace splinefig::cli
