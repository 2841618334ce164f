// Scene building: URDF visuals and collisions → DrawItems with RViz's shapes and colours
// (src/rviz/robot/robot_link.cpp createEntityForGeometryElement), plus the grid.
#include "scene/scene_builder.h"

#include "common/error.h"
#include "geometry/mesh_file.h"
#include "geometry/mesh_uri.h"
#include "scene/link_colours.h"
#include "scene/primitive_meshes.h"
#include "scene/texture_file.h"
#include "scene/tf_markers.h"

namespace urdfsnap::scene {

namespace {

Eigen::Isometry3d ToIsometry(const urdf::Pose& pose) {
  double x, y, z, w;
  pose.rotation.getQuaternion(x, y, z, w);
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

// One drawn mesh of a URDF geometry element and its material.
struct Part {
  std::shared_ptr<const geometry::TriangleMesh> mesh;
  Eigen::Vector4f rgba;
  std::shared_ptr<const TextureImage> texture;
  Eigen::Vector3f emissive = Eigen::Vector3f::Zero();
};

// Runs `load` (which resolves or reads a file the model names); its error is reported at the
// link's element, or, with --allow-missing-meshes, becomes a warning saying what `instead` happens
// and the result is empty.
template <typename Load>
auto LoadForLink(const model::Link& link, const SceneOptions& options, Warnings& warnings,
                 const char* instead, Load load) -> decltype(load()) {
  const SourceLocation where{options.model_file, link.line};
  const std::string culprit = "link '" + link.name + "': ";
  try {
    return load();
  } catch (const Error& e) {
    if (!options.allow_missing_meshes) throw Error(where, culprit + e.what());
    warnings.Add(Error(where, culprit + e.what() + " (" + instead + ": --allow-missing-meshes)").what());
    return {};
  }
}

// The texture of a URDF material, found as mesh URIs are (RViz's resource_retriever); null for
// none, or when it is missing and missing files are allowed (the part is then drawn white).
std::shared_ptr<const TextureImage> UrdfTexture(const model::Link& link, const LinkMaterial& material,
                                                const SceneOptions& options, Warnings& warnings) {
  if (material.texture.empty()) return nullptr;
  return LoadForLink(link, options, warnings, "drawn without it", [&] {
    return LoadTextureFile(geometry::ResolveMeshUri(material.texture, options.model_file, options.packages));
  });
}

// A mesh file's sub-meshes: STL sub-meshes take the link's material, the others keep the file's
// own diffuse colour, emission and texture (robot_link.cpp: only BaseWhite/BaseWhiteNoLighting
// sub-meshes get it). Errors and warnings point at the link's element in the model file.
std::vector<Part> MeshParts(const model::Link& link, const urdf::Mesh& mesh, const Part& link_part,
                            const SceneOptions& options, Warnings& warnings) {
  const SourceLocation where{options.model_file, link.line};
  const std::string culprit = "link '" + link.name + "': ";
  const std::string path = LoadForLink(link, options, warnings, "not drawn", [&] {
    return geometry::ResolveMeshUri(mesh.filename, options.model_file, options.packages);
  });
  if (path.empty()) return {};
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
    throw Error(where, culprit + "mesh '" + mesh.filename + "': " + e.what());
  }
  std::vector<Part> parts;
  for (const auto& part : file->parts) {
    // the aliasing pointer keeps the whole cached file alive while the scene uses a part of it
    const std::shared_ptr<const geometry::TriangleMesh> shared(file, &part.mesh);
    if (part.takes_urdf_material) {
      parts.push_back({shared, link_part.rgba, link_part.texture});
      continue;
    }
    std::shared_ptr<const TextureImage> texture;
    if (!part.texture.empty()) {
      texture = LoadForLink(link, options, warnings, "drawn without it",
                            [&] { return LoadTextureFile(part.texture); });
    }
    parts.push_back({shared, part.diffuse, texture, part.emissive});
  }
  return parts;
}

// RViz's meshes for a URDF geometry and the scale that sizes them (robot_link.cpp L580-640).
std::vector<Part> PartsOf(const model::Link& link, const urdf::Geometry& geometry,
                          const LinkMaterial& material, const SceneOptions& options,
                          Eigen::Vector3d& scale, Warnings& warnings) {
  const Part link_part{nullptr, material.rgba, UrdfTexture(link, material, options, warnings)};
  const auto shape = [&](const std::shared_ptr<const geometry::TriangleMesh>& mesh) {
    Part part = link_part;
    part.mesh = mesh;
    return std::vector<Part>{part};
  };
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      scale = {box.dim.x, box.dim.y, box.dim.z};
      return shape(UnitBoxMesh());
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      scale = {2 * cylinder.radius, 2 * cylinder.radius, cylinder.length};
      return shape(UnitCylinderMesh());
    }
    case urdf::Geometry::SPHERE: {
      const auto& sphere = static_cast<const urdf::Sphere&>(geometry);
      scale = Eigen::Vector3d::Constant(2 * sphere.radius);
      return shape(UnitSphereMesh());
    }
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      scale = {mesh.scale.x, mesh.scale.y, mesh.scale.z};
      if (mesh.filename.empty()) return {};   // RViz skips it too
      return MeshParts(link, mesh, link_part, options, warnings);
    }
  }
  return {};
}

struct ShapeElement {
  const urdf::GeometrySharedPtr& geometry;
  const urdf::Pose& origin;
};

void AddShape(const model::Link& link, const ShapeElement& element, const LinkMaterial& material,
              const Eigen::Isometry3d& X_FL, const SceneOptions& options, Scene& scene,
              Warnings& warnings) {
  if (!element.geometry) return;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  for (auto& part : PartsOf(link, *element.geometry, material, options, scale, warnings)) {
    part.rgba.w() *= static_cast<float>(options.alpha);
    scene.items.push_back({std::move(part.mesh),
                           X_FL * ToIsometry(element.origin) * Eigen::Scaling(scale), part.rgba,
                           link.name, std::move(part.texture), part.emissive});
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

}  // namespace urdfsnap::scene
