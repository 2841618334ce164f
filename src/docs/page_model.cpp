// MakeRobotPage: the robot's facts as table cells and tree nodes, and the sections of the movable
// joints the patterns choose.
#include "docs/page_model.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "common/error.h"
#include "docs/fact_text.h"
#include "docs/file_names.h"
#include "docs/joint_sweeps.h"
#include "model/joint_values.h"

namespace urdfsnap::docs {

namespace {

constexpr const char* kNone = "—";

std::string Joined(const std::vector<std::string>& parts, const char* separator) {
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : separator) + part;
  return text.empty() ? kNone : text;
}

std::string Plural(size_t count, const char* noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// "-1 × finger_left + 0.1": the mimic rule of a joint that follows another.
std::string MimicText(const model::Robot& robot, const model::Joint& joint) {
  if (joint.mimic_leader < 0) return kNone;
  std::string text = ShortNumber(joint.mimic_multiplier) + " × " + robot.joints()[joint.mimic_leader].name;
  if (joint.mimic_offset != 0) {
    text += (joint.mimic_offset < 0 ? " - " : " + ") + ShortNumber(std::abs(joint.mimic_offset));
  }
  return text;
}

// "From mrm.xacro with xacro arguments a:=1: 7 links, 6 joints (5 movable). Made by ...".
std::string SourceNote(const model::Robot& robot, const RobotPage& page) {
  size_t movable = 0, mimic = 0;
  for (const model::Joint& joint : robot.joints()) {
    if (joint.mimic_leader >= 0) {
      ++mimic;
    } else if (joint.IsMovable()) {
      ++movable;
    }
  }
  std::string text = Plural(robot.links().size(), "link") + ", " + Plural(robot.joints().size(), "joint") +
                     " (" + std::to_string(movable) + " movable";
  if (mimic > 0) text += ", " + std::to_string(mimic) + " mimic";
  std::string note = "From " + page.model_file;
  if (!page.xacro_args.empty()) {
    note += " with xacro arguments";
    for (const auto& [name, value] : page.xacro_args) note += " " + name + ":=" + value;
  }
  return note + ": " + text + "). Made by urdfsnap docs; regenerate the page rather than edit it.";
}

std::string SectionsNote(size_t movable, size_t shown, bool posed) {
  if (movable == 0) return "The robot has no movable joints.";
  std::string note = posed ? "Each movable joint at its limits and at the page's pose (given with -j or --joints: "
                             "\"default\" below), the others staying there, seen by one camera"
                           : "Each movable joint at its limits and its default (joint_state_publisher's), seen by one camera";
  note += " that frames its whole motion, with the links it does not move faded.";
  const size_t left_out = movable - shown;
  if (left_out == 1) note += " 1 movable joint is left out of this page (--sections).";
  if (left_out > 1) note += " " + std::to_string(left_out) + " movable joints are left out of this page (--sections).";
  return note;
}

LinkRow MakeLinkRow(const model::Link& link) {
  std::vector<std::string> visuals, collisions, meshes;
  std::set<std::string> seen;
  const auto add_mesh = [&](const model::Shape& shape) {
    if (shape.type == model::Shape::Type::kMesh && !shape.mesh_uri.empty() && seen.insert(shape.mesh_uri).second) {
      meshes.push_back(shape.mesh_uri);
    }
  };
  for (const model::Visual& visual : link.visuals) {
    visuals.push_back(ShapeText(visual.shape));
    add_mesh(visual.shape);
  }
  for (const model::Collision& collision : link.collisions) {
    collisions.push_back(ShapeText(collision.shape));
    add_mesh(collision.shape);
  }
  return {link.name, Joined(visuals, "; "), Joined(collisions, "; "), Joined(meshes, "; "),
          link.mass ? ShortNumber(*link.mass) + " kg" : kNone};
}

// The movable, non-mimic joints the patterns choose (all when there are none), in document order;
// a pattern matching a mimic joint chooses its leader.
std::vector<int> ChosenJoints(const model::Robot& robot, const std::vector<std::string>& globs) {
  const auto& joints = robot.joints();
  std::vector<bool> chosen(joints.size(), globs.empty());
  for (const std::string& glob : globs) {
    bool matched = false;
    for (size_t j = 0; j < joints.size(); ++j) {
      if (!joints[j].IsMovable() || fnmatch(glob.c_str(), joints[j].name.c_str(), 0) != 0) continue;
      int shown = static_cast<int>(j);
      while (joints[shown].mimic_leader >= 0) shown = joints[shown].mimic_leader;
      if (!joints[shown].IsMovable()) continue;   // a mimic of a fixed joint does not move
      chosen[shown] = matched = true;
    }
    if (!matched) {
      std::string names;
      for (const std::string& name : robot.MovableJointNames()) names += (names.empty() ? "" : ", ") + name;
      throw Error("--sections '" + glob + "' matches none of the movable joints of robot '" + robot.name() +
                  "'" + (names.empty() ? " (it has none)" : ": " + names));
    }
  }
  std::vector<int> result;
  for (size_t j = 0; j < joints.size(); ++j) {
    if (chosen[j] && joints[j].IsMovable() && joints[j].mimic_leader < 0) result.push_back(static_cast<int>(j));
  }
  return result;
}

JointSection MakeSection(const model::Robot& robot, const RobotPage& page, int j, const std::string& safe_name,
                         const PageOptions& options) {
  const model::Joint& joint = robot.joints()[j];
  const JointRow& row = page.joints[j];
  JointSection section;
  section.joint = j;
  section.name = joint.name;
  section.anchor = "joint-" + safe_name;
  section.summary = row.type + " joint from " + row.parent + " to " + row.child + ", axis " + row.axis +
                    ", limits " + row.limits + ", default " + row.default_value + ".";
  const std::vector<int> followers = MimicFollowers(robot, j);
  for (size_t i = 0; i < followers.size(); ++i) {
    const model::Joint& follower = robot.joints()[followers[i]];
    section.summary += (i ? ", " : " Also moves its mimic joints: ") + follower.name + " = " + MimicText(robot, follower);
  }
  if (!followers.empty()) section.summary += ".";
  section.moving_links = MovingLinks(robot, j);
  const std::string folder = "joints/" + safe_name + "/";
  const double default_position = page.default_positions[j];
  for (const StillPose& still : StillPoses(joint, default_position)) {
    const std::string value = PositionText(joint, still.position);
    section.pictures.push_back({still.label, still.position, value, folder + still.file_stem + options.still_extension,
                                joint.name + " at " + still.label + ", " + value});
  }
  section.sweep = SweepPositions(joint, default_position, options.sweep_frames);
  if (!options.animation_extension.empty()) section.sweep_file = folder + "sweep" + options.animation_extension;
  return section;
}

}  // namespace

Table JointsTable(const RobotPage& page) {
  Table table{{"joint", "type", "parent → child", "axis", "limits", "mimic (of leader)", "default"}, {}};
  for (const JointRow& j : page.joints) {
    table.rows.push_back({{j.name, j.anchor}, {j.type}, {j.parent + " → " + j.child}, {j.axis}, {j.limits},
                          {j.mimic}, {j.default_value}});
  }
  return table;
}

Table LinksTable(const RobotPage& page) {
  Table table{{"link", "visual", "collision", "mesh files", "mass"}, {}};
  for (const LinkRow& l : page.links) {
    table.rows.push_back({{l.name}, {l.visual}, {l.collision}, {l.meshes}, {l.mass}});
  }
  return table;
}

std::vector<View> Views(const RobotPage& page) {
  std::vector<View> views;
  if (!page.collision_file.empty()) {
    views.push_back({"collision geometry", "collision geometry of " + page.robot_name, page.collision_file,
                     page.view_size});
  }
  views.push_back({"TF frames", "TF frames of " + page.robot_name, page.tf_file, page.tf_size});
  if (!page.turntable_file.empty()) {
    views.push_back({"turntable", page.robot_name + " turning", page.turntable_file, page.joint_size});
  }
  return views;
}

RobotPage MakeRobotPage(const model::Robot& robot, const std::string& model_path,
                        const std::vector<std::pair<std::string, std::string>>& xacro_args,
                        const PageOptions& options, Warnings& warnings) {
  if (options.sweep_frames < 2) throw Error("a joint sweep needs at least 2 frames");
  RobotPage page;
  page.robot_name = robot.name();
  page.model_file = std::filesystem::path(model_path).filename().string();
  page.xacro_args = xacro_args;
  page.source_note = SourceNote(robot, page);
  page.default_positions = options.positions.empty() ? model::ResolveJointPositions(robot, {}, true, warnings)
                                                     : options.positions;
  if (page.default_positions.size() != robot.joints().size()) {
    throw Error("a docs page's pose needs " + std::to_string(robot.joints().size()) + " joint positions, not " +
                std::to_string(page.default_positions.size()));
  }
  if (options.still_extension != ".png" && options.still_extension != ".webp") {
    throw Error("a docs page's pictures are .png or .webp, not '" + options.still_extension + "'");
  }
  page.hero_file = "images/robot" + options.still_extension;
  bool has_collision = false;
  for (const model::Link& link : robot.links()) has_collision |= !link.collisions.empty();
  if (has_collision) page.collision_file = "images/collision" + options.still_extension;
  page.tf_file = "images/tf" + options.still_extension;
  if (!options.animation_extension.empty()) page.turntable_file = "images/turntable" + options.animation_extension;
  page.view_size = options.view_size;
  // about 30 frame names fit the TF view at --size 640x480; more frames (a PR2 has 90) get a
  // picture up to twice as wide and high, so that more of their names find a place
  const double grow = std::clamp(std::sqrt(robot.links().size() / 30.0), 1.0, 2.0);
  page.tf_size = {static_cast<int>(std::lround(options.view_size.width * grow)),
                  static_cast<int>(std::lround(options.view_size.height * grow))};
  page.joint_size = options.joint_size;

  const auto& joints = robot.joints();
  const auto& links = robot.links();
  for (size_t j = 0; j < joints.size(); ++j) {
    const model::Joint& joint = joints[j];
    page.joints.push_back({joint.name, model::JointTypeName(joint.type), links[joint.parent_link].name,
                           links[joint.child_link].name, AxisText(joint), LimitsText(joint),
                           MimicText(robot, joint),
                           joint.IsMovable() ? PositionText(joint, page.default_positions[j]) : kNone, ""});
  }
  for (const model::Link& link : links) {
    page.links.push_back(MakeLinkRow(link));
    TreeNode node;
    node.link = link.name;
    if (link.parent_joint >= 0) {
      const model::Joint& joint = joints[link.parent_joint];
      node.parent = joint.parent_link;
      node.depth = page.tree[joint.parent_link].depth + 1;
      node.joint = joint.name;
      node.joint_type = model::JointTypeName(joint.type);
    }
    page.tree.push_back(std::move(node));
  }

  const std::vector<int> chosen = ChosenJoints(robot, options.section_globs);
  std::vector<std::string> chosen_names;
  for (int j : chosen) chosen_names.push_back(joints[j].name);
  const std::vector<std::string> safe_names = FileSafeNames(chosen_names);
  for (size_t i = 0; i < chosen.size(); ++i) {
    page.sections.push_back(MakeSection(robot, page, chosen[i], safe_names[i], options));
    page.joints[chosen[i]].anchor = page.sections.back().anchor;
  }
  for (size_t i = 0; i < links.size(); ++i) {
    if (links[i].parent_joint >= 0) page.tree[i].anchor = page.joints[links[i].parent_joint].anchor;
  }
  page.sections_note = SectionsNote(robot.MovableJointNames().size(), chosen.size(), options.posed);
  return page;
}

}  // namespace urdfsnap::docs
