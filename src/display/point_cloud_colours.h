// RViz's colour transformers for point clouds (src/rviz/default_plugin/point_cloud_transformers.cpp)
// and the rainbow they share.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "display/point_cloud_reader.h"
#include "display/point_cloud_settings.h"

namespace urdfsnap::display {

// getRainbowColor: value in [0, 1] (clamped) to a hue from red (0) through yellow, green, cyan and
// blue to magenta (1).
Eigen::Vector3f RainbowColour(float value);

// The transformer `settings` asks for, or RViz's choice when it asks for none or for one the
// cloud cannot use (RGB8 needs an int32/uint32/float32 rgb or rgba field, RGBF32 float32 r, g, b).
PointCloudSettings::Colour ChooseColour(const PointCloudReader& cloud, const PointCloudSettings& settings);

// The colour (rgba, before the display's Alpha) of the points `indices` of `cloud` by `colour`.
// `axis_values` are the points' AxisColor values (their positions along the axis, in the fixed
// frame or the cloud's as settings say), used by kAxisColor only. Intensity with no such channel
// leaves the points white, as RViz's transformer does by failing. Throws CloudError for a field
// that cannot be read.
std::vector<Eigen::Vector4f> PointColours(const PointCloudReader& cloud, const std::vector<std::size_t>& indices,
                                          PointCloudSettings::Colour colour, const PointCloudSettings& settings,
                                          const std::vector<float>& axis_values);

}  // namespace urdfsnap::display
