// Scene building: URDF visuals and collisions → DrawItems with RViz's shapes and colours
// (src/rviz/robot/robot_link.cpp createEntityForGeometryElement), plus the grid.
#include "render/scene_builder.h"

#include "common/error.h"
#include "geometry/mesh_file.h"
#include "geometry/mesh_uri.h"
#include "render/link_colours.h"
#include "render/mesh_prefetch.h"
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

// One drawn mesh of a URDF geometry element and its colour.
struct Part {
  std::shared_ptr<const geometry::TriangleMesh> mesh;
  Eigen::Vector4f rgba;
};

// A mesh file's sub-meshes: STL sub-meshes take the link's material, the others keep the file's
// own diffuse colour (robot_link.cpp: only BaseWhite/BaseWhiteNoLighting sub-meshes get it).
// Errors and warnings point at the link's element in the model file.
std::vector<Part> MeshParts(const model::Link& link, const urdf::Mesh& mesh,
                            const Eigen::Vector4f& link_rgba, const SceneOptions& options,
                            Warnings& warnings) {
  const SourceLocation where{options.model_file, link.line};
  const std::string culprit = "link '" + link.name + "': ";
  std::string path;
  try {
    path = geometry::ResolveMeshUri(mesh.filename, options.model_file, options.packages);
  } catch (const Error& e) {
    if (!options.allow_missing_meshes) throw Error(where, culprit + e.what());
    warnings.Add(Error(where, culprit + e.what() + " (not drawn: --allow-missing-meshes)").what());
    return {};
  }
  if (geometry::IsPlainPath(mesh.filename)) {
    // one warning per model (the collector drops repeats), not one per mesh
    warnings.Add(Error(SourceLocation{options.model_file},
                       "mesh filenames without package:// or file:// are found by urdfsnap, "
                       "but not by RViz and other ROS tools")
                     .what());
  }
  std::shared_ptr<const geometry::MeshFile> file;
  try {
    file = geometry::LoadMeshFile(path);
  } catch (const Error& e) {
    throw Error(where, culprit + e.what());
  }
  std::vector<Part> parts;
  for (const auto& part : file->parts) {
    // the aliasing pointer keeps the whole cached file alive while the scene uses a part of it
    parts.push_back({std::shared_ptr<const geometry::TriangleMesh>(file, &part.mesh),
                     part.takes_urdf_material ? link_rgba : part.diffuse});
  }
  return parts;
}

// RViz's meshes for a URDF geometry and the scale that sizes them (robot_link.cpp L580-640).
std::vector<Part> PartsOf(const model::Link& link, const urdf::Geometry& geometry,
                          const Eigen::Vector4f& rgba, const SceneOptions& options,
                          Eigen::Vector3d& scale, Warnings& warnings) {
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      scale = {box.dim.x, box.dim.y, box.dim.z};
      return {{UnitBoxMesh(), rgba}};
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      scale = {2 * cylinder.radius, 2 * cylinder.radius, cylinder.length};
      return {{UnitCylinderMesh(), rgba}};
    }
    case urdf::Geometry::SPHERE: {
      const auto& sphere = static_cast<const urdf::Sphere&>(geometry);
      scale = Eigen::Vector3d::Constant(2 * sphere.radius);
      return {{UnitSphereMesh(), rgba}};
    }
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      scale = {mesh.scale.x, mesh.scale.y, mesh.scale.z};
      if (mesh.filename.empty()) return {};   // RViz skips it too
      return MeshParts(link, mesh, rgba, options, warnings);
    }
  }
  return {};
}

struct ShapeElement {
  const urdf::GeometrySharedPtr& geometry;
  const urdf::Pose& origin;
};

void AddShape(const model::Link& link, const ShapeElement& element, const Eigen::Vector4f& rgba,
              const Eigen::Isometry3d& X_FL, const SceneOptions& options, Scene& scene,
              Warnings& warnings) {
  if (!element.geometry) return;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  for (auto& part : PartsOf(link, *element.geometry, rgba, options, scale, warnings)) {
    part.rgba.w() *= static_cast<float>(options.alpha);
    scene.items.push_back({std::move(part.mesh),
                           X_FL * ToIsometry(element.origin) * Eigen::Scaling(scale), part.rgba,
                           link.name});
  }
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
  PrefetchMeshFiles(robot, options);
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
