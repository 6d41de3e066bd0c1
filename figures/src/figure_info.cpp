// The pixel maps of a laid-out panel (see figure_info.hpp).
#include <splinefig/figures/figure_info.hpp>

namespace splinefig::figures {

AxisMap AxesInfo::x_map() const { return {x_scale, x_range[0], x_range[1], pixel_box[0], pixel_box[2]}; }
AxisMap AxesInfo::y_map() const { return {y_scale, y_range[0], y_range[1], pixel_box[3], pixel_box[1]}; }

}  // namespace splinefig::figures
