#pragma once
// What a Scene records for each drawing call: the call's own arguments, validated. Geometry is
// built at rasterization time, when the clip region (canvas plus filter support) is known.
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <memory>
#include <vector>

namespace splinefig::render {

// A clip path: what the items recorded after Scene::set_clip are intersected with, exactly.
struct ClipRegion {
  Path path;
  FillRule rule = FillRule::NonZero;
};

struct Scene::Item {
  enum class Kind { Stroke, Fill, Disk, Ring, Marker, Text, Image, PathFill, PathStroke } kind = Kind::Fill;
  std::vector<std::vector<Vec2>> contours;  // Fill: the contours; Stroke: contours[0] the path
  bool closed = false;
  StrokeStyle stroke;
  FillRule rule = FillRule::NonZero;
  Color color;
  Vec2 centre;
  double radius = 0;  // Disk, Ring: radius; Marker: size
  render::Marker marker = render::Marker::Circle;
  struct Text {
    std::string text;
    TextStyle style;
    Path outline;  // the glyph outlines in canvas pixels (text_path), filled with the nonzero rule
  };
  std::unique_ptr<Text> text;  // Text only: keeps the common item small
  struct Raster {
    std::shared_ptr<const Image> image;  // 4 channels, associated alpha
    Vec2 p0, p1;                         // the target rectangle's corners
    bool nearest = true;
  };
  std::shared_ptr<const Raster> raster;  // Image only
  std::shared_ptr<const Path> path;      // PathFill, PathStroke only
  std::shared_ptr<const ClipRegion> clip;  // the clip in effect when recorded; none: null
};

}  // namespace splinefig::render
