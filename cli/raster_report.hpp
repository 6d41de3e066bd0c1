#pragma once
// What `render -v` and `figures -v` say about how a figure was rasterized: exactly, or with
// bands of rows of some items resolved from their pieces within the coverage tolerance
// (render::RasterReport, docs/renderer.md "Dense strokes").
#include <splinefig/renderer/renderer.hpp>

#include <string>
#include <vector>

namespace splinefig::cli {

// One line, e.g. "exact (no band needed the coverage tolerance, 1/1024)" or "item 3: 40 of 64
// bands of 16 rows resolved from its pieces, within the coverage tolerance 1/1024 (the other
// bands and items exact)". Items are numbered from 1 in drawing order; at most five are named.
std::string describe_raster(const render::RasterReport& report);

// An animation's frames, one line per run of consecutive frames described alike, numbered from
// 1: "frames 1-12 of 13: exact (...)", "frame 13 of 13: item 2: 3 of 16 bands ...".
std::vector<std::string> describe_frames(const std::vector<render::RasterReport>& frames);

}  // namespace splinefig::cli
