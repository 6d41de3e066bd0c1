#pragma once
// Publishing a file atomically: the bytes go to a new temporary file in the target's
// directory, every write is checked, the file is fsync'd and closed, and only then renamed
// over the target (and the directory fsync'd). On any failure the temporary file is removed
// and the target is untouched, so a reader sees the old file or the complete new one, never
// a partial one.
//
// Temporary names are ".<start of the target's name>.splinefig-<pid>-<n>.tmp": unique per
// call (process id, a per-process counter, O_EXCL), at most 255 bytes for any valid target
// name. After a successful write, temporary files of the same target left by processes that no
// longer exist (killed with SIGKILL) are removed. Thread-safe. While a write is under way, SIGINT, SIGTERM and SIGHUP remove the
// temporary files of every writer thread and then take their previous action (the handler is
// installed at the first write, and not at all for a signal whose action is SIG_IGN, so an
// ignored signal stays ignored).
#include <splinefig/base/error.hpp>

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

namespace splinefig {

// A file that cannot be written; what() is one line naming the file and the reason.
struct UnwritableFile : ErrorOf<std::runtime_error, ErrorKind::unwritable> {
  using ErrorOf::ErrorOf;
};

void write_file_atomically(const std::string& path, std::span<const unsigned char> bytes);

// True if `a` and `b` name the same existing file, by any spelling: a relative or absolute
// path, a symbolic link or a hard link (same device and inode). Commands refuse to write an
// output over one of their inputs with it, before reading or writing anything.
bool same_file(const std::string& a, const std::string& b);

// The temporary name write_file_atomically uses for `filename` (no directory) in a process
// with id `pid` on its `n`-th call (exposed for tests).
std::string temporary_name(const std::string& filename, long pid, unsigned long n);

}  // namespace splinefig
