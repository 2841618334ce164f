// The page `urdfsnap docs` writes about a robot, as data: its tables and kinematic tree as plain
// text cells, and one section per movable joint with the poses and file names of its pictures and
// sweep animation. GL-free and file-free: markdown_page and html_page write it as text,
// page_images renders its pictures.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "common/warnings.h"
#include "model/robot.h"

namespace urdfsnap::docs {

// One row of the joints table; cells are plain text (the writers escape them), "—" when empty.
struct JointRow {
  std::string name, type, parent, child, axis, limits, mimic, default_value;
  std::string anchor;   // the joint's section ("joint-shoulder"), "" when it has none
};

// One row of the links table.
struct LinkRow {
  std::string name, visual, collision, meshes, mass;
};

// A link in the kinematic tree, in Robot::links() order (depth first, parents first).
struct TreeNode {
  int parent = -1;          // index of the parent's node, -1 for the root
  int depth = 0;            // 0 for the root
  std::string link;
  std::string joint;        // the joint from the parent ("" for the root) and its type
  std::string joint_type;
  std::string anchor;       // the joint's section, "" when it has none
};

// One still picture of a joint section.
struct Picture {
  std::string label;        // "lower limit", "default", "upper limit", "quarter turn back", ...
  double position = 0;      // the joint's position, rad or m
  std::string value;        // position with its unit, "-1.5708 rad (-90°)"
  std::string file;         // relative to the page, "joints/shoulder/lower.png"
  std::string alt;          // "shoulder at lower limit, -1.5708 rad (-90°)"
};

// A movable joint's section: pictures from one camera that fits the whole motion, the rest of the
// robot faded, and an animation of the joint sweeping its range. Mimic joints move with their
// leader and have no section of their own.
struct JointSection {
  int joint = -1;                        // index into Robot::joints()
  std::string name;
  std::string anchor;                    // "joint-" + a file-safe name, unique on the page
  std::string summary;                   // "revolute joint from base to arm, axis (0, 0, 1), ...
                                         // Also moves its mimic joints: finger = -1 × grip."
  std::vector<int> moving_links;         // the links it moves (its child's subtree, followers'),
                                         // indices into Robot::links()
  std::vector<Picture> pictures;
  std::vector<double> sweep;             // the joint's position in each animation frame, a loop
  std::string sweep_file;                // "" when the page has no animations
};

// Pixels of a picture.
struct PictureSize {
  int width = 640;
  int height = 480;
};

// What the page holds and the file names of its images (relative paths, '/' separated).
struct RobotPage {
  std::string robot_name;
  std::string model_file;                // the model's file name, without its folders
  std::vector<std::pair<std::string, std::string>> xacro_args;
  std::string source_note;               // "From mrm.urdf: 7 links, 6 joints (5 movable). Made by ..."
  std::string sections_note;             // what the joint sections show, and what is left out
  std::vector<double> default_positions; // the page's pose (joint_state_publisher's unless
                                         // given), one per Robot::joints()
  std::string hero_file, tf_file;
  std::string collision_file;            // "" when the robot has no collision geometry
  std::string turntable_file;            // "" when the page has no animations
  std::string tf_note;                   // what the TF picture leaves out (LeftOutNote), "" for nothing
  PictureSize view_size;                 // the robot and collision views
  PictureSize tf_size;                   // the TF view: larger for a robot with many frames
  PictureSize joint_size;                // the joints' pictures and every animation
  std::vector<JointRow> joints;          // every joint, in document order
  std::vector<LinkRow> links;            // every link, in tree order
  std::vector<TreeNode> tree;
  std::vector<JointSection> sections;    // in joint order
};

// A table as the page shows it: a header and rows of plain-text cells, a cell linking to a joint's
// section when its anchor is set.
struct Cell {
  std::string text;
  std::string anchor{};   // "" for plain text
};
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<Cell>> rows;
};

// The joints table (name, type, parent → child, axis, limits, mimic, default) and the links
// table (name, visual, collision, mesh files, mass).
Table JointsTable(const RobotPage& page);
Table LinksTable(const RobotPage& page);

// A picture of the page's strip of views below the robot.
struct View {
  std::string caption;                   // "collision geometry"
  std::string alt;                       // "collision geometry of mrm"
  std::string file;
  PictureSize size;
};

// The views the page shows beside the robot: collision geometry (when there is any), TF frames,
// turntable (when the page has animations).
std::vector<View> Views(const RobotPage& page);

struct PageOptions {
  // Shell-style patterns (fnmatch: * ? [...]) choosing the movable joints that get a section
  // (--sections); empty for all. A pattern naming a mimic joint gives its leader's section.
  std::vector<std::string> section_globs;
  // The page's pose, one position per Robot::joints() (mimics resolved): the views' and, but for
  // its own joint, each section's; empty for joint_state_publisher's defaults.
  std::vector<double> positions;
  bool posed = false;                    // the pose was given (-j, --joints), not the defaults
  PictureSize view_size;                 // --size
  PictureSize joint_size{320, 240};      // half of it
  int sweep_frames = 24;                 // frames of each joint's sweep animation (2.4 s)
  std::string animation_extension = ".gif";   // "" for a page without animations
  std::string still_extension = ".png";       // of the pictures: ".png", or ".webp" (lossy, smaller)
};

// The page of `robot`, loaded from `model_path` with `xacro_args`. Throws urdfsnap::Error for a
// section pattern that matches no movable joint (listing them), positions of the wrong count, or
// sweep_frames below 2.
RobotPage MakeRobotPage(const model::Robot& robot, const std::string& model_path,
                        const std::vector<std::pair<std::string, std::string>>& xacro_args,
                        const PageOptions& options, Warnings& warnings);

}  // namespace urdfsnap::docs
