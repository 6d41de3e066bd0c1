#pragma once
// The limits a request is held to, in one place (docs/limits.md lists each with its reason).
// Naming rule: kMax<Thing> / kMin<Thing>, in the unit the name says.

#include <cstddef>
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

// The exact union's work for one drawn item: crossings of its outline with itself on the canvas,
// each an event of the sweep (about 0.2 us): 2^28 is about a minute on one core. 10^5 uniformly
// random points on 1024^2, stroked, cross about 4.5e9 times.
inline constexpr double kMaxSweepCrossings = double(1 << 28);

// The outline vertices of a scene's items (stroke joins and caps, dashes, circles, markers,
// flattened paths, glyphs and clip paths), estimated from above before any is built: each item's
// and all of a scene's together (the rasterizer holds every item's outline at once on more than
// one thread), about 20 bytes a vertex, so 2^26 is about 1.3 GB. A 10^6-point zigzag with
// hairpin turns and round joins (a pen of width 2) needs about 2.2e8 (3.9 GB).
inline constexpr double kMaxOutlineVertices = double(1 << 26);

// The text of one item (a title, a label, a [[text]], Scene::text, measure_text), in UTF-8
// bytes, checked before it is decoded: every character becomes a placed glyph and its outline,
// under 1 KB each at the arc tolerance, so 2^20 bytes stay under about 1 GB, as the outline
// limit does (4 * 10^6 characters took 3.4 GB before their outline could be counted).
inline constexpr std::size_t kMaxTextBytes = std::size_t(1) << 20;

// Resolution written into PNG, SVG and PDF files, in dots per inch (0 leaves it unset).
inline constexpr double kMinDpi = 1, kMaxDpi = 10000;

// Text: a font size in pixels (the em), at 1x and after --scale: glyph rasters and their
// integer metrics.
inline constexpr double kMaxFontSize = 4096;

// An image read (diff, resample, a spec's [[image]]), checked from the file's header before any
// pixel data is decompressed (a PNG of a few KB can declare 20000 x 20000 zeros): float values
// (width * height * channels), 4 GiB; pixels (width * height), as for a canvas; either side
// (OpenEXR sizes its scanline buffers by the width: a header of a few hundred bytes declaring
// 2097155 x 3 pixels made it ask for 4 GiB); the data window's origin (EXR data windows, PNG
// oFFs), |x|, |y|, so that origin + size and the span of two windows fit an int.
inline constexpr std::uint64_t kMaxImageValues = std::uint64_t(1) << 30;
inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t(1) << 28;
inline constexpr std::uint64_t kMaxImageSide = std::uint64_t(1) << 16;
inline constexpr std::int64_t kMaxImageOrigin = std::int64_t(1) << 30;
// Values a file may declare per byte it holds: no codec packs more than 2^14 values in a byte
// (deflate's 1032:1 on a 1-bit PNG or TIFF expanded to a grey float is about 8256; an LZW GIF
// expanded to RGB about 4100; RLE formats 64 to 128), so a 21-byte TGA header declaring
// 10240 x 25953 x 3 values (3.2 GB of floats) is refused before anything is allocated.
inline constexpr std::uint64_t kMaxImageValuesPerByte = std::uint64_t(1) << 14;

// Figure specs, checked where they are loaded, before any work.
inline constexpr std::size_t kMaxSpecBytes = std::size_t(1) << 26;  // a spec file: 64 MiB, held whole
inline constexpr std::size_t kMaxKeyParts = 64;       // parts of a dotted key or table header (the parser recurses)
inline constexpr std::size_t kMaxValueNesting = 16;   // arrays and inline tables inside each other (the parser recurses)
inline constexpr std::size_t kMaxMarks = 100000;      // x_marks, y_marks, curve marks: each a drawn shape
inline constexpr std::size_t kMaxBezierPoints = 128;  // control points of one [[axes.bezier]] (degree 127)
inline constexpr std::size_t kMaxFilmstripFrames = 4096;  // frames of one [[axes.inbetween]] filmstrip, each a stroke
// A spec's [animation] (an animated WebP of its filmstrips): frames, and pixels over all frames
// (frames x width x height after --scale), each frame rendered and encoded in turn; checked
// before the first frame is drawn. A frame's delay in milliseconds (browsers show a delay under
// 20 ms as 100 ms).
inline constexpr std::size_t kMaxAnimationFrames = 1024;
inline constexpr std::uint64_t kMaxAnimationPixels = std::uint64_t(1) << 28;
inline constexpr int kMaxAnimationSide = 16383;  // WebP's largest side
inline constexpr int kMinFrameDelayMs = 20;
inline constexpr int kMaxFrameDelayMs = 60000;
inline constexpr int kMaxTicks = 1000;                // ticks of one axis, each label measured
// An axis range's span: at least kMinAxisSpan and kMinRelativeAxisSpan of the larger end's
// magnitude, so that the pixel map and the ticks have distinct numbers to work with.
inline constexpr double kMinAxisSpan = 1e-100;
inline constexpr double kMinRelativeAxisSpan = 1e-12;

}  // namespace splinefig
