// RobotScene: URDF visuals and collisions → LinkParts with RViz's shapes and colours
// (src/rviz/robot/robot_link.cpp createEntityForGeometryElement), prepared once; per frame the
// parts are placed, and the TF markers and the grid added.
#include "scene/robot_scene.h"

#include <map>
#include <set>
#include <variant>

#include "common/error.h"
#include "common/number_text.h"
#include "geometry/mesh_uri.h"
#include "scene/link_colours.h"
#include "geometry/mesh_loading.h"
#include "scene/primitive_meshes.h"
#include "texture/texture_file.h"

namespace urdfsnap::scene {

namespace {

// One shape element the displays show: a visual with its material, or a collision shape.
struct ShownShape {
  const model::Link* link;
  int link_index;
  const model::Shape* shape;
  const Eigen::Isometry3d* X_LG;
  LinkMaterial material;
};

// The shape elements of the robot the options show, in link order, visuals before collisions.
std::vector<ShownShape> ShownShapes(const model::Robot& robot, const SceneOptions& options) {
  std::vector<ShownShape> shown;
  for (size_t i = 0; i < robot.links().size(); ++i) {
    const model::Link& link = robot.links()[i];
    const LinkColours colours = ResolveLinkColours(link);
    const int index = static_cast<int>(i);
    if (options.show_visual) {
      for (size_t v = 0; v < link.visuals.size(); ++v) {
        shown.push_back({&link, index, &link.visuals[v].shape, &link.visuals[v].X_LG, colours.visuals[v]});
      }
    }
    if (options.show_collision) {
      for (const auto& collision : link.collisions) {
        shown.push_back({&link, index, &collision.shape, &collision.X_LG, colours.collision});
      }
    }
  }
  return shown;
}

// Resolves and loads the files of one robot: mesh URIs to paths, meshes (all at once, on every
// core) and textures, with errors located at the link that names the file.
class FileLoader {
 public:
  FileLoader(const SceneOptions& options, Warnings& warnings) : options_(options), warnings_(warnings) {}

  // Resolves the mesh URI of every shown mesh shape and loads the files in parallel; errors wait
  // until the shape that needs them is built, so they are reported at the first link in order.
  void Prefetch(const std::vector<ShownShape>& shapes) {
    std::set<std::string> paths;
    for (const ShownShape& s : shapes) {
      if (s.shape->type != model::Shape::Type::kMesh || s.shape->mesh_uri.empty()) continue;
      try {
        paths.insert(ResolvedPath(s.shape->mesh_uri));
      } catch (const Error&) {
        // reported when the shape is built
      }
    }
    meshes_ = geometry::LoadMeshFiles(paths);
  }

  // The mesh file of `uri` for `link`; null when it is missing and missing files are allowed.
  std::shared_ptr<const geometry::MeshFile> Mesh(const model::Link& link, const std::string& uri) {
    const std::string path = ForLink(link, "not drawn", [&] { return ResolvedPath(uri); });
    if (path.empty()) return nullptr;
    if (geometry::IsPlainPath(uri)) {
      // one warning per model (the collector drops repeats), not one per mesh
      warnings_.Add(Error(SourceLocation{options_.model_file},
                          "mesh filenames without package:// or file:// are found by urdfsnap, "
                          "but not by RViz and other ROS tools")
                        .what());
    }
    const geometry::MeshLoad& load = meshes_.at(path);
    if (load.error) {
      try {
        std::rethrow_exception(load.error);
      } catch (const Error& e) {
        // a broken file is an error even with --allow-missing-meshes
        throw Error(SourceLocation{options_.model_file, link.line},
                    "link '" + link.name + "': mesh '" + uri + "': " + e.what());
      }
    }
    Use(path);
    return load.file;
  }

  // The texture at `uri` (a URDF material's, resolved as mesh URIs are) or at `path` (a mesh
  // material's, already a path). When it is missing and missing files are allowed: Ogre's warning
  // texture, which RViz shows for a texture it cannot load (robot_link.cpp and mesh_loader.cpp
  // name the image to Ogre even when loading it failed).
  std::shared_ptr<const texture::TextureImage> Texture(const model::Link& link, const std::string& uri, bool is_uri) {
    return ForLink(
        link, "drawn with Ogre's warning texture, as RViz draws it",
        [&] {
          const std::string path = is_uri ? geometry::ResolveMeshUri(uri, options_.model_file, options_.packages) : uri;
          std::shared_ptr<const texture::TextureImage> texture = texture::LoadTextureFile(path);
          Use(path);
          return texture;
        },
        texture::WarningTexture());
  }

