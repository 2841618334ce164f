// Loads the mesh files a scene will draw on all cores before the scene builder asks for them one
// by one (geometry::LoadMeshFile caches each file, so the builder then finds them loaded). Call
// it before building a robot's first scene; after that its files are cached and it only costs
// the URI lookups.
#pragma once

#include "model/robot.h"
#include "scene/scene_builder.h"

namespace urdfsnap::scene {

// Loads every mesh file of the geometry `options` shows (visuals, collisions) in parallel.
// Errors are left for the scene builder to report, in link order, with their locations.
void PrefetchMeshFiles(const model::Robot& robot, const SceneOptions& options);

}  // namespace urdfsnap::scene
