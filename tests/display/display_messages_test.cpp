// The display messages decoded from CDR through the definitions urdfsnap ships (as a bag without
// definitions gets them): every Marker field, MarkerArray, Path and PoseArray.
#include "display/display_messages.h"

#include <gtest/gtest.h>

#include <map>

#include "support/cdr_bytes.h"

namespace urdfsnap::display {
namespace {

// A CDR message under construction, with the Header and Pose layouts added.
class Cdr : public test::CdrBytes {
 public:
  Cdr& Header(std::int32_t sec, std::uint32_t nanosec, const std::string& frame) {
    I32(sec).U32(nanosec).Str(frame);
    return *this;
  }
  Cdr& Pose(double x, double y, double z) {
    F64(x).F64(y).F64(z).F64(0).F64(0).F64(0).F64(1);
    return *this;
  }
};

void AppendMarker(Cdr& cdr) {
  cdr.Header(2, 500, "/tool").Str("goals").I32(7).I32(Marker::kLineStrip).I32(Marker::kAdd);
  cdr.Pose(1, 2, 3).F64(0.1).F64(0.2).F64(0.3);
  cdr.F32(0.5f).F32(0.25f).F32(1).F32(0.75f);   // color
  cdr.I32(3).U32(0).U8(1);                       // lifetime 3 s, frame_locked
  cdr.U32(2).F64(0).F64(0).F64(0).F64(1).F64(1).F64(1);   // points
  cdr.U32(1).F32(1).F32(0).F32(0).F32(1);                  // colors
  cdr.Str("");                                             // texture_resource
  cdr.Header(0, 0, "").Str("").U32(0);                     // texture
  cdr.U32(0);                                              // uv_coordinates
  cdr.Str("hello").Str("package://p/m.dae");               // text, mesh_resource
  cdr.Str("").U32(0).U32(0);                               // mesh_file
  cdr.U8(1);                                               // mesh_use_embedded_materials
}

bag::MessageValue Decode(const char* type, const Cdr& cdr) {
  static std::map<std::string, bag::MessageSchema> schemas;
  auto it = schemas.find(type);
  if (it == schemas.end()) it = schemas.emplace(type, *bag::MessageSchema::Shipped(type)).first;
  return bag::DecodeMessage(it->second, cdr.bytes());
}

TEST(DisplayMessagesTest, MarkerArrayDecodesEveryMarkerField) {
  Cdr cdr;
  cdr.U32(1);
  AppendMarker(cdr);
  const std::vector<Marker> markers = DecodeMarkerArray(Decode("visualization_msgs/msg/MarkerArray", cdr));
  ASSERT_EQ(markers.size(), 1u);
  const Marker& m = markers[0];
  EXPECT_EQ(m.header.frame_id, "tool");   // tf2 drops the leading slash
  EXPECT_EQ(m.header.stamp_ns, 2'000'000'500);
  EXPECT_EQ(m.ns, "goals");
  EXPECT_EQ(m.id, 7);
  EXPECT_EQ(m.type, Marker::kLineStrip);
  EXPECT_EQ(m.pose.position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(m.pose.orientation.w(), 1);
  EXPECT_EQ(m.scale, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(m.colour, Eigen::Vector4f(0.5f, 0.25f, 1, 0.75f));
  EXPECT_EQ(m.lifetime_ns, 3'000'000'000);
  EXPECT_TRUE(m.frame_locked);
  ASSERT_EQ(m.points.size(), 2u);
  EXPECT_EQ(m.points[1], Eigen::Vector3f(1, 1, 1));
  ASSERT_EQ(m.colours.size(), 1u);
  EXPECT_EQ(m.text, "hello");
  EXPECT_EQ(m.mesh_resource, "package://p/m.dae");
  EXPECT_TRUE(m.mesh_use_embedded_materials);
}

TEST(DisplayMessagesTest, PathAndPoseArrayDecodeTheirPoses) {
  Cdr path;
  path.Header(1, 0, "map").U32(2);
  path.Header(1, 0, "ignored").Pose(1, 0, 0);
  path.Header(1, 0, "ignored").Pose(2, 0, 0);
  const PoseList p = DecodePath(Decode("nav_msgs/msg/Path", path));
  EXPECT_EQ(p.header.frame_id, "map");
  ASSERT_EQ(p.poses.size(), 2u);
  EXPECT_EQ(p.poses[1].position.x(), 2);

  Cdr array;
  array.Header(1, 0, "odom").U32(1);
  array.Pose(0, 3, 0);
  const PoseList a = DecodePoseArray(Decode("geometry_msgs/msg/PoseArray", array));
  EXPECT_EQ(a.header.frame_id, "odom");
  ASSERT_EQ(a.poses.size(), 1u);
  EXPECT_EQ(a.poses[0].position.y(), 3);
}

}  // namespace
}  // namespace urdfsnap::display