  // The image the texture units of a mesh part's own material show (geometry::MeshPart): the
  // diffuse map's file, or, for a material whose maps include no diffuse map in a file, Ogre's
  // warning texture with a warning (RViz names an image that cannot exist to its units).
  std::shared_ptr<const texture::TextureImage> UnitTexture(const model::Link& link, const std::string& mesh_uri,
                                                  const geometry::MeshPart& part) {
    if (!part.texture.empty()) return Texture(link, part.texture, false);
    warnings_.Add(Error(SourceLocation{options_.model_file, link.line},
                        "link '" + link.name + "': mesh '" + mesh_uri +
                            "': a material has texture maps but no diffuse map in a file; RViz draws "
                            "it with Ogre's yellow and black warning texture, and so does urdfsnap")
                      .what());
    return texture::WarningTexture();
  }

  std::vector<std::string> TakeFiles() { return std::move(files_); }

 private:
  std::string ResolvedPath(const std::string& uri) {
    auto it = resolved_.find(uri);
    if (it == resolved_.end()) {
      try {
        it = resolved_.emplace(uri, geometry::ResolveMeshUri(uri, options_.model_file, options_.packages)).first;
      } catch (const Error&) {
        it = resolved_.emplace(uri, std::current_exception()).first;
      }
    }
    if (auto* error = std::get_if<std::exception_ptr>(&it->second)) std::rethrow_exception(*error);
    return std::get<std::string>(it->second);
  }

  // Runs `load`; its error is reported at the link's element, or, with allow_missing_meshes,
  // becomes a warning saying what `instead` happens, and the result is `fallback`.
  template <typename Load>
  auto ForLink(const model::Link& link, const char* instead, Load load, decltype(load()) fallback = {})
      -> decltype(load()) {
    const SourceLocation where{options_.model_file, link.line};
    const std::string culprit = "link '" + link.name + "': ";
    try {
      return load();
    } catch (const Error& e) {
      if (!options_.allow_missing_meshes) throw Error(where, culprit + e.what());
      warnings_.Add(Error(where, culprit + e.what() + " (" + instead + ": --allow-missing-meshes)").what());
      return fallback;
    }
  }

  void Use(const std::string& path) {
    if (used_.insert(path).second) files_.push_back(path);
  }

