// Each marker type's geometry, following the RViz 1.14 marker class named at each function.
#include "display/marker_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "display/arrow_shapes.h"
#include "texture/glyph_atlas.h"
#include "texture/texture_file.h"
#include "scene/primitive_meshes.h"
#include "scene/text_layout.h"

namespace urdfsnap::display {
namespace {

// Below this alpha RViz's marker materials blend and stop writing depth (Ogre's SBT_TRANSPARENT_ALPHA)
constexpr float kOpaqueAlpha = 0.9998f;

bool Finite(const Eigen::Vector3d& v) { return v.allFinite(); }

void AddShape(const std::shared_ptr<const geometry::TriangleMesh>& mesh, const Eigen::Affine3d& X_FG,
              const Eigen::Vector4f& rgba, scene::Scene& scene) {
  scene.items.push_back({mesh, X_FG, rgba, -1, nullptr, 1, Eigen::Vector3f::Zero()});
}

// Per-point colours when there is one per point (every marker class tests colors.size() ==
// points.size()), else the marker's colour.
Eigen::Vector4f PointColour(const Marker& m, size_t i) {
  return m.colours.size() == m.points.size() ? m.colours[i] : m.colour;
}

// arrow_marker.cpp: with two points the arrow runs from the first to the second (both in the
// marker's frame), scale.x the shaft's diameter, scale.y the head's, scale.z the head's length
// (0: 0.23 of the length; clamped to the length); without points it starts at the pose, points
// along its +x and is scale.x long: shaft 0.77, head 0.23 of it, diameters scale.y and scale.z
// (the head twice those).
void AddArrowMarker(const Marker& m, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  if (m.points.size() != 2) {
    const ArrowSize size{0.77 * m.scale.x(), {m.scale.y(), m.scale.z()}, 0.23 * m.scale.x(),
                         {2 * m.scale.y(), 2 * m.scale.z()}};
    AddArrow(X_FM, size, m.colour, scene);
    return;
  }
  const Eigen::Vector3d p0 = m.points[0].cast<double>(), p1 = m.points[1].cast<double>();
  const double length = (p1 - p0).norm();
  if (length <= 0) return;
  const double head = m.scale.z() != 0 ? std::clamp(m.scale.z(), 0.0, length) : 0.23 * length;
  Eigen::Isometry3d X_MA = Eigen::Isometry3d::Identity();
  X_MA.translation() = p0;
  X_MA.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), p1 - p0).toRotationMatrix();
  AddArrow(X_FM * X_MA,
           {length - head, {m.scale.x(), m.scale.x()}, head, {m.scale.y(), m.scale.y()}}, m.colour, scene);
}

// line_strip_marker.cpp, line_list_marker.cpp: a BillboardLine of width scale.x through the
// points (a strip joins neighbours, a list pairs them). BillboardLine::setColor blends only when
// the marker's own alpha is below 0.9998; otherwise its material replaces what is behind, so
// per-point alphas (often a ColorRGBA left at its default 0) do not show.
void AddLineMarker(const Marker& m, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  const bool blended = m.colour.w() < kOpaqueAlpha;
  scene::LineSet lines;
  lines.rgba = m.colour;
  lines.width = static_cast<float>(m.scale.x());
  const Eigen::Affine3f X = X_FM.cast<float>();
  const auto add = [&](size_t i) {
    lines.points.push_back(X * m.points[i]);
    Eigen::Vector4f colour = PointColour(m, i);
    if (!blended) colour.w() = 1;
    lines.colours.push_back(colour);
  };
  if (m.type == Marker::kLineList) {
    for (size_t i = 0; i < m.points.size(); ++i) add(i);
  } else {
    for (size_t i = 1; i < m.points.size(); ++i) {
      add(i - 1);
      add(i);
    }
  }
  if (!lines.points.empty()) scene.lines.push_back(std::move(lines));
}

