// Scene building: URDF visuals and collisions → DrawItems with RViz's shapes and colours
// (src/rviz/robot/robot_link.cpp createEntityForGeometryElement), plus the grid.
#include "render/scene_builder.h"

#include "common/error.h"
#include "render/link_colours.h"
#include "render/primitive_meshes.h"
#include "render/tf_markers.h"

namespace urdfsnap::render {

namespace {

Eigen::Isometry3d ToIsometry(const urdf::Pose& pose) {
  double x, y, z, w;
  pose.rotation.getQuaternion(x, y, z, w);
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

// The RViz mesh for a URDF primitive and the scale that sizes it (robot_link.cpp L580-609).
// Returns false for geometry this build cannot draw.
bool ShapeOf(const urdf::Geometry& geometry, std::shared_ptr<const geometry::TriangleMesh>& mesh,
             Eigen::Vector3d& scale) {
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      mesh = UnitBoxMesh();
      scale = {box.dim.x, box.dim.y, box.dim.z};
      return true;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      mesh = UnitCylinderMesh();
      scale = {2 * cylinder.radius, 2 * cylinder.radius, cylinder.length};
      return true;
    }
    case urdf::Geometry::SPHERE: {
      const auto& sphere = static_cast<const urdf::Sphere&>(geometry);
      mesh = UnitSphereMesh();
      scale = Eigen::Vector3d::Constant(2 * sphere.radius);
      return true;
    }
    default:
      return false;
  }
}

struct ShapeElement {
  const urdf::GeometrySharedPtr& geometry;
  const urdf::Pose& origin;
};

void AddShape(const model::Link& link, const ShapeElement& element, Eigen::Vector4f rgba,
              const Eigen::Isometry3d& X_FL, const SceneOptions& options, Scene& scene,
              Warnings& warnings) {
  if (!element.geometry) return;
  DrawItem item;
  Eigen::Vector3d scale;
  if (!ShapeOf(*element.geometry, item.mesh, scale)) {
    warnings.Add("link '" + link.name + "': mesh geometry is not drawn by this build");
    return;
  }
  item.X_FG = X_FL * ToIsometry(element.origin) * Eigen::Scaling(scale);
  rgba.w() *= static_cast<float>(options.alpha);
  item.rgba = rgba;
  item.link = link.name;
  scene.items.push_back(std::move(item));
}

}  // namespace

Scene BuildScene(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_RL,
                 const SceneOptions& options, Warnings& warnings) {
  Scene scene;
  scene.background = options.background;
  int fixed = 0;
  if (!options.fixed_frame.empty()) {
    fixed = robot.FindLink(options.fixed_frame);
    if (fixed < 0) {
      std::string names;
      for (const auto& link : robot.links()) names += (names.empty() ? "" : ", ") + link.name;
      throw Error("fixed frame '" + options.fixed_frame + "' is not a link of robot '" +
                  robot.name() + "' (links: " + names + ")");
    }
  }
  const Eigen::Isometry3d X_FR = X_RL[fixed].inverse();
  std::vector<Eigen::Isometry3d> X_FL(X_RL.size());
  for (size_t i = 0; i < X_RL.size(); ++i) X_FL[i] = X_FR * X_RL[i];
  for (size_t i = 0; i < robot.links().size(); ++i) {
    const model::Link& link = robot.links()[i];
    const LinkColours colours = ResolveLinkColours(*link.urdf);
    if (options.show_visual) {
      for (size_t v = 0; v < link.urdf->visual_array.size(); ++v) {
        const auto& visual = link.urdf->visual_array[v];
        AddShape(link, {visual->geometry, visual->origin}, colours.visuals[v], X_FL[i], options, scene,
                 warnings);
      }
    }
    if (options.show_collision) {
      for (const auto& collision : link.urdf->collision_array) {
        AddShape(link, {collision->geometry, collision->origin}, colours.collision, X_FL[i], options,
                 scene, warnings);
      }
    }
  }
  if (options.tf.enabled) AddTfMarkers(robot, X_FL, options.tf, scene);
  if (options.grid.enabled) scene.lines.push_back(MakeGrid(options.grid));
  return scene;
}

}  // namespace urdfsnap::render
