// A spec's [animation]: its filmstrips frame by frame, each frame a figure (see animation.hpp).
#include <splinefig/figures/animation.hpp>
#include <splinefig/base/limits.hpp>
#include <splinefig/image/webp_animation.hpp>

#include "layout/generated.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace splinefig::figures {
namespace {

const AnimationSpec& animation_of(const FigureSpec& spec) {
  if (!spec.animation) throw std::logic_error(spec.path + ": the spec has no [animation]");
  return *spec.animation;
}

// The spec's [[axes]] in document order (as [animation] panels and caption fields count them).
std::vector<const AxesSpec*> spec_axes(const FigureSpec& spec) {
  std::vector<const AxesSpec*> axes;
  for (const Item& item : spec.items)
    if (const auto* ax = std::get_if<AxesSpec>(&item)) axes.push_back(ax);
  return axes;
}

// The keyframes' opacity under the moving frame: 0x4d / 255, about 30% (a colour "#rrggbb4d").
constexpr float kGhostAlpha = 77.0f / 255.0f;

bool is_strip(const PlotElement& e) {
  const auto* ib = std::get_if<InbetweenElement>(&e);
  return ib && ib->steps > 0;
}

// The first filmstrip of the animated panels (the loader checked that all have one frame count).
const InbetweenElement& first_strip(const FigureSpec& spec) {
  const auto axes = spec_axes(spec);
  for (int p : animation_of(spec).panels)
    for (const PlotElement& e : axes[static_cast<std::size_t>(p)]->elements)
      if (is_strip(e)) return std::get<InbetweenElement>(e);
  throw std::logic_error(spec.path + ": [animation] has no filmstrip");
}

// The bounding box of every frame of every animated filmstrip, unshifted: x0, y0, x1, y1.
std::array<double, 4> frames_box(const FigureSpec& spec) {
  std::array<double, 4> box{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  const auto axes = spec_axes(spec);
  for (int p : animation_of(spec).panels)
    for (const PlotElement& e : axes[static_cast<std::size_t>(p)]->elements) {
      if (!is_strip(e)) continue;
      const auto& strip = std::get<InbetweenElement>(e);
      const auto parts = detail::parts_of(strip);  // frame i moved by i * shift
      for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto* g = std::get_if<detail::GeneratedSeries>(&parts[i]);
        if (!g) continue;
        for (Vec2 q : g->series.points) {
          const double x = q.x - static_cast<double>(i) * strip.shift.x, y = q.y - static_cast<double>(i) * strip.shift.y;
          box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
        }
      }
    }
  return box;
}

std::string time_label(double t, bool key) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", t);
  return std::string("$t$ = ") + buf + (key ? ", a key frame" : "");
}

}  // namespace

int animation_frames(const FigureSpec& spec) {
  if (!spec.animation) return 0;
  const InbetweenElement& s = first_strip(spec);
  return s.steps * static_cast<int>(s.frames.size() - 1) + 1;
}

double animation_time(const FigureSpec& spec, int i) {
  return static_cast<double>(i) / first_strip(spec).steps;
}

bool animation_keyframe(const FigureSpec& spec, int i) { return i % first_strip(spec).steps == 0; }

int animation_delay(const FigureSpec& spec, int i) {
  const AnimationSpec& a = animation_of(spec);
  return animation_keyframe(spec, i) && a.key_delay > 0 ? a.key_delay : a.delay;
}

std::string animation_alt(const FigureSpec& spec) {
  const AnimationSpec& a = animation_of(spec);
  if (!a.alt.empty()) return a.alt;
  const std::string title = spec.title.empty() ? spec.name : spec.title;
  return "Animation of " + title + ": " + std::to_string(animation_frames(spec)) +
         " frames, one in-between time each, the key frames marked";
}

