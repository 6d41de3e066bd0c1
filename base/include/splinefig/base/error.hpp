#pragma once
// The library's errors. Each is a standard exception, whose what() is its one-line message and
// whose class (std::invalid_argument, std::runtime_error, ...) code that catches those still
// catches, and a splinefig::Error, which says what kind of failure it is. The kind alone decides
// a command's exit code (cli/main.cpp, docs/conventions.md) and a Python exception's class
// (python/src/module.cpp); where an error is caught does not.
#include <stdexcept>
#include <string>

namespace splinefig {

enum class ErrorKind {
  bad_input,   // a bad flag, spec, value or data, or a request over a limit
  unreadable,  // a file or stream that cannot be read (missing, not permitted, not an image)
  unwritable,  // a file or stream that cannot be written (a full disk, a closed pipe)
};

class Error {
 public:
  explicit Error(ErrorKind kind) noexcept : kind_(kind) {}
  Error(const Error&) = default;
  Error& operator=(const Error&) = default;
  virtual ~Error() = default;
  ErrorKind kind() const noexcept { return kind_; }

 private:
  ErrorKind kind_;
};

// The error of kind `Kind` that is also a `Std` (a standard exception taking a message).
template <class Std, ErrorKind Kind>
struct ErrorOf : Std, Error {
  explicit ErrorOf(const std::string& what) : Std(what), Error(Kind) {}
  explicit ErrorOf(const char* what) : Std(what), Error(Kind) {}
};

// The kind of any exception: its own if it is a splinefig::Error, else bad_input (a bare
// std::invalid_argument from a check, a std::length_error from a limit, ...).
inline ErrorKind error_kind(const std::exception& e) noexcept {
  const auto* error = dynamic_cast<const Error*>(&e);
  return error ? error->kind() : ErrorKind::bad_input;
}

}  // namespace splinefig
