#include "raster_report.hpp"

#include <cmath>
#include <cstdio>

namespace splinefig::cli {
namespace {

// 1/1024 when the tolerance is the reciprocal of a whole number, else its shortest %g form.
std::string tolerance_text(double t) {
  char buf[64];
  if (t == 0) return "0";
  const double inv = 1 / t;
  if (inv == std::round(inv) && inv <= 1e9 && 1 / inv == t) {
    std::snprintf(buf, sizeof buf, "1/%.0f", inv);
  } else {
    std::snprintf(buf, sizeof buf, "%g", t);
  }
  return buf;
}

}  // namespace

std::string describe_raster(const render::RasterReport& r) {
  const std::string tol = tolerance_text(r.tolerance);
  if (r.items.empty()) return "exact (no band needed the coverage tolerance, " + tol + ")";
  std::string out;
  const std::size_t named = std::min<std::size_t>(r.items.size(), 5);
  for (std::size_t i = 0; i < named; ++i) {
    const render::RasterReport::Item& it = r.items[i];
    out += (i ? "; item " : "item ") + std::to_string(it.index + 1) + ": " + std::to_string(it.piece_bands) + " of " +
           std::to_string(it.bands) + " bands";
  }
  if (r.items.size() > named) out += "; and " + std::to_string(r.items.size() - named) + " more items";
  return out + " of " + std::to_string(r.band_rows) + " rows resolved from " + (r.items.size() == 1 ? "its" : "their") +
         " pieces, within the coverage tolerance " + tol + " (the other bands and items exact)";
}

std::vector<std::string> describe_frames(const std::vector<render::RasterReport>& frames) {
  std::vector<std::string> out;
  const std::string of = " of " + std::to_string(frames.size()) + ": ";
  for (std::size_t i = 0; i < frames.size();) {
    const std::string what = describe_raster(frames[i]);
    std::size_t j = i + 1;
    while (j < frames.size() && describe_raster(frames[j]) == what) ++j;
    out.push_back(j == i + 1 ? "frame " + std::to_string(i + 1) + of + what
                             : "frames " + std::to_string(i + 1) + "-" + std::to_string(j) + of + what);
    i = j;
  }
  return out;
}

}  // namespace splinefig::cli
