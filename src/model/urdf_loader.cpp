// LoadRobot: URDF text -> Robot. tinyxml2 reads the text for lines and located checks, urdfdom
// parses the model, which is copied into the Robot's own records (shapes, materials, joints) with
// the links in tree order for kinematics.
#include <algorithm>
#include <map>
#include <optional>
#include <memory>
#include <string_view>
#include <utility>

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include "common/error.h"
#include "model/robot.h"
#include "model/internal/urdf_validation.h"

namespace urdfsnap::model {

namespace {

// Collects what urdfdom logs through console_bridge while it is alive, instead of printing it,
// and restores the previous handler and level afterwards. console_bridge's handler is
// process-wide, so robots must not be loaded from several threads at once.
class UrdfdomLogCapture : public console_bridge::OutputHandler {
 public:
  UrdfdomLogCapture() : previous_level_(console_bridge::getLogLevel()) {
    console_bridge::useOutputHandler(this);
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_WARN);
  }
  ~UrdfdomLogCapture() override {
    console_bridge::restorePreviousOutputHandler();
    console_bridge::setLogLevel(previous_level_);
  }
  UrdfdomLogCapture(const UrdfdomLogCapture&) = delete;
  UrdfdomLogCapture& operator=(const UrdfdomLogCapture&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR ? errors_ : warnings_).push_back(text);
  }

  const std::vector<std::string>& errors() const { return errors_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  console_bridge::LogLevel previous_level_;
  std::vector<std::string> errors_, warnings_;
};

const tinyxml2::XMLElement& ParseRobotElement(tinyxml2::XMLDocument& doc, const std::string& text,
                                              const std::string& source) {
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    // ErrorStr() reads "Error=NAME ErrorID=N (0xN) Line number=L: detail"; keep the detail
    const std::string detail = doc.ErrorStr();
    const size_t colon = detail.find(": ");
    throw Error(SourceLocation{source, doc.ErrorLineNum()},
                std::string("malformed XML (") + doc.ErrorName() + ")" +
                    (colon == std::string::npos ? "" : ": " + detail.substr(colon + 2)));
  }
  // tinyxml2 skips a DOCTYPE, but urdfdom's TinyXML stops at the "]>" of an internal subset and
  // finds no robot; entities declared there would not be expanded either
  for (const tinyxml2::XMLNode* node = doc.FirstChild(); node; node = node->NextSibling()) {
    const tinyxml2::XMLUnknown* unknown = node->ToUnknown();
    const std::string_view text = unknown ? unknown->Value() : "";
    if (text.substr(0, 7) == "DOCTYPE" && text.find('[') != std::string_view::npos) {
      throw Error(SourceLocation{source, node->GetLineNum()},
                  "<!DOCTYPE> with declarations ([...]: entities, elements) is not supported by "
                  "urdfdom; expand the entities, or use xacro");
    }
  }
  const tinyxml2::XMLElement* robot = doc.RootElement();
  if (!robot || std::string_view(robot->Name()) != "robot") {
    throw Error(SourceLocation{source, robot ? robot->GetLineNum() : 0},
                std::string("expected a <robot> root element, found ") +
                    (robot ? "<" + std::string(robot->Name()) + ">" : "none"));
  }
  return *robot;
}

Eigen::Isometry3d ToIsometry(const urdf::Pose& pose) {
  const urdf::Rotation& r = pose.rotation;
  const urdf::Vector3& p = pose.position;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(p.x, p.y, p.z);
  return X;
}

Shape ToShape(const urdf::Geometry& geometry) {
  Shape shape;
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      shape.type = Shape::Type::kBox;
      shape.box_size = {box.dim.x, box.dim.y, box.dim.z};
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      shape.type = Shape::Type::kCylinder;
      shape.radius = cylinder.radius;
      shape.length = cylinder.length;
      break;
    }
    case urdf::Geometry::SPHERE:
      shape.type = Shape::Type::kSphere;
      shape.radius = static_cast<const urdf::Sphere&>(geometry).radius;
      break;
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      shape.type = Shape::Type::kMesh;
      shape.mesh_uri = mesh.filename;
      shape.mesh_scale = {mesh.scale.x, mesh.scale.y, mesh.scale.z};
      break;
    }
  }
  return shape;
}

