// A PointCloud2 as RViz's PointCloud2 display draws it (src/rviz/default_plugin/
// point_cloud2_display.cpp and point_cloud_common.cpp): the points whose x, y and z are finite,
// placed in the fixed frame, coloured by the settings' transformer, in the settings' style and size.
#pragma once

#include <Eigen/Geometry>

#include "display/point_cloud_message.h"
#include "display/point_cloud_settings.h"
#include "scene/scene.h"

namespace urdfsnap::display {

// `X_FC`: the cloud's frame in the fixed frame. Throws CloudError (display/point_cloud_reader.h)
// for a cloud whose claims do not fit its bytes or whose x, y, z or colour fields cannot be read;
// memory stays within a small multiple of the bytes present.
scene::PointSet CloudPointSet(const PointCloud2& cloud, const PointCloudSettings& settings,
                              const Eigen::Isometry3d& X_FC);

}  // namespace urdfsnap::display
