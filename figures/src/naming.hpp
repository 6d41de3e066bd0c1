#pragma once
// Internal: errors named by the spec table they come from. Whatever is found wrong after
// loading (while laying out or painting) names the table of the item or element being worked
// on, "FILE:LINE: KEY: what", as the loader's own errors do.
#include <splinefig/figures/spec.hpp>

#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace splinefig::figures::detail {

// An error about one key of the table being drawn (e.g. an axes table's x_range).
struct KeyError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  KeyError(std::string k, const std::string& what) : ErrorOf(what), key(std::move(k)) {}
  std::string key;
};

// Runs f(); an error it throws other than SpecFileError becomes a SpecFileError
// "ORIGIN: what" (one line), `origin` being the location of the spec table being drawn; a
// KeyError becomes "ORIGIN.KEY: what".
template <class F>
void naming_origin(const SpecLocation& origin, F&& f) {
  try {
    f();
  } catch (const SpecFileError&) {
    throw;
  } catch (const KeyError& e) {
    throw SpecFileError(origin.empty() ? e.key + ": " + e.what() : origin.str() + "." + e.key + ": " + e.what());
  } catch (const std::bad_alloc&) {
    throw SpecFileError(origin, "out of memory");
  } catch (const std::exception& e) {
    throw SpecFileError(origin.empty() ? std::string(e.what()) : origin.str() + ": " + e.what());
  }
}

}  // namespace splinefig::figures::detail
