// The messages RViz's Marker, MarkerArray, Path and PoseArray displays draw, as typed values
// (visualization_msgs/Marker, nav_msgs/Path, geometry_msgs/PoseArray of ROS 2), and their decoding
// from a bag::MessageValue by field name, so that the bag's own definition (or the shipped one)
// decides the layout.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bag/cdr_message.h"

namespace urdfsnap::display {

// std_msgs/Header: the frame a message is in and the time its data holds for.
struct Header {
  std::string frame_id;
  std::int64_t stamp_ns = 0;
};

// geometry_msgs/Pose as written: the quaternion is checked and normalised where it is used.
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// visualization_msgs/Marker.
struct Marker {
  enum Type : int {
    kArrow = 0, kCube = 1, kSphere = 2, kCylinder = 3, kLineStrip = 4, kLineList = 5,
    kCubeList = 6, kSphereList = 7, kPoints = 8, kTextViewFacing = 9, kMeshResource = 10,
    kTriangleList = 11,
  };
  enum Action : int { kAdd = 0, kDelete = 2, kDeleteAll = 3 };   // MODIFY = ADD

  Header header;
  std::string ns;
  int id = 0;
  int type = kArrow;
  int action = kAdd;
  Pose pose;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  Eigen::Vector4f colour{1, 1, 1, 1};
  std::int64_t lifetime_ns = 0;   // 0: forever
  bool frame_locked = false;
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector4f> colours;
  std::string text;
  std::string mesh_resource;
  bool mesh_use_embedded_materials = false;
};

// nav_msgs/Path and geometry_msgs/PoseArray alike: poses in the header's frame (RViz's Path
// display transforms every pose by the path's header, ignoring each PoseStamped's own header).
struct PoseList {
  Header header;
  std::vector<Pose> poses;
};

// Decoders of a decoded message of the named type. Throw bag::CdrError when a field they read is
// missing from the message's definition.
Marker DecodeMarker(const bag::MessageValue& value);
std::vector<Marker> DecodeMarkerArray(const bag::MessageValue& value);
PoseList DecodePath(const bag::MessageValue& value);
PoseList DecodePoseArray(const bag::MessageValue& value);

}  // namespace urdfsnap::display