FigureSpec animation_frame_spec(const FigureSpec& spec, int i) {
  const AnimationSpec& a = animation_of(spec);
  const int frames = animation_frames(spec);
  if (i < 0 || i >= frames)
    throw std::out_of_range("animation frame " + std::to_string(i) + " of " + std::to_string(frames));
  FigureSpec f;
  f.name = spec.name;
  f.path = spec.path;
  f.title = spec.title;
  f.show_title = spec.show_title;
  f.sizes = spec.sizes;
  f.font_family = spec.font_family;
  f.title_origin = spec.title_origin;
  f.canvas = spec.canvas;
  f.canvas.width = a.width;
  f.canvas.height = a.height;
  f.layout = spec.layout;
  f.layout.rows = 1;
  f.layout.cols = static_cast<int>(a.panels.size());
  // One range for every frame and panel: the frames' box, 5% of its larger side around it.
  const auto box = frames_box(spec);
  const double pad = 0.05 * std::max({box[2] - box[0], box[3] - box[1], 1e-9});
  const std::array<double, 2> xr{box[0] - pad, box[2] + pad}, yr{box[1] - pad, box[3] + pad};
  const auto axes = spec_axes(spec);
  const double t = animation_time(spec, i);
  const bool keyframe = animation_keyframe(spec, i);
  for (std::size_t k = 0; k < a.panels.size(); ++k) {
    const AxesSpec& from = *axes[static_cast<std::size_t>(a.panels[k])];
    AxesSpec ax = from;
    ax.cell = std::array<int, 2>{0, static_cast<int>(k)};
    ax.box.reset();
    ax.x = AxisSpec{};
    ax.y = AxisSpec{};
    ax.x.range = xr;
    ax.y.range = yr;
    ax.x.ticks = std::vector<double>{};
    ax.y.ticks = std::vector<double>{};
    ax.x.label = time_label(t, keyframe);
    ax.legend = LegendPlace::None;
    ax.elements.clear();
    ax.element_origins.clear();
    std::vector<PlotElement> current;
    std::vector<SpecLocation> current_origins;
    for (std::size_t j = 0; j < from.elements.size(); ++j) {
      if (!is_strip(from.elements[j])) continue;
      const auto& strip = std::get<InbetweenElement>(from.elements[j]);
      const SpecLocation origin = j < from.element_origins.size() ? from.element_origins[j] : from.where;
      // The keyframes, faint: key_color (or the colour) at 30% opacity (0x4d), marked.
      SeriesLook key = strip.look;
      if (strip.key_color) key.color = strip.key_color;
      key.mode = SeriesMode::LineMarkers;
      key.stroke.dashes = {};
      key.label = {};
      SeriesLook ghost = key;
      Color c = ghost.color.value_or(Color{0, 0, 0, 1});
      c.a *= kGhostAlpha;
      ghost.color = c;
      if (ghost.marker_color) ghost.marker_color->a *= kGhostAlpha;
      for (const auto& frame : strip.frames) {
        ax.elements.push_back(SeriesElement{frame, ghost});
        ax.element_origins.push_back(origin);
      }
      // The frame at t: a keyframe from its data, marked, as the strip draws it; an in-between
      // frame as [[axes.inbetween]] with t draws it.
      if (keyframe) {
        current.push_back(SeriesElement{strip.frames[static_cast<std::size_t>(i / strip.steps)], key});
      } else {
        InbetweenElement one = strip;
        one.steps = 0;
        one.t = t;
        one.shift = {0, 0};
        one.key_color.reset();
        one.key_label = {};
        one.look.label = {};
        current.push_back(std::move(one));
      }
      current_origins.push_back(origin);
    }
    ax.elements.insert(ax.elements.end(), current.begin(), current.end());
    ax.element_origins.insert(ax.element_origins.end(), current_origins.begin(), current_origins.end());
    f.items.push_back(std::move(ax));
    f.item_origins.push_back(from.where);
  }
  return f;
}

void check_animation_size(const FigureSpec& spec, double scale) {
  if (!spec.animation) return;
  const AnimationSpec& a = *spec.animation;
  const int frames = animation_frames(spec);
  const double w = std::round(a.width * scale), h = std::round(a.height * scale);
  auto refuse = [&](const std::string& why) { throw SpecFileError(a.where.with_key("animation"), why); };
  if (!(w >= 1 && h >= 1 && w <= kMaxAnimationSide && h <= kMaxAnimationSide))
    refuse("the animation is " + std::to_string(static_cast<long long>(w)) + " x " + std::to_string(static_cast<long long>(h)) +
           " px at scale " + std::to_string(scale) + ": each side must be 1 to " + std::to_string(kMaxAnimationSide) + " px");
  if (static_cast<double>(frames) * w * h > static_cast<double>(kMaxAnimationPixels))
    refuse(std::to_string(frames) + " frames of " + std::to_string(static_cast<long long>(w)) + " x " +
           std::to_string(static_cast<long long>(h)) + " px, over the limit of 2^28 pixels in all");
}

AnimationInfo write_animation(const FigureSpec& spec, const std::string& path, double scale, int threads,
                              std::vector<render::RasterReport>* reports) {
  const AnimationSpec& a = animation_of(spec);
  const int frames = animation_frames(spec);
  check_animation_size(spec, scale);
  const double w = std::round(a.width * scale), h = std::round(a.height * scale);
  WebpAnimation anim(static_cast<int>(w), static_cast<int>(h), a.loops);
  AnimationInfo info;
  if (reports) reports->clear();
  for (int i = 0; i < frames; ++i) {
    const FigureScene fig = figure_scene(animation_frame_spec(spec, i), scale);
    if (i == 0) {
      info.width = fig.info.width;
      info.height = fig.info.height;
    }
    render::RasterReport* report = reports ? &reports->emplace_back() : nullptr;
    anim.add(render::rasterize(fig.raster, threads, report), animation_delay(spec, i));
  }
  anim.write(path);
  info.file = std::filesystem::path(path).filename().string();
  info.frames = frames;
  info.alt = animation_alt(spec);
  return info;
}

}  // namespace splinefig::figures