std::optional<Material> ToMaterial(const urdf::MaterialSharedPtr& material) {
  if (!material) return std::nullopt;
  const urdf::Color& c = material->color;
  return Material{material->name, Eigen::Vector4f(c.r, c.g, c.b, c.a), material->texture_filename};
}

// The link's name, line and parent joint, and copies of its shapes (urdfdom refuses a visual or
// collision without geometry, but a null one is skipped all the same).
Link ToLink(const urdf::Link& u, int parent_joint, int line) {
  Link link{u.name, parent_joint, line, {}, {}, std::nullopt};
  for (const auto& visual : u.visual_array) {
    if (!visual->geometry) continue;
    link.visuals.push_back({ToShape(*visual->geometry), ToIsometry(visual->origin),
                            visual->material_name, ToMaterial(visual->material)});
  }
  for (const auto& collision : u.collision_array) {
    if (!collision->geometry) continue;
    link.collisions.push_back({ToShape(*collision->geometry), ToIsometry(collision->origin)});
  }
  if (u.inertial) link.mass = u.inertial->mass;
  return link;
}

JointType ToJointType(int urdf_type) {
  switch (urdf_type) {
    case urdf::Joint::REVOLUTE: return JointType::kRevolute;
    case urdf::Joint::CONTINUOUS: return JointType::kContinuous;
    case urdf::Joint::PRISMATIC: return JointType::kPrismatic;
    case urdf::Joint::FLOATING: return JointType::kFloating;
    case urdf::Joint::PLANAR: return JointType::kPlanar;
    default: return JointType::kFixed;
  }
}

// urdfdom reads the text with TinyXML, which takes some malformed attributes (a bare '&' in a
// name) differently from tinyxml2: every link and joint must be in urdfdom's model by the name
// tinyxml2 read (found by fuzzing: a missing joint was dereferenced).
void CheckUrdfdomNames(const tinyxml2::XMLElement& robot, const urdf::ModelInterface& model,
                       const std::string& source) {
  for (const tinyxml2::XMLElement* e = robot.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string_view kind = e->Name();
    if (kind != "link" && kind != "joint") continue;
    const char* name = e->Attribute("name");
    if (kind == "link" ? !model.getLink(name) : !model.getJoint(name)) {
      throw Error(SourceLocation{source, e->GetLineNum()},
                  std::string(kind) + " '" + name +
                      "': urdfdom reads this name differently (characters such as a bare '&' "
                      "must be escaped)");
    }
  }
}

// Joints in document order with everything but the link indices, which need the tree order.
std::vector<Joint> ReadJoints(const tinyxml2::XMLElement& robot,
                              const urdf::ModelInterface& model) {
  std::vector<Joint> joints;
  std::vector<std::string> leaders;  // the joint each one mimics, "" for none
  for (const tinyxml2::XMLElement* e = robot.FirstChildElement("joint"); e;
       e = e->NextSiblingElement("joint")) {
    const urdf::JointConstSharedPtr u = model.getJoint(e->Attribute("name"));
    Joint joint;
    joint.name = u->name;
    joint.type = ToJointType(u->type);
    joint.X_PJ = ToIsometry(u->parent_to_joint_origin_transform);
    // URDF's default axis is (1, 0, 0), which an <axis> without xyz also gets here; KDL, hence
    // robot_state_publisher, normalises the axis
    const Eigen::Vector3d axis(u->axis.x, u->axis.y, u->axis.z);
    joint.axis = axis.squaredNorm() > 0 ? axis.normalized() : Eigen::Vector3d::UnitX();
    joint.has_limits = joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic;
    if (joint.has_limits) {
      joint.lower = u->limits->lower;
      joint.upper = u->limits->upper;
    }
    if (u->limits) {
      joint.velocity = u->limits->velocity;
      joint.effort = u->limits->effort;
    }
    if (u->mimic) {
      joint.mimic_multiplier = u->mimic->multiplier;
      joint.mimic_offset = u->mimic->offset;
    }
    leaders.push_back(u->mimic ? u->mimic->joint_name : "");
    joint.line = e->GetLineNum();
    joints.push_back(joint);
  }
  // mimic leaders by index, now that every joint has one (validation made sure they exist)
  std::map<std::string, int> index_of;
  for (size_t i = 0; i < joints.size(); ++i) index_of[joints[i].name] = static_cast<int>(i);
  for (size_t i = 0; i < joints.size(); ++i) {
    if (!leaders[i].empty()) joints[i].mimic_leader = index_of.at(leaders[i]);
  }
  return joints;
}

