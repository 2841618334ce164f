// Located checks of a URDF document before urdfdom sees it: urdfdom only logs "Failed to build
// tree" through console_bridge, so every mistake it rejects is found here first with its line.
#include "model/internal/urdf_validation.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string_view>
#include <vector>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap::model {

namespace {

using tinyxml2::XMLElement;

// What the numbers of an attribute may be besides finite.
enum class Range { kAny, kPositive, kNonZero };

// An attribute urdfdom reads: `count` numbers, or text when count is 0.
struct AttributeRule {
  const char* element;
  const char* attribute;
  int count;
  bool required;
  Range range = Range::kAny;
};

// What urdfdom 3 (link.cpp, joint.cpp, model.cpp, pose.cpp) parses and which of it it requires
// (checked against urdfdom 3.0.1: it lets a missing axis xyz, inertia term, mesh filename or
// color rgba through).
constexpr AttributeRule kAttributeRules[] = {
    {"origin", "xyz", 3, false},
    {"origin", "rpy", 3, false},
    {"axis", "xyz", 3, false},
    // shapes of no size draw nothing in RViz (Ogre scales a unit shape by them); a negative mesh
    // scale mirrors the mesh, which RViz draws
    {"box", "size", 3, true, Range::kPositive},
    {"cylinder", "radius", 1, true, Range::kPositive},
    {"cylinder", "length", 1, true, Range::kPositive},
    {"sphere", "radius", 1, true, Range::kPositive},
    {"mesh", "scale", 3, false, Range::kNonZero},
    {"color", "rgba", 4, false},
    {"mass", "value", 1, true},
    {"inertia", "ixx", 1, false},
    {"inertia", "ixy", 1, false},
    {"inertia", "ixz", 1, false},
    {"inertia", "iyy", 1, false},
    {"inertia", "iyz", 1, false},
    {"inertia", "izz", 1, false},
    {"limit", "lower", 1, false},
    {"limit", "upper", 1, false},
    {"limit", "effort", 1, true},
    {"limit", "velocity", 1, true},
    {"safety_controller", "soft_lower_limit", 1, false},
    {"safety_controller", "soft_upper_limit", 1, false},
    {"safety_controller", "k_position", 1, false},
    {"safety_controller", "k_velocity", 1, true},
    {"dynamics", "damping", 1, false},
    {"dynamics", "friction", 1, false},
    {"mimic", "joint", 0, true},
    {"mimic", "multiplier", 1, false},
    {"mimic", "offset", 1, false},
    {"calibration", "rising", 1, false},
    {"calibration", "falling", 1, false},
};

bool IsOneOf(std::string_view word, std::initializer_list<const char*> words) {
  for (const char* w : words) {
    if (word == w) return true;
  }
  return false;
}

std::string Quoted(const char* text) { return std::string("'") + (text ? text : "") + "'"; }

class Validator {
 public:
  Validator(const XMLElement& robot, const std::string& source) : robot_(robot), source_(source) {}

  void Run() {
    if (!robot_.Attribute("name")) Fail(robot_, "<robot> has no name attribute");
    CollectLinks();
    CollectJoints();
    for (const XMLElement* e = robot_.FirstChildElement("material"); e;
         e = e->NextSiblingElement("material")) {
      CheckAttributes(*e, "material " + Quoted(e->Attribute("name")));
    }
    for (const auto& [name, link] : links_) CheckLink(name, *link);
    for (const JointInfo& joint : joints_) CheckJoint(joint);
    CheckTree();
    CheckMimicCircles();
  }

 private:
  struct JointInfo {
    const XMLElement* element;
    std::string name;
    std::string parent, child;
  };

  [[noreturn]] void Fail(const XMLElement& where, const std::string& message) const {
    throw Error(SourceLocation{source_, where.GetLineNum()}, message);
  }

