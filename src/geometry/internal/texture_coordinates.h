// Texture coordinates of the unit primitives as RViz's Ogre meshes carry them (read from
// ogre_media/models/rviz_*.mesh of Debian's rviz 1.14.19): a whole image on each cube face, and
// angle-based wrapping on the cylinder and sphere with a seam where u wraps. Internal to the
// geometry library.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry::internal {

// Sets mesh.uvs from `corner_uvs` (three per triangle, in index order). A vertex whose triangles
// give it different coordinates (a seam, a pole) is split into one copy per coordinate.
void AttachCornerUvs(TriangleMesh& mesh, const std::vector<Eigen::Vector2f>& corner_uvs);

// rviz_cube.mesh: each face maps the whole image, v = 0 (the image's top) at the face's upper edge
// (+Z for the side faces, +Y for the top and bottom), u growing along up × normal.
void AttachBoxUvs(TriangleMesh& mesh);

// rviz_cylinder.mesh (which lies along its Y axis; here it is already turned onto Z): u = 0.75 +
// θ/2π with θ = atan2(-y, x), v = z + 0.5 on the side; the caps keep v of their height and put
// u = 0.5 at the centre.
void AttachCylinderUvs(TriangleMesh& mesh);

// rviz_sphere.mesh: u = 0.5 + atan2(y, x)/2π, v = acos(z / r)/π; a pole takes the mean u of its
// triangle's other corners.
void AttachSphereUvs(TriangleMesh& mesh);

}  // namespace urdfsnap::geometry::internal
