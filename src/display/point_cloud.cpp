// CloudPointSet: RViz's NaN filter (point_cloud2_display.cpp processMessage), then the XYZ and colour
// transformers (point_cloud_common.cpp transformCloud), then the style's size and the Alpha.
#include "display/point_cloud.h"

#include <algorithm>
#include <vector>

#include "display/point_cloud_colours.h"
#include "display/point_cloud_reader.h"

namespace urdfsnap::display {

scene::PointSet CloudPointSet(const PointCloud2& cloud, const PointCloudSettings& settings,
                              const Eigen::Isometry3d& X_FC) {
  const PointCloudReader reader(cloud);
  const int x = reader.Field("x"), y = reader.Field("y"), z = reader.Field("z");
  std::vector<std::size_t> kept;
  std::vector<Eigen::Vector3f> local;
  for (std::size_t i = 0; i < reader.size(); ++i) {
    const Eigen::Vector3f p(reader.Value(x, i), reader.Value(y, i), reader.Value(z, i));
    if (!p.allFinite()) continue;
    kept.push_back(i);
    local.push_back(p);
  }
  scene::PointSet points;
  points.style = settings.style;
  points.size.setConstant(settings.style == scene::PointSet::Style::kPoints ? settings.size_px : settings.size_m);
  points.box_axes = X_FC.linear().cast<float>();
  const Eigen::Affine3f X = Eigen::Affine3f(X_FC.cast<float>());
  points.positions.reserve(local.size());
  for (const Eigen::Vector3f& p : local) points.positions.push_back(X * p);

  const PointCloudSettings::Colour colour = ChooseColour(reader, settings);
  std::vector<float> axis_values;
  if (colour == PointCloudSettings::Colour::kAxisColor) {
    const std::vector<Eigen::Vector3f>& along = settings.axis_in_fixed_frame ? points.positions : local;
    axis_values.reserve(along.size());
    for (const Eigen::Vector3f& p : along) axis_values.push_back(p[std::clamp(settings.axis, 0, 2)]);
  }
  points.colours = PointColours(reader, kept, colour, settings, axis_values);
  for (Eigen::Vector4f& c : points.colours) c.w() *= settings.alpha;
  return points;
}

}  // namespace urdfsnap::display
