// Every marker type's scene items: where and how large RViz's marker classes make them.
#include "display/marker_shapes.h"

#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/primitive_meshes.h"

namespace urdfsnap::display {
namespace {

using ::testing::HasSubstr;

Marker Make(int type) {
  Marker m;
  m.type = type;
  m.scale = {1, 0.1, 0.2};
  m.colour = {0.5f, 0.25f, 1, 1};
  return m;
}

scene::Scene Draw(const Marker& m, const Eigen::Isometry3d& X_FH = Eigen::Isometry3d::Identity(),
                  const MarkerResources& resources = {}) {
  scene::Scene scene;
  EXPECT_EQ(MarkerProblem(m), "");
  AddMarker(m, X_FH, resources, scene);
  return scene;
}

// The world-space extent of a draw item's unit mesh along each axis of the fixed frame.
Eigen::Vector3d Extent(const scene::DrawItem& item) {
  Eigen::AlignedBox3d box;
  for (const auto& p : item.mesh->positions) box.extend(item.X_FG * p.cast<double>());
  return box.sizes();
}

TEST(MarkerShapesTest, ShapesAreTheUnitMeshesAtFullScaleInTheMarkersPose) {
  Eigen::Isometry3d X_FH = Eigen::Isometry3d::Identity();
  X_FH.translation() = Eigen::Vector3d(1, 2, 3);
  for (const auto& [type, mesh] : {std::pair{Marker::kCube, scene::UnitBoxMesh()},
                                   std::pair{Marker::kSphere, scene::UnitSphereMesh()},
                                   std::pair{Marker::kCylinder, scene::UnitCylinderMesh()}}) {
    Marker m = Make(type);
    m.pose.position = {0.5, 0, 0};
    const scene::Scene scene = Draw(m, X_FH);
    ASSERT_EQ(scene.items.size(), 1u);
    EXPECT_EQ(scene.items[0].mesh, mesh);
    EXPECT_TRUE(scene.items[0].X_FG.translation().isApprox(Eigen::Vector3d(1.5, 2, 3)));
    EXPECT_TRUE(scene.items[0].X_FG.linear().isApprox(Eigen::Vector3d(1, 0.1, 0.2).asDiagonal().toDenseMatrix()));
    EXPECT_EQ(scene.items[0].rgba, m.colour);
  }
}

TEST(MarkerShapesTest, AZeroQuaternionIsTheIdentityAndOthersAreNormalised) {
  Pose pose;
  pose.orientation = Eigen::Quaterniond(0, 0, 0, 0);
  EXPECT_TRUE(MarkerPose(pose).linear().isIdentity());
  pose.orientation = Eigen::Quaterniond(0, 0, 0, 2);   // 180 degrees about z, twice too long
  EXPECT_TRUE(MarkerPose(pose).linear().isApprox(Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix()));
}

TEST(MarkerShapesTest, ArrowByPoseIsShaftAndHeadAlongX) {
  Marker m = Make(Marker::kArrow);   // scale (1, 0.1, 0.2)
  const scene::Scene scene = Draw(m);
  ASSERT_EQ(scene.items.size(), 2u);
  // arrow_marker.cpp: shaft 0.77 long, scale.y by scale.z thick; head 0.23 long, twice as thick
  EXPECT_TRUE(Extent(scene.items[0]).isApprox(Eigen::Vector3d(0.77, 0.1, 0.2), 1e-6));
  EXPECT_TRUE(scene.items[0].X_FG.translation().isApprox(Eigen::Vector3d(0.385, 0, 0)));
  EXPECT_TRUE(Extent(scene.items[1]).isApprox(Eigen::Vector3d(0.23, 0.2, 0.4), 1e-6));
  EXPECT_TRUE(scene.items[1].X_FG.translation().isApprox(Eigen::Vector3d(0.885, 0, 0)));
  EXPECT_EQ(scene.items[1].mesh, scene::UnitConeMesh());
}

TEST(MarkerShapesTest, ArrowByPointsRunsBetweenThemWithAClampedHead) {
  Marker m = Make(Marker::kArrow);
  m.points = {{0, 0, 0}, {0, 0, 2}};
  m.scale = {0.05, 0.1, 0};   // head length 0: 0.23 of the length
  scene::Scene scene = Draw(m);
  ASSERT_EQ(scene.items.size(), 2u);
  EXPECT_TRUE(Extent(scene.items[0]).isApprox(Eigen::Vector3d(0.05, 0.05, 2 - 0.46), 1e-6));
  EXPECT_TRUE(Extent(scene.items[1]).isApprox(Eigen::Vector3d(0.1, 0.1, 0.46), 1e-6));
  m.scale.z() = 5;   // longer than the arrow: the whole arrow is head
  scene = Draw(m);
  EXPECT_NEAR(Extent(scene.items[1]).z(), 2, 1e-6);
}

TEST(MarkerShapesTest, LinesAreRibbonsOfScaleXWithPerPointColours) {
  Marker strip = Make(Marker::kLineStrip);
  strip.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  strip.colours = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  scene::Scene scene = Draw(strip);
  ASSERT_EQ(scene.lines.size(), 1u);
  EXPECT_FLOAT_EQ(scene.lines[0].width, 1.0f);
  ASSERT_EQ(scene.lines[0].points.size(), 4u);   // two segments
  EXPECT_EQ(scene.lines[0].colours[2], Eigen::Vector4f(0, 1, 0, 1));
  EXPECT_EQ(scene.lines[0].points[3], Eigen::Vector3f(1, 1, 0));

  Marker list = Make(Marker::kLineList);
  list.points = strip.points;
  EXPECT_THAT(MarkerProblem(list), HasSubstr("odd number of points"));
  list.points.push_back({2, 2, 2});
  list.colours = {{1, 0, 0, 1}};   // not one per point: the marker's colour
  scene = Draw(list);
  ASSERT_EQ(scene.lines[0].points.size(), 4u);
  EXPECT_EQ(scene.lines[0].colours[3], list.colour);

  // billboard_line.cpp setColor: an opaque marker colour replaces (per-point alphas do not show);
  // a translucent one blends with each point's alpha
  strip.colours = {{1, 0, 0, 0}, {0, 1, 0, 0.5f}, {0, 0, 1, 1}};
  scene = Draw(strip);
  EXPECT_EQ(scene.lines[0].colours[0], Eigen::Vector4f(1, 0, 0, 1));
  EXPECT_EQ(scene.lines[0].colours[1], Eigen::Vector4f(0, 1, 0, 1));
  strip.colour.w() = 0.5f;
  scene = Draw(strip);
  EXPECT_EQ(scene.lines[0].colours[0], Eigen::Vector4f(1, 0, 0, 0));
  EXPECT_EQ(scene.lines[0].colours[1], Eigen::Vector4f(0, 1, 0, 0.5f));
}

TEST(MarkerShapesTest, PointsAreSquaresInMetresAndListsAreBoxesAndSpheres) {
  Marker points = Make(Marker::kPoints);
  points.points = {{1, 0, 0}, {2, 0, 0}};
  Eigen::Isometry3d X_FH = Eigen::Isometry3d::Identity();
  X_FH.translation() = Eigen::Vector3d(0, 0, 1);
  scene::Scene scene = Draw(points, X_FH);
  ASSERT_EQ(scene.points.size(), 1u);
  EXPECT_EQ(scene.points[0].style, scene::PointSet::Style::kSquares);
  EXPECT_EQ(scene.points[0].size, Eigen::Vector3f(1, 0.1f, 0));
  EXPECT_EQ(scene.points[0].positions[1], Eigen::Vector3f(2, 0, 1));
  EXPECT_EQ(scene.points[0].colours[1], points.colour);

  X_FH.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (const auto& [type, style] : {std::pair{Marker::kCubeList, scene::PointSet::Style::kBoxes},
                                    std::pair{Marker::kSphereList, scene::PointSet::Style::kSpheres}}) {
    Marker list = Make(type);
    list.points = points.points;
    list.colours = {{1, 0, 0, 0.5f}, {0, 1, 0, 1}};
    scene = Draw(list, X_FH);
    ASSERT_EQ(scene.points.size(), 1u);
    EXPECT_EQ(scene.points[0].style, style);
    EXPECT_EQ(scene.points[0].size, Eigen::Vector3f(1, 0.1f, 0.2f));
    EXPECT_TRUE(scene.points[0].box_axes.isApprox(X_FH.linear().cast<float>()));
    EXPECT_EQ(scene.points[0].colours[0], Eigen::Vector4f(1, 0, 0, 0.5f));
  }
}

// triangle_list_marker.cpp
TEST(MarkerShapesTest, TriangleListScalesPointsAndBlendsAsRvizDecides) {
  Marker m = Make(Marker::kTriangleList);
  m.scale = {2, 2, 2};
  m.colour.w() = 0.5f;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  // opaque colours per vertex: the material replaces, whatever the marker's alpha
  m.colours = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  scene::Scene scene = Draw(m);
  ASSERT_EQ(scene.triangles.size(), 1u);
  EXPECT_EQ(scene.triangles[0].positions[1], Eigen::Vector3f(2, 0, 0));
  EXPECT_EQ(scene.triangles[0].colours[2], Eigen::Vector4f(0, 0, 1, 1));
  // one translucent vertex: blended, each alpha the marker's times the colour's
  m.colours[1].w() = 0.5f;
  scene = Draw(m);
  EXPECT_EQ(scene.triangles[0].colours[1], Eigen::Vector4f(0, 1, 0, 0.25f));
  EXPECT_EQ(scene.triangles[0].colours[2], Eigen::Vector4f(0, 0, 1, 0.5f));
  // a colour per triangle: blended by the marker's alpha
  m.colours = {{1, 1, 0, 1}};
  scene = Draw(m);
  EXPECT_EQ(scene.triangles[0].colours[0], Eigen::Vector4f(1, 1, 0, 0.5f));
  m.points.pop_back();
  EXPECT_THAT(MarkerProblem(m), HasSubstr("not divisible by 3"));
}

// Without colours: lit in the marker's colour, each triangle both ways round with its own normal,
// so that the back (culling off in RViz) is lit from behind, black.
TEST(MarkerShapesTest, TriangleListWithoutColoursIsLitWithItsWindingsNormal) {
  Marker m = Make(Marker::kTriangleList);
  m.scale = {2, 2, 2};
  m.pose.position = {0, 0, 1};
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const scene::Scene scene = Draw(m);
  EXPECT_TRUE(scene.triangles.empty());
  ASSERT_EQ(scene.items.size(), 1u);
  EXPECT_EQ(scene.items[0].rgba, m.colour);
  EXPECT_TRUE(scene.items[0].X_FG.translation().isApprox(Eigen::Vector3d(0, 0, 1)));
  const geometry::TriangleMesh& mesh = *scene.items[0].mesh;
  EXPECT_EQ(mesh.positions[1], Eigen::Vector3f(2, 0, 0));
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 1}));
  for (const Eigen::Vector3f& n : mesh.normals) EXPECT_EQ(n, Eigen::Vector3f(0, 0, 1));
}