  // The name of a <link> or <joint>, which must be there and be unique.
  std::string UniqueName(const XMLElement& e, const std::set<std::string>& seen) const {
    const char* name = e.Attribute("name");
    if (!name || !*name) Fail(e, std::string("<") + e.Name() + "> has no name attribute");
    if (seen.count(name)) {
      Fail(e, std::string(e.Name()) + " " + Quoted(name) + " is defined twice (first at line " +
                  std::to_string(FirstLineOf(e.Name(), name)) + ")");
    }
    return name;
  }

  int FirstLineOf(const char* element, const char* name) const {
    for (const XMLElement* e = robot_.FirstChildElement(element); e;
         e = e->NextSiblingElement(element)) {
      const char* n = e->Attribute("name");
      if (n && std::strcmp(n, name) == 0) return e->GetLineNum();
    }
    return 0;
  }

  void CollectLinks() {
    std::set<std::string> seen;
    for (const XMLElement* e = robot_.FirstChildElement("link"); e;
         e = e->NextSiblingElement("link")) {
      const std::string name = UniqueName(*e, seen);
      seen.insert(name);
      links_[name] = e;
      link_order_.push_back(name);
    }
    if (links_.empty()) {
      Fail(robot_, "robot " + Quoted(robot_.Attribute("name")) + " has no <link>");
    }
  }

  void CollectJoints() {
    std::set<std::string> seen;
    for (const XMLElement* e = robot_.FirstChildElement("joint"); e;
         e = e->NextSiblingElement("joint")) {
      const std::string name = UniqueName(*e, seen);
      seen.insert(name);
      JointInfo joint{e, name, LinkOfJoint(*e, name, "parent"), LinkOfJoint(*e, name, "child")};
      joint_index_[name] = joints_.size();
      joints_.push_back(joint);
    }
  }

  // The link named by the joint's <parent link> or <child link>, which must exist.
  std::string LinkOfJoint(const XMLElement& joint, const std::string& name,
                          const char* role) const {
    const XMLElement* e = joint.FirstChildElement(role);
    const char* link = e ? e->Attribute("link") : nullptr;
    if (!link) {
      Fail(e ? *e : joint, "joint " + Quoted(name.c_str()) + " has no <" + role + " link=...>");
    }
    if (!links_.count(link)) {
      Fail(*e, "joint " + Quoted(name.c_str()) + " names " + role + " link " + Quoted(link) +
                   ", which is not defined");
    }
    return link;
  }

  // Checks the numbers and required attributes of `e` and everything inside it.
  void CheckAttributes(const XMLElement& e, const std::string& owner) const {
    for (const AttributeRule& rule : kAttributeRules) {
      if (std::strcmp(e.Name(), rule.element) != 0) continue;
      const char* value = e.Attribute(rule.attribute);
      if (!value) {
        if (rule.required) {
          Fail(e, owner + ": <" + rule.element + "> has no " + rule.attribute + " attribute");
        }
      } else if (rule.count > 0) {
        CheckNumbers(e, owner, rule, value);
      }
    }
    for (const XMLElement* child = e.FirstChildElement(); child;
         child = child->NextSiblingElement()) {
      CheckAttributes(*child, owner);
    }
  }

  void CheckNumbers(const XMLElement& e, const std::string& owner, const AttributeRule& rule,
                    const char* value) const {
    const std::string what = owner + ": <" + rule.element + " " + rule.attribute + "=\"" + value + "\">";
    double numbers[4];
    if (!ParseNumbers(value, rule.count, numbers)) {
      Fail(e, what + ": expected " + std::to_string(rule.count) +
                  (rule.count == 1 ? " finite number" : " finite numbers"));
    }
    for (int i = 0; i < rule.count; ++i) {
      if (rule.range == Range::kPositive && numbers[i] <= 0) {
        Fail(e, what + ": expected " + (rule.count == 1 ? "a size" : "sizes") + " above 0");
      }
      if (rule.range == Range::kNonZero && numbers[i] == 0) {
        Fail(e, what + ": a scale of 0 flattens the mesh to nothing");
      }
    }
  }