// points_marker.cpp: POINTS, CUBE_LIST and SPHERE_LIST are RViz point clouds in the marker's
// frame: POINTS camera-facing squares of scale.x by scale.y metres with RViz's Squares material
// (RM_SQUARES), the lists boxes (turned with the marker) and spheres of size scale (RM_BOXES,
// RM_SPHERES).
void AddPointList(const Marker& m, const Eigen::Isometry3d& X_FM, scene::PointSet::Style style,
                  scene::Scene& scene) {
  scene::PointSet points;
  points.style = style;
  points.size = m.scale.cast<float>();
  if (style == scene::PointSet::Style::kSquares) points.size.z() = 0;
  points.box_axes = X_FM.linear().cast<float>();
  const Eigen::Affine3f X = X_FM.cast<float>();
  points.positions.reserve(m.points.size());
  points.colours.reserve(m.points.size());
  for (size_t i = 0; i < m.points.size(); ++i) {
    points.positions.push_back(X * m.points[i]);
    points.colours.push_back(PointColour(m, i));
  }
  if (!points.positions.empty()) scene.points.push_back(std::move(points));
}

// triangle_list_marker.cpp without colours: a lit material of the marker's colour, culling off
// and each triangle's normal from its winding (LitTriangleMesh), drawn at the marker's pose.
void AddLitTriangles(const Marker& m, const MarkerMeshes& meshes, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  AddShape(meshes.lit_triangles ? meshes.lit_triangles : LitTriangleMesh(m), Eigen::Affine3d(X_FM), m.colour, scene);
}

// Whether a TRIANGLE_LIST has a colour per vertex or per triangle (and is drawn unlit).
bool Coloured(const Marker& m) {
  return m.colours.size() == m.points.size() || m.colours.size() == m.points.size() / 3;
}

// triangle_list_marker.cpp: every three points one triangle, the points scaled by scale. With a
// colour per vertex or per triangle: unlit, seen from both sides, alpha the marker's times the
// colour's, blended only when (per vertex) a vertex's own alpha or (per triangle) the marker's is
// below 0.9998, else the material replaces and alpha does not show. Without: lit (AddLitTriangles).
void AddTriangleList(const Marker& m, const MarkerMeshes& meshes, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  const size_t count = m.points.size();
  if (!Coloured(m)) {
    AddLitTriangles(m, meshes, X_FM, scene);
    return;
  }
  const bool per_vertex = m.colours.size() == count, per_face = !per_vertex && m.colours.size() == count / 3;
  const auto colour_of = [&](size_t i) { return m.colours[per_vertex ? i : i / 3]; };
  bool blended = per_face && m.colour.w() < kOpaqueAlpha;
  for (size_t i = 0; per_vertex && i < count; ++i) blended = blended || colour_of(i).w() < kOpaqueAlpha;
  scene::FlatTriangles triangles;
  const Eigen::Affine3f X = (X_FM * Eigen::Scaling(m.scale)).cast<float>();
  triangles.positions.reserve(count);
  triangles.colours.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    triangles.positions.push_back(X * m.points[i]);
    Eigen::Vector4f colour = colour_of(i);
    colour.w() = blended ? m.colour.w() * colour.w() : 1.f;
    triangles.colours.push_back(colour);
  }
  if (!triangles.positions.empty()) scene.triangles.push_back(std::move(triangles));
}

// text_view_facing_marker.cpp: MovableText in Liberation Sans, scale.z high, its block of lines
// centred horizontally and vertically on the pose (H_CENTER, V_CENTER), in the marker's colour.
void AddText(const Marker& m, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  if (m.text.empty()) return;
  const auto atlas = texture::BuildGlyphAtlas(texture::FindLiberationSans(), scene::CodePointsOf({m.text}));
  const float height = static_cast<float>(m.scale.z());
  // the label's texture shares the atlas's ownership, so that whoever keeps the label's texture
  // keeps the atlas (and BuildGlyphAtlas returns it again rather than rasterising anew)
  scene.labels.push_back({std::shared_ptr<const texture::TextureImage>(atlas, atlas->texture.get()),
                          scene::LayOutText(*atlas, m.text, height, scene::TextAnchor::kCentre), X_FM.translation(),
                          m.colour});
}