// Links depth first from the root, children in the document order of their joints; fills in
// the joints' link indices.
std::vector<Link> OrderLinks(const tinyxml2::XMLElement& robot, const urdf::ModelInterface& model,
                             std::vector<Joint>& joints) {
  std::map<std::string, int> line_of_link;
  for (const tinyxml2::XMLElement* e = robot.FirstChildElement("link"); e;
       e = e->NextSiblingElement("link")) {
    line_of_link[e->Attribute("name")] = e->GetLineNum();
  }
  std::map<std::string, std::vector<int>> child_joints;  // by parent link name
  for (size_t j = 0; j < joints.size(); ++j) {
    child_joints[model.getJoint(joints[j].name)->parent_link_name].push_back(static_cast<int>(j));
  }

  std::vector<Link> links;
  links.push_back(ToLink(*model.getRoot(), -1, line_of_link[model.getRoot()->name]));
  for (size_t i = 0; i < links.size(); ++i) {
    // inserting each link's children right after it yields the depth-first order
    const std::vector<int>& children = child_joints[links[i].name];
    std::vector<Link> inserted;
    for (int j : children) {
      const urdf::JointConstSharedPtr u = model.getJoint(joints[j].name);
      inserted.push_back(ToLink(*model.getLink(u->child_link_name), j, line_of_link[u->child_link_name]));
    }
    links.insert(links.begin() + i + 1, inserted.begin(), inserted.end());
  }
  std::map<std::string, int> index_of_link;
  for (size_t i = 0; i < links.size(); ++i) index_of_link[links[i].name] = static_cast<int>(i);
  for (Joint& joint : joints) {
    const urdf::JointConstSharedPtr u = model.getJoint(joint.name);
    joint.parent_link = index_of_link.at(u->parent_link_name);
    joint.child_link = index_of_link.at(u->child_link_name);
  }
  return links;
}

}  // namespace

Robot LoadRobot(const std::string& urdf_text, const std::string& source, Warnings& warnings) {
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement& robot = ParseRobotElement(doc, urdf_text, source);
  ValidateUrdfDocument(robot, source);

  urdf::ModelInterfaceSharedPtr model;
  {
    UrdfdomLogCapture log;
    model = urdf::parseURDF(urdf_text);
    for (const std::string& message : log.warnings()) {
      warnings.Add(source + ": urdfdom: " + message);
    }
    if (!model) {
      std::string why;
      for (const std::string& message : log.errors()) why += (why.empty() ? "" : "; ") + message;
      throw Error(SourceLocation{source, robot.GetLineNum()},
                  "urdfdom rejected robot '" + std::string(robot.Attribute("name")) + "': " +
                      (why.empty() ? "no reason given" : why));
    }
  }

  CheckUrdfdomNames(robot, *model, source);
  std::vector<Joint> joints = ReadJoints(robot, *model);
  std::vector<Link> links = OrderLinks(robot, *model, joints);
  std::string name = model->getName();
  return Robot(std::move(name), source, std::move(links), std::move(joints));
}

}  // namespace urdfsnap::model
