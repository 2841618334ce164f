// The GL-free description of one frame: what to draw, where, in which colour. The scene builder
// fills it from a posed robot; the renderer turns it into pixels. Everything is expressed in the
// fixed frame F.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "geometry/triangle_mesh.h"
#include "scene/text_layout.h"
#include "texture/texture_image.h"

namespace urdfsnap::scene {

// One lit mesh: a robot visual or collision shape, or a part of a TF marker.
struct DrawItem {
  std::shared_ptr<const geometry::TriangleMesh> mesh;
  Eigen::Affine3d X_FG;                 // mesh pose in the fixed frame, including its scale
  Eigen::Vector4f rgba{1, 0, 0, 1};     // diffuse colour and alpha
  int link = -1;                        // index into the robot's links(); -1 for markers
  // modulates the lit colour (Ogre's default texture unit), sampled at the mesh's uvs; none if null
  std::shared_ptr<const texture::TextureImage> texture;
  // how many of the material's texture units show `texture`: the lit colour is multiplied by it
  // this many times (RViz gives a mesh material one unit per texture map, all showing its diffuse
  // map; see geometry::MeshPart)
  int texture_units = 1;
  Eigen::Vector3f emissive{0, 0, 0};    // self-illumination, added to the lit colour
};

// Unlit line segments (pairs of points), drawn 1 pixel wide, or, with a width, as RViz's
// BillboardLine draws marker lines and Path billboards (ogre_helpers/billboard_line.cpp): each
// segment a ribbon `width` metres wide that turns about the segment to face the camera.
struct LineSet {
  std::vector<Eigen::Vector3f> points;  // segment i runs from points[2i] to points[2i+1]
  Eigen::Vector4f rgba{1, 1, 1, 1};
  std::vector<Eigen::Vector4f> colours;  // one per point, blended along the segment; empty: rgba
  float width = 0;                       // metres; 0: 1-pixel GL lines
};

// Unlit triangles with a colour per corner, interpolated across, seen from both sides: RViz's
// TRIANGLE_LIST marker (markers/triangle_list_marker.cpp). Blended where a colour's alpha is < 1.
struct FlatTriangles {
  std::vector<Eigen::Vector3f> positions;  // three per triangle, in the fixed frame
  std::vector<Eigen::Vector4f> colours;    // one per position
};

// Unlit text that faces the camera (TF frame names): quads in the camera's image plane, x right and
// y up in metres, hung at an anchor point, textured with a luminance-alpha glyph texture, blended,
// depth-tested without depth writes and pulled slightly towards the camera (movable_text.cpp).
struct TextLabel {
  std::shared_ptr<const texture::TextureImage> texture;
  std::vector<GlyphQuad> quads;
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();   // in the fixed frame
  Eigen::Vector4f rgba{1, 1, 1, 1};
};

// Points drawn as RViz's point-cloud renderer draws them (rviz/ogre_helpers/point_cloud.cpp): the
// points of a PointCloud2 or LaserScan display and of POINTS, CUBE_LIST and SPHERE_LIST markers.
// Points are GL points `size.x()` pixels wide; Squares and FlatSquares camera-facing quads of
// `size` metres (Squares with RViz's thin darker outline); Spheres and Boxes lit solids of `size`
// metres.
struct PointSet {
  enum class Style { kPoints, kSquares, kFlatSquares, kSpheres, kBoxes };
  Style style = Style::kFlatSquares;
  std::vector<Eigen::Vector3f> positions;  // in the fixed frame
  std::vector<Eigen::Vector4f> colours;    // one rgba per position
  Eigen::Vector3f size{0.01f, 0.01f, 0.01f};
  // Boxes: the axes the boxes are aligned with, in the fixed frame (those of the cloud's or the
  // marker's frame: RViz's box.geom builds them in the point cloud's scene node)
  Eigen::Matrix3f box_axes = Eigen::Matrix3f::Identity();
};

struct Scene {
  Eigen::Vector3f background{48 / 255.f, 48 / 255.f, 48 / 255.f};
  std::vector<DrawItem> items;
  std::vector<LineSet> lines;           // transparent overlays such as the grid
  std::vector<TextLabel> labels;        // blended with the transparent geometry
  std::vector<PointSet> points;         // display points; opaque unless a colour's alpha is < 1
  std::vector<FlatTriangles> triangles; // display surfaces; opaque unless a colour's alpha is < 1
};

}  // namespace urdfsnap::scene