// The image a mesh part's own material shows in its texture units (mesh_loader.cpp, as for the
// robot's meshes: geometry::MeshPart), Ogre's warning texture when no diffuse map names a file;
// none without texture units. Throws when the file cannot be read.
std::shared_ptr<const texture::TextureImage> PartTexture(const geometry::MeshPart& part) {
  if (part.texture_units == 0) return nullptr;
  return part.texture.empty() ? texture::WarningTexture() : texture::LoadTextureFile(part.texture);
}

// mesh_resource_marker.cpp: the file's sub-meshes scaled by scale. Without embedded materials
// every sub-mesh takes the marker's colour. With them, a colour of (0, 0, 0, 0) leaves the file's
// own colours and textures (sub-meshes without a material, as in STL files, Ogre's default
// white); any other colour ("update_color") gives each file material the marker's alpha and a
// second, blended tint pass of the marker's colour at alpha min(a, 0.5), and the default
// material, whose one pass is also its tint pass, the marker's colour: opaque when a >= 0.9998
// (scene blending replace), else blended at min(a, 0.5).
void AddMesh(const Marker& m, const Eigen::Isometry3d& X_FM, const MarkerResources& resources,
             scene::Scene& scene) {
  const std::shared_ptr<const geometry::MeshFile> file = resources.load_mesh(m.mesh_resource);
  const Eigen::Affine3d X_FG = X_FM * Eigen::Scaling(m.scale);
  const bool recolour = m.colour != Eigen::Vector4f::Zero();
  const float alpha = m.colour.w();
  Eigen::Vector4f tint = m.colour;
  tint.w() = std::min(alpha, 0.5f);
  for (const geometry::MeshPart& part : file->parts) {
    const std::shared_ptr<const geometry::TriangleMesh> mesh(file, &part.mesh);
    if (!m.mesh_use_embedded_materials) {
      AddShape(mesh, X_FG, m.colour, scene);
    } else if (part.takes_urdf_material) {
      Eigen::Vector4f own = Eigen::Vector4f::Ones();
      if (recolour) own << m.colour.head<3>(), alpha >= kOpaqueAlpha ? 1.f : tint.w();
      AddShape(mesh, X_FG, own, scene);
    } else {
      Eigen::Vector4f own = part.diffuse;
      if (recolour) own.w() = alpha;
      scene.items.push_back({mesh, X_FG, own, -1, PartTexture(part), part.texture_units, part.emissive});
      if (recolour) AddShape(mesh, X_FG, tint, scene);
    }
  }
}

}  // namespace

std::shared_ptr<const geometry::TriangleMesh> LitTriangleMesh(const Marker& m) {
  auto mesh = std::make_shared<geometry::TriangleMesh>();
  const Eigen::Vector3f scale = m.scale.cast<float>();
  for (size_t i = 0; i + 2 < m.points.size(); i += 3) {
    const Eigen::Vector3f a = m.points[i].cwiseProduct(scale), b = m.points[i + 1].cwiseProduct(scale),
                          c = m.points[i + 2].cwiseProduct(scale);
    const Eigen::Vector3f normal = (b - a).cross(c - a).normalized();
    for (const Eigen::Vector3f& p : {a, b, c}) {
      mesh->positions.push_back(p);
      mesh->normals.push_back(normal);
    }
    const auto first = static_cast<std::uint32_t>(mesh->positions.size() - 3);
    mesh->indices.insert(mesh->indices.end(), {first, first + 1, first + 2, first, first + 2, first + 1});
  }
  return mesh;
}

