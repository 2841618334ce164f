// RViz's unit shapes, tessellated once per process and shared by every draw item that uses them.
#pragma once

#include <memory>

#include "geometry/triangle_mesh.h"

namespace urdfsnap::scene {

const std::shared_ptr<const geometry::TriangleMesh>& UnitBoxMesh();
const std::shared_ptr<const geometry::TriangleMesh>& UnitCylinderMesh();
const std::shared_ptr<const geometry::TriangleMesh>& UnitSphereMesh();
const std::shared_ptr<const geometry::TriangleMesh>& UnitConeMesh();

}  // namespace urdfsnap::scene
