#pragma once
// The data window's origin against kMaxImageOrigin (io.hpp), one rule and one message for the
// PNG header check and for any codec's header.
#include <splinefig/image/io.hpp>

#include <cstdint>
#include <cstdlib>
#include <string>

namespace splinefig::detail {

// Empty if (x, y) is within the limit, else what is wrong with it.
inline std::string origin_problem(std::int64_t x, std::int64_t y) {
  if (std::abs(x) <= kMaxImageOrigin && std::abs(y) <= kMaxImageOrigin) return {};
  return "data window origin (" + std::to_string(x) + ", " + std::to_string(y) + ") out of range (limit 2^30 either way)";
}

}  // namespace splinefig::detail