  void CheckLink(const std::string& name, const XMLElement& link) const {
    const std::string owner = "link " + Quoted(name.c_str());
    CheckAttributes(link, owner);
    for (const char* kind : {"visual", "collision"}) {
      for (const XMLElement* v = link.FirstChildElement(kind); v;
           v = v->NextSiblingElement(kind)) {
        const XMLElement* geometry = v->FirstChildElement("geometry");
        if (!geometry) Fail(*v, owner + ": <" + kind + "> has no <geometry>");
        const XMLElement* shape = geometry->FirstChildElement();
        if (!shape || !IsOneOf(shape->Name(), {"box", "cylinder", "sphere", "mesh"})) {
          Fail(shape ? *shape : *geometry,
               owner + ": <geometry> needs one of box, cylinder, sphere or mesh" +
                   (shape ? std::string(", found <") + shape->Name() + ">" : std::string()));
        }
      }
    }
  }

  void CheckJoint(const JointInfo& joint) const {
    const XMLElement& e = *joint.element;
    const std::string owner = "joint " + Quoted(joint.name.c_str());
    const char* type = e.Attribute("type");
    if (!type) Fail(e, owner + " has no type attribute");
    if (!IsOneOf(type, {"revolute", "continuous", "prismatic", "fixed", "floating", "planar"})) {
      Fail(e, owner + " has unknown type " + Quoted(type) +
                  "; expected revolute, continuous, prismatic, fixed, floating or planar");
    }
    CheckAttributes(e, owner);

    const XMLElement* limit = e.FirstChildElement("limit");
    if (IsOneOf(type, {"revolute", "prismatic"})) {
      if (!limit) Fail(e, owner + " is " + type + " but has no <limit>");
      double lower = 0, upper = 0;
      if (const char* text = limit->Attribute("lower")) ParseNumbers(text, 1, &lower);
      if (const char* text = limit->Attribute("upper")) ParseNumbers(text, 1, &upper);
      if (lower > upper) {
        Fail(*limit, owner + ": lower limit " + FormatNumber(lower) + " is above upper limit " +
                         FormatNumber(upper));
      }
    }

    const XMLElement* axis = e.FirstChildElement("axis");
    if (axis && axis->Attribute("xyz") &&
        IsOneOf(type, {"revolute", "continuous", "prismatic", "planar"})) {
      double xyz[3];
      ParseNumbers(axis->Attribute("xyz"), 3, xyz);
      if (xyz[0] == 0 && xyz[1] == 0 && xyz[2] == 0) Fail(*axis, owner + " has a zero axis");
    }

    if (const XMLElement* mimic = e.FirstChildElement("mimic")) {
      const std::string leader = mimic->Attribute("joint");
      if (leader == joint.name) Fail(*mimic, owner + " mimics itself");
      if (!FindJoint(leader)) {
        Fail(*mimic, owner + " mimics joint " + Quoted(leader.c_str()) + ", which is not defined");
      }
    }
  }

  const JointInfo* FindJoint(const std::string& name) const {
    const auto it = joint_index_.find(name);
    return it == joint_index_.end() ? nullptr : &joints_[it->second];
  }

