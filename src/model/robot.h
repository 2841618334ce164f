// The loaded robot: links in tree order with their visual and collision shapes and materials,
// joints with their origins, axes, limits and mimic rules. Its own records, not urdfdom's: the
// stages after this one see abstract geometry only (urdfdom stays inside model/).
// LoadRobot (urdf_loader.cpp) is the way to make one from URDF text.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "model/kinematic_step.h"

namespace urdfsnap::model {

enum class JointType { kFixed, kRevolute, kContinuous, kPrismatic, kFloating, kPlanar };

// The URDF spelling of a joint type ("revolute", "fixed", ...).
const char* JointTypeName(JointType type);

struct Joint {
  std::string name;
  JointType type = JointType::kFixed;
  int parent_link = -1;  // index into Robot::links()
  int child_link = -1;
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();  // joint origin in the parent link frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();          // unit axis in the joint frame
  bool has_limits = false;  // true for revolute and prismatic joints
  double lower = 0, upper = 0;  // metres or radians
  // <limit velocity effort>, when the joint has a <limit> (continuous joints may have one too):
  // rad/s or m/s, and N·m or N
  std::optional<double> velocity, effort;
  int mimic_leader = -1;  // index into Robot::joints(); -1 when the joint is not a mimic
  double mimic_multiplier = 1, mimic_offset = 0;
  int line = 0;  // source line of the <joint> element (0 if unknown)

  // True for the joint types a value moves: revolute, continuous and prismatic.
  bool IsMovable() const;
  // The unit of the joint's position: "m" for a prismatic joint, else "rad".
  const char* Unit() const { return type == JointType::kPrismatic ? "m" : "rad"; }
};

// A URDF <geometry>: a box, cylinder or sphere in metres, or a mesh file with its scale.
struct Shape {
  enum class Type { kBox, kCylinder, kSphere, kMesh };
  Type type = Type::kBox;
  Eigen::Vector3d box_size = Eigen::Vector3d::Ones();   // m, x y z
  double radius = 0;                                    // m, cylinder and sphere
  double length = 0;                                    // m, cylinder
  std::string mesh_uri;                                 // as written: package://, file://, a path
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones(); // per axis; negative mirrors
};

// A URDF <material> as a visual defines or names it (urdfdom has already replaced a named
// material by the robot-level one of that name).
struct Material {
  std::string name;                          // "" for an anonymous inline material
  Eigen::Vector4f rgba{0, 0, 0, 0};          // <color rgba>; urdfdom's default when none
  std::string texture;                       // <texture filename> URI; "" for none
};

struct Visual {
  Shape shape;
  Eigen::Isometry3d X_LG = Eigen::Isometry3d::Identity();  // <origin> in the link frame
  std::string material_name;                 // the name the visual's <material> gives, or ""
  std::optional<Material> material;          // none when the visual has no (known) material
};

struct Collision {
  Shape shape;
  Eigen::Isometry3d X_LG = Eigen::Isometry3d::Identity();
};

struct Link {
  std::string name;
  int parent_joint = -1;  // index into Robot::joints(); -1 for the root
  int line = 0;           // source line of the <link> element (0 if unknown)
  std::vector<Visual> visuals;        // in document order
  std::vector<Collision> collisions;  // in document order
  std::optional<double> mass;         // kg, from <inertial><mass> when given
};

class Robot {
 public:
  // Takes links in tree order (root first, every parent before its children) and joints whose
  // indices refer to them; precomputes the kinematics. LoadRobot is the usual way to make one.
  Robot(std::string name, std::string source, std::vector<Link> links, std::vector<Joint> joints);

  const std::string& name() const { return name_; }
  // The file the description came from, as given to LoadRobot.
  const std::string& source() const { return source_; }
  // Links in topological order: the root first, parents before children.
  const std::vector<Link>& links() const { return links_; }
  // Joints in document order.
  const std::vector<Joint>& joints() const { return joints_; }

  // The index of the link or joint with this name, or -1 if there is none.
  int FindLink(std::string_view name) const;
  int FindJoint(std::string_view name) const;

  // Names of the links in links() order (the label image's order: label k is link k - 1).
  std::vector<std::string> LinkNames() const;
  // Per link in links() order the index of its parent link, -1 for the root.
  std::vector<int> ParentLinks() const;

  // Names of the joints a value moves (revolute, continuous, prismatic, not mimic), in
  // document order.
  std::vector<std::string> MovableJointNames() const;

  // Per-link kinematics precomputed for ComputeLinkPoses, one step for each non-root link in
  // links() order.
  const std::vector<KinematicStep>& kinematic_steps() const { return kinematic_steps_; }

 private:
  std::string name_;
  std::string source_;
  std::vector<Link> links_;
  std::vector<Joint> joints_;
  std::vector<KinematicStep> kinematic_steps_;
};

// Parses URDF text (already xacro-expanded) into a Robot. `source` names the file in messages.
// Throws Error "source:line: ..." naming the joint or link at fault for bad XML, missing or
// duplicate names, unknown parent or child links, loops, several roots, unknown joint types,
// missing <limit> on revolute and prismatic joints, unparsable numbers, zero axes and mimic
// joints that follow unknown joints or each other in a circle.
Robot LoadRobot(const std::string& urdf_text, const std::string& source, Warnings& warnings);

}  // namespace urdfsnap::model