  const SceneOptions& options_;
  Warnings& warnings_;
  std::map<std::string, std::variant<std::string, std::exception_ptr>> resolved_;   // by URI
  std::map<std::string, geometry::MeshLoad> meshes_;                                         // by path
  std::set<std::string> used_;
  std::vector<std::string> files_;
};

// RViz's meshes for a shape, sized by `scale` (robot_link.cpp L580-640), with their looks: STL
// sub-meshes take the link's material, the others keep the file's own diffuse colour, emission
// and texture (robot_link.cpp: only BaseWhite/BaseWhiteNoLighting sub-meshes get it).
std::vector<LinkPart> PartsOf(const ShownShape& s, FileLoader& files) {
  LinkPart link_part;
  link_part.link = s.link_index;
  link_part.rgba = s.material.rgba;
  if (!s.material.texture.empty()) link_part.texture = files.Texture(*s.link, s.material.texture, true);
  const model::Shape& shape = *s.shape;
  const auto one = [&](std::shared_ptr<const geometry::TriangleMesh> mesh, const Eigen::Vector3d& scale) {
    link_part.mesh = std::move(mesh);
    link_part.X_LG = *s.X_LG * Eigen::Scaling(scale);
    return std::vector<LinkPart>{link_part};
  };
  switch (shape.type) {
    case model::Shape::Type::kBox: return one(UnitBoxMesh(), shape.box_size);
    case model::Shape::Type::kCylinder:
      return one(UnitCylinderMesh(), {2 * shape.radius, 2 * shape.radius, shape.length});
    case model::Shape::Type::kSphere: return one(UnitSphereMesh(), Eigen::Vector3d::Constant(2 * shape.radius));
    case model::Shape::Type::kMesh: break;
  }
  if (shape.mesh_uri.empty()) return {};   // RViz skips it too
  const std::shared_ptr<const geometry::MeshFile> file = files.Mesh(*s.link, shape.mesh_uri);
  if (!file) return {};
  std::vector<LinkPart> parts;
  for (const auto& part : file->parts) {
    LinkPart p = link_part;
    // the aliasing pointer keeps the whole file alive while a part of it is used
    p.mesh = std::shared_ptr<const geometry::TriangleMesh>(file, &part.mesh);
    p.X_LG = *s.X_LG * Eigen::Scaling(shape.mesh_scale);
    if (!part.takes_urdf_material) {
      p.rgba = part.diffuse;
      p.emissive = part.emissive;
      p.texture_units = part.texture_units;
      p.texture = part.texture_units > 0 ? files.UnitTexture(*s.link, shape.mesh_uri, part) : nullptr;
    }
    parts.push_back(std::move(p));
  }
  return parts;
}

// The links' names, for messages: "base, arm".
std::string LinkNames(const model::Robot& robot) {
  std::string names;
  for (const auto& link : robot.links()) names += (names.empty() ? "" : ", ") + link.name;
  return names;
}

// RobotModel alpha times the link's own alpha (options.link_alpha), one per robot.links().
std::vector<float> LinkAlphas(const model::Robot& robot, const SceneOptions& options) {
  std::vector<float> alphas(robot.links().size(), static_cast<float>(options.alpha));
  for (const auto& [name, alpha] : options.link_alpha) {
    const int link = robot.FindLink(name);
    if (link < 0) {
      throw Error("link alpha for '" + name + "', which is not a link of robot '" + robot.name() +
                  "' (links: " + LinkNames(robot) + ")");
    }
    if (!(alpha >= 0 && alpha <= 1)) {
      throw Error("link alpha for '" + name + "' is " + FormatNumber(alpha) + "; expected 0 to 1");
    }
    alphas[link] *= static_cast<float>(alpha);
  }
  return alphas;
}

int FixedLink(const model::Robot& robot, const std::string& fixed_frame) {
  if (fixed_frame.empty()) return 0;
  const int fixed = robot.FindLink(fixed_frame);
  if (fixed < 0) {
    throw Error("fixed frame '" + fixed_frame + "' is not a link of robot '" + robot.name() +
                "' (links: " + LinkNames(robot) + ")");
  }
  return fixed;
}

// Asking for collision (or visual) geometry that the robot does not have draws nothing of it: say
// so rather than leave the user to wonder whether the option took.
void WarnOfShapesNotThere(const model::Robot& robot, const SceneOptions& options, Warnings& warnings) {
  bool visuals = false, collisions = false;
  for (const model::Link& link : robot.links()) {
    visuals = visuals || !link.visuals.empty();
    collisions = collisions || !link.collisions.empty();
  }
  if (options.show_collision && !collisions) {
    warnings.Add("collision geometry is shown, but robot '" + robot.name() + "' has none (no link has a <collision>)");
  }
  if (options.show_visual && !visuals && !options.show_collision) {
    warnings.Add("robot '" + robot.name() + "' has no visual geometry (no link has a <visual>); --collision shows "
                 "its collision geometry");
  }
}

}  // namespace

RobotScene::RobotScene(const model::Robot& robot, SceneOptions options, Warnings& warnings)
    : robot_(robot), options_(std::move(options)), fixed_link_(FixedLink(robot, options_.fixed_frame)) {
  const std::vector<float> alphas = LinkAlphas(robot_, options_);
  const std::vector<ShownShape> shapes = ShownShapes(robot_, options_);
  WarnOfShapesNotThere(robot_, options_, warnings);
  FileLoader files(options_, warnings);
  files.Prefetch(shapes);
  for (const ShownShape& shape : shapes) {
    for (LinkPart& part : PartsOf(shape, files)) {
      part.rgba.w() *= alphas[part.link];
      parts_.push_back(std::move(part));
    }
  }
  files_ = files.TakeFiles();
  if (options_.tf.enabled && options_.tf.show_names) tf_names_ = MakeTfNameLabels(robot_, options_.tf);
  if (options_.tf.enabled) tf_parents_ = robot_.ParentLinks();
}

std::size_t RobotScene::triangle_count() const {
  std::size_t triangles = 0;
  for (const LinkPart& part : parts_) triangles += part.mesh->indices.size() / 3;
  return triangles;
}

std::vector<Eigen::Isometry3d> RobotScene::LinkPoses(const std::vector<Eigen::Isometry3d>& X_RL,
                                                     const Eigen::Isometry3d& X_SF) const {
  const Eigen::Isometry3d X_SR = X_SF * X_RL[fixed_link_].inverse();
  std::vector<Eigen::Isometry3d> X_SL(X_RL.size());
  for (size_t i = 0; i < X_RL.size(); ++i) X_SL[i] = X_SR * X_RL[i];
  return X_SL;
}

Scene RobotScene::Pose(const std::vector<Eigen::Isometry3d>& X_RL,
                       const Eigen::Isometry3d& X_SF) const {
  if (X_RL.size() != robot_.links().size()) {
    throw Error("RobotScene::Pose: " + std::to_string(X_RL.size()) + " link poses for " +
                std::to_string(robot_.links().size()) + " links");
  }
  Scene scene;
  scene.background = options_.background;
  // (X_FL below is in the scene's frame S, which is F's unless X_SF says otherwise)
  const std::vector<Eigen::Isometry3d> X_FL = LinkPoses(X_RL, X_SF);
  scene.items.reserve(parts_.size());
  for (const LinkPart& part : parts_) {
    scene.items.push_back({part.mesh, X_FL[part.link] * part.X_LG, part.rgba, part.link, part.texture,
                           part.texture_units, part.emissive});
  }
  if (options_.tf.enabled) AddTfFrames(X_FL, tf_parents_, options_.tf, tf_names_, scene);
  if (options_.grid.enabled) scene.lines.push_back(MakeGrid(options_.grid));
  return scene;
}

}  // namespace urdfsnap::scene