TEST(MarkerShapesTest, TextIsCentredOnThePoseAndScaleZHigh) {
  Marker m = Make(Marker::kTextViewFacing);
  m.text = "Hi";
  m.pose.position = {0, 0, 2};
  const scene::Scene scene = Draw(m);
  ASSERT_EQ(scene.labels.size(), 1u);
  EXPECT_TRUE(scene.labels[0].anchor.isApprox(Eigen::Vector3d(0, 0, 2)));
  float low = 1e9f, high = -1e9f, left = 1e9f, right = -1e9f;
  for (const auto& q : scene.labels[0].quads) {
    low = std::min(low, q.min.y()), high = std::max(high, q.max.y());
    left = std::min(left, q.min.x()), right = std::max(right, q.max.x());
  }
  EXPECT_NEAR(low, -0.1f, 1e-6);
  EXPECT_NEAR(high, 0.1f, 1e-6);
  EXPECT_NEAR(left, -right, 1e-6);
}

TEST(MarkerShapesTest, MeshResourceTakesTheMarkersColourOrTheFilesOwn) {
  auto file = std::make_shared<geometry::MeshFile>();
  geometry::MeshPart part;
  part.mesh = geometry::MakeUnitBox();
  part.diffuse = {0.1f, 0.2f, 0.3f, 1};
  file->parts.push_back(part);
  std::string asked;
  const MarkerResources resources{[&](const std::string& uri) {
    asked = uri;
    return file;
  }};
  Marker m = Make(Marker::kMeshResource);
  m.mesh_resource = "package://p/m.dae";
  scene::Scene scene = Draw(m, Eigen::Isometry3d::Identity(), resources);
  EXPECT_EQ(asked, "package://p/m.dae");
  ASSERT_EQ(scene.items.size(), 1u);
  EXPECT_EQ(scene.items[0].rgba, m.colour);
  EXPECT_TRUE(Extent(scene.items[0]).isApprox(Eigen::Vector3d(1, 0.1, 0.2), 1e-6));

  // with embedded materials: the colours of the items drawn for the marker in `colour`
  m.mesh_use_embedded_materials = true;
  using Colours = std::vector<Eigen::Vector4f>;
  const auto drawn = [&](const Eigen::Vector4f& colour) {
    m.colour = colour;
    Colours colours;
    for (const scene::DrawItem& item : Draw(m, Eigen::Isometry3d::Identity(), resources).items) colours.push_back(item.rgba);
    return colours;
  };
  EXPECT_EQ(drawn(Eigen::Vector4f::Zero()), Colours{part.diffuse});
  // mesh_resource_marker.cpp: the file's colours at the marker's alpha, tinted at min(a, 0.5)
  EXPECT_EQ(drawn({1, 0, 0, 1}), (Colours{part.diffuse, {1, 0, 0, 0.5f}}));
  EXPECT_EQ(drawn({1, 0, 0, 0.3f}), (Colours{{0.1f, 0.2f, 0.3f, 0.3f}, {1, 0, 0, 0.3f}}));
  // a sub-mesh without a material (STL) has Ogre's default white one, whose only pass is the tint
  file->parts[0].takes_urdf_material = true;
  EXPECT_EQ(drawn(Eigen::Vector4f::Zero()), Colours{Eigen::Vector4f::Ones()});
  EXPECT_EQ(drawn({0, 1, 0, 1}), Colours{Eigen::Vector4f(0, 1, 0, 1)});
  EXPECT_EQ(drawn({0, 1, 0, 0.8f}), Colours{Eigen::Vector4f(0, 1, 0, 0.5f)});

  const MarkerResources missing{[](const std::string& uri) -> std::shared_ptr<const geometry::MeshFile> {
    throw Error(uri + ": no such package");
  }};
  scene::Scene none;
  EXPECT_THROW(AddMarker(m, Eigen::Isometry3d::Identity(), missing, none), Error);
}

TEST(MarkerShapesTest, NonFiniteNumbersAndUnknownTypesAreRefused) {
  Marker m = Make(Marker::kCube);
  m.pose.position.x() = std::nan("");
  EXPECT_THAT(MarkerProblem(m), HasSubstr("nans or infs"));
  m = Make(Marker::kPoints);
  m.points = {{0, 0, std::numeric_limits<float>::infinity()}};
  EXPECT_THAT(MarkerProblem(m), HasSubstr("nans or infs"));
  EXPECT_THAT(MarkerProblem(Make(42)), HasSubstr("unknown marker type 42"));
}

}  // namespace
}  // namespace urdfsnap::display
