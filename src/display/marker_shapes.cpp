// Each marker type's geometry, following the RViz 1.14 marker class named at each function.
#include "display/marker_shapes.h"

#include <cmath>

#include "display/arrow_shapes.h"
#include "texture/glyph_atlas.h"
#include "scene/primitive_meshes.h"
#include "scene/text_layout.h"

namespace urdfsnap::display {
namespace {

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
// points (a strip joins neighbours, a list pairs them).
void AddLineMarker(const Marker& m, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  scene::LineSet lines;
  lines.rgba = m.colour;
  lines.width = static_cast<float>(m.scale.x());
  const Eigen::Affine3f X = X_FM.cast<float>();
  const auto add = [&](size_t i) {
    lines.points.push_back(X * m.points[i]);
    lines.colours.push_back(PointColour(m, i));
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

// triangle_list_marker.cpp: every three points one triangle, the points scaled by scale, with
// per-vertex colours (alpha from the marker's colour) or the marker's colour, unlit.
void AddTriangleList(const Marker& m, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  scene::FlatTriangles triangles;
  const Eigen::Affine3f X = (X_FM * Eigen::Scaling(m.scale)).cast<float>();
  triangles.positions.reserve(m.points.size());
  triangles.colours.reserve(m.points.size());
  for (size_t i = 0; i < m.points.size(); ++i) {
    triangles.positions.push_back(X * m.points[i]);
    Eigen::Vector4f colour = PointColour(m, i);
    colour.w() = m.colour.w();
    triangles.colours.push_back(colour);
  }
  if (!triangles.positions.empty()) scene.triangles.push_back(std::move(triangles));
}

// text_view_facing_marker.cpp: MovableText in Liberation Sans, scale.z high, centred
// horizontally and vertically on the pose, in the marker's colour.
void AddText(const Marker& m, const Eigen::Isometry3d& X_FM, scene::Scene& scene) {
  if (m.text.empty()) return;
  const auto atlas = texture::BuildGlyphAtlas(texture::FindLiberationSans(), scene::CodePointsOf({m.text}));
  const float height = static_cast<float>(m.scale.z());
  std::vector<scene::GlyphQuad> quads = scene::LayOutText(*atlas, m.text, height);
  for (scene::GlyphQuad& q : quads) {   // LayOutText hangs the line below the anchor: centre it
    q.min.y() += height / 2;
    q.max.y() += height / 2;
  }
  // the label's texture shares the atlas's ownership, so that whoever keeps the label's texture
  // keeps the atlas (and BuildGlyphAtlas returns it again rather than rasterising anew)
  scene.labels.push_back({std::shared_ptr<const texture::TextureImage>(atlas, atlas->texture.get()), std::move(quads),
                          X_FM.translation(), m.colour});
}

// mesh_resource_marker.cpp: the file's sub-meshes scaled by scale. Without embedded materials
// every sub-mesh takes the marker's colour; with them, the file's own colours (STL sub-meshes,
// which have none, white), and a marker colour other than (0, 0, 0, 0) laid over them as a
// second, blended pass.
void AddMesh(const Marker& m, const Eigen::Isometry3d& X_FM, const MarkerResources& resources,
             scene::Scene& scene) {
  const std::shared_ptr<const geometry::MeshFile> file = resources.load_mesh(m.mesh_resource);
  const Eigen::Affine3d X_FG = X_FM * Eigen::Scaling(m.scale);
  const bool tinted = !m.mesh_use_embedded_materials || m.colour != Eigen::Vector4f::Zero();
  for (const geometry::MeshPart& part : file->parts) {
    const std::shared_ptr<const geometry::TriangleMesh> mesh(file, &part.mesh);
    if (m.mesh_use_embedded_materials) {
      const Eigen::Vector4f own = part.takes_urdf_material ? Eigen::Vector4f::Ones() : part.diffuse;
      scene.items.push_back({mesh, X_FG, own, -1, nullptr, 1,
                             part.takes_urdf_material ? Eigen::Vector3f::Zero() : part.emissive});
    }
    if (tinted) AddShape(mesh, X_FG, m.colour, scene);
  }
}

}  // namespace

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
    case Marker::kTriangleList: AddTriangleList(m, X_FM, scene); break;
    default: break;   // MarkerProblem refuses unknown types
  }
}

}  // namespace urdfsnap::display