  // One parent per link, exactly one root, every link reachable from it.
  void CheckTree() const {
    std::map<std::string, const JointInfo*> parent_joint;  // by child link
    for (const JointInfo& joint : joints_) {
      const auto [it, inserted] = parent_joint.emplace(joint.child, &joint);
      if (!inserted) {
        Fail(*joint.element, "link " + Quoted(joint.child.c_str()) +
                                 " is the child of two joints: " + Quoted(it->second->name.c_str()) +
                                 " (line " + std::to_string(it->second->element->GetLineNum()) +
                                 ") and " + Quoted(joint.name.c_str()));
      }
    }
    std::vector<std::string> roots;
    for (const std::string& link : link_order_) {
      if (!parent_joint.count(link)) roots.push_back(link);
    }
    if (roots.size() > 1) {
      std::string list;
      for (const std::string& root : roots) {
        list += (list.empty() ? "" : ", ") + Quoted(root.c_str()) + " (line " +
                std::to_string(links_.at(root)->GetLineNum()) + ")";
      }
      Fail(*links_.at(roots[1]), "robot " + Quoted(robot_.Attribute("name")) +
                                     " has several root links (links without a parent joint): " +
                                     list + "; a URDF tree has exactly one");
    }
    // with one parent each, a link the root cannot reach sits on a loop: walk up until a link
    // repeats, then report the joint that closes the loop. Links already seen to reach the root
    // end a walk, so that every link is walked once (deep chains are linear, not cubic).
    std::set<std::string> reaches_root, on_walk;
    for (const std::string& start : link_order_) {
      std::vector<std::string> chain;
      std::string link = start;
      on_walk.clear();
      while (parent_joint.count(link) && !reaches_root.count(link)) {
        if (on_walk.count(link)) {
          const auto repeat = std::find(chain.begin(), chain.end(), link);
          const JointInfo& closing = *parent_joint.at(chain.back());
          std::string names;
          for (auto it = chain.rbegin(); it.base() != repeat; ++it) {
            names += Quoted(it->c_str()) + " -> ";
          }
          Fail(*closing.element, "joint " + Quoted(closing.name.c_str()) +
                                     " closes a loop of links " + names + Quoted(chain.back().c_str()) +
                                     " (parent to child); a URDF must be a tree");
        }
        chain.push_back(link);
        on_walk.insert(link);
        link = parent_joint.at(link)->parent;
      }
      reaches_root.insert(chain.begin(), chain.end());
    }
  }

  // A joint whose chain of mimicked joints comes back to it. Each joint is walked once: a walk
  // ends at a joint that mimics none, at one walked before, or on a circle, which is noted; the
  // report names the first joint, in document order, that is on a circle.
  void CheckMimicCircles() const {
    enum State { kUnseen, kOnWalk, kDone };
    std::vector<State> state(joints_.size(), kUnseen);
    std::vector<size_t> circle;  // the circle through the earliest joint, starting there
    for (size_t start = 0; start < joints_.size(); ++start) {
      std::vector<size_t> chain;
      for (size_t j = start; state[j] == kUnseen;) {
        state[j] = kOnWalk;
        chain.push_back(j);
        const XMLElement* mimic = joints_[j].element->FirstChildElement("mimic");
        if (!mimic) break;
        j = FindJoint(mimic->Attribute("joint")) - joints_.data();
        if (state[j] != kOnWalk) continue;
        const auto first = std::find(chain.begin(), chain.end(), j);
        const auto earliest = std::min_element(first, chain.end());
        if (circle.empty() || *earliest < circle.front()) {
          circle.assign(earliest, chain.end());
          circle.insert(circle.end(), first, earliest);
        }
      }
      for (size_t j : chain) state[j] = kDone;
    }
    if (circle.empty()) return;
    const JointInfo& joint = joints_[circle.front()];
    std::string names;
    for (size_t j : circle) names += Quoted(joints_[j].name.c_str()) + " -> ";
    Fail(*joint.element->FirstChildElement("mimic"),
         "joint " + Quoted(joint.name.c_str()) + " mimics itself through a circle of mimic joints: " +
             names + Quoted(joint.name.c_str()));
  }

  const XMLElement& robot_;
  const std::string& source_;
  std::map<std::string, const XMLElement*> links_;
  std::vector<std::string> link_order_;
  std::vector<JointInfo> joints_;
  std::map<std::string, size_t> joint_index_;  // joints_ by name
};

}  // namespace

void ValidateUrdfDocument(const tinyxml2::XMLElement& robot, const std::string& source) {
  Validator(robot, source).Run();
}

}  // namespace urdfsnap::model