MarkerMeshes MakeMarkerMeshes(const Marker& m) {
  MarkerMeshes meshes;
  if (m.type == Marker::kTriangleList && !Coloured(m)) meshes.lit_triangles = LitTriangleMesh(m);
  return meshes;
}

Eigen::Isometry3d MarkerPose(const Pose& pose) {
  Eigen::Quaterniond q = pose.orientation;
  if (q.coeffs().isZero()) q = Eigen::Quaterniond::Identity();
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = q.normalized().toRotationMatrix();
  X.translation() = pose.position;
  return X;
}

std::string MarkerProblem(const Marker& m) {
  bool finite = Finite(m.pose.position) && m.pose.orientation.coeffs().allFinite() && Finite(m.scale) &&
                m.colour.allFinite();
  for (const auto& p : m.points) finite = finite && p.allFinite();
  for (const auto& c : m.colours) finite = finite && c.allFinite();
  if (!finite) return "contains invalid floating point values (nans or infs)";
  switch (m.type) {
    case Marker::kArrow:
      if (!m.points.empty() && m.points.size() != 2) {
        return "an arrow marker takes 0 or 2 points, not " + std::to_string(m.points.size());
      }
      return "";
    case Marker::kLineList:
      return m.points.size() % 2 == 0 ? "" : "a line list marker has an odd number of points";
    case Marker::kTriangleList:
      return m.points.size() % 3 == 0 ? ""
                                      : "a triangle list marker has a point count not divisible by 3 (" +
                                            std::to_string(m.points.size()) + ")";
    case Marker::kMeshResource:
      return m.mesh_resource.empty() ? "a mesh resource marker names no mesh_resource" : "";
    case Marker::kCube: case Marker::kSphere: case Marker::kCylinder: case Marker::kLineStrip:
    case Marker::kCubeList: case Marker::kSphereList: case Marker::kPoints: case Marker::kTextViewFacing:
      return "";
    default:
      return "unknown marker type " + std::to_string(m.type);
  }
}

void AddMarker(const Marker& m, const Eigen::Isometry3d& X_FH, const MarkerResources& resources,
               scene::Scene& scene) {
  AddMarker(m, MarkerMeshes{}, X_FH, resources, scene);
}

void AddMarker(const Marker& m, const MarkerMeshes& meshes, const Eigen::Isometry3d& X_FH,
               const MarkerResources& resources, scene::Scene& scene) {
  const Eigen::Isometry3d X_FM = X_FH * MarkerPose(m.pose);
  // shape_marker.cpp: the unit cube, sphere and cylinder (axis z) scaled to full size
  const Eigen::Affine3d X_FS = X_FM * Eigen::Scaling(m.scale);
  switch (m.type) {
    case Marker::kArrow: AddArrowMarker(m, X_FM, scene); break;
    case Marker::kCube: AddShape(scene::UnitBoxMesh(), X_FS, m.colour, scene); break;
    case Marker::kSphere: AddShape(scene::UnitSphereMesh(), X_FS, m.colour, scene); break;
    case Marker::kCylinder: AddShape(scene::UnitCylinderMesh(), X_FS, m.colour, scene); break;
    case Marker::kLineStrip: case Marker::kLineList: AddLineMarker(m, X_FM, scene); break;
    case Marker::kCubeList: AddPointList(m, X_FM, scene::PointSet::Style::kBoxes, scene); break;
    case Marker::kSphereList: AddPointList(m, X_FM, scene::PointSet::Style::kSpheres, scene); break;
    case Marker::kPoints: AddPointList(m, X_FM, scene::PointSet::Style::kSquares, scene); break;
    case Marker::kTextViewFacing: AddText(m, X_FM, scene); break;
    case Marker::kMeshResource: AddMesh(m, X_FM, resources, scene); break;
    case Marker::kTriangleList: AddTriangleList(m, meshes, X_FM, scene); break;
    default: break;   // MarkerProblem refuses unknown types
  }
}

}  // namespace urdfsnap::display
