#pragma once
// A spec's [animation] (docs/figures.md): its filmstrips ([[axes.inbetween]] with steps = N)
// played frame by frame as an animated WebP (image/animation.hpp), each frame a figure of its
// own, laid out, painted and rasterized as every figure is.
#include <splinefig/figures/figure.hpp>

#include <string>
#include <vector>

namespace splinefig::figures {

// Frames of the spec's animation: steps x keyframe intervals + 1 of its filmstrips; 0 without
// [animation].
int animation_frames(const FigureSpec& spec);
// The in-between time of frame `i` (i / steps) and whether it is a keyframe.
double animation_time(const FigureSpec& spec, int i);
bool animation_keyframe(const FigureSpec& spec, int i);
// Milliseconds frame `i` is shown: key_delay for a keyframe (when set), else delay.
int animation_delay(const FigureSpec& spec, int i);

// Frame `i` (0 .. animation_frames - 1) as a figure: the spec's title; the animated panels in one
// row on the [animation] canvas, each with its title and, in place of its elements, every
// filmstrip's keyframes drawn faintly (key_color, or the colour, at opacity 0x4d / 255, about 30%) under the frame
// at t = i / steps: the keyframe itself, marked, as the strip draws it, or the in-between frame
// as [[axes.inbetween]] with t = i / steps draws it; one data range for every frame and panel
// (the frames' bounding box, 5% of its larger side around it); the time as each panel's x label.
FigureSpec animation_frame_spec(const FigureSpec& spec, int i);

// The gallery's alt text: [animation] alt, or one made from the title and frame count.
std::string animation_alt(const FigureSpec& spec);

// Checks the animation's frames, size and their product at `scale` against base/limits.hpp;
// throws SpecFileError naming the [animation] table. Nothing without [animation].
void check_animation_size(const FigureSpec& spec, double scale);

// Renders every frame at `scale` (rasterizer threads `threads`; the bytes do not depend on
// them) and writes the animated WebP to `path` atomically. The frames, their size and their
// product are checked against base/limits.hpp after scaling, before the first is drawn
// (SpecFileError naming the [animation] table). Throws as figure_scene and WebpAnimation do.
// With `reports`, it receives each frame's render::RasterReport, in frame order.
AnimationInfo write_animation(const FigureSpec& spec, const std::string& path, double scale = 1, int threads = 0,
                              std::vector<render::RasterReport>* reports = nullptr);

}  // namespace splinefig::figures
