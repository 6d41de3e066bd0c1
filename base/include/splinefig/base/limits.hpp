#pragma once
// The limits a request is held to, in one place (docs/limits.md lists each with its reason).
// Naming rule: kMax<Thing> / kMin<Thing>, in the unit the name says.

#include <cstdint>

namespace splinefig {

// Worker threads a request may ask for; more is clamped to this (0 asks for every core).
inline constexpr int kMaxThreads = 256;

// A canvas (a scene, a figure at 1x and after --scale): pixels a side and in all.
inline constexpr int kMaxCanvasSide = 32768;
inline constexpr long long kMaxCanvasPixels = 1LL << 28;

// Coordinates and lengths given to the renderer, in pixels: beyond 1e15 a double cannot place a
// point within a pixel, and differences of such values may overflow.
inline constexpr double kMaxCoordinate = 1e15;

// A dash pattern's period (the sum of its lengths), in pixels, and the work of one dashed stroke:
// the dashes near the canvas times the square of the number each one's outline overlaps.
inline constexpr double kMinDashPeriod = 1e-3;
inline constexpr double kMaxDashWork = 1 << 20;

// Resolution written into PNG, SVG and PDF files, in dots per inch (0 leaves it unset).
inline constexpr double kMinDpi = 1, kMaxDpi = 10000;

}  // namespace splinefig
