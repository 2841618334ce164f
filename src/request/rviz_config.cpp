// ReadRvizConfig: yaml-cpp walks the .rviz file; each RViz property is read the way RViz's
// property classes load it (src/rviz/properties/*.cpp in ros-visualization/rviz 1.14) and limited
// to the range RViz gives it. RViz 2 (ros2/rviz) saves the same property names under its own class
// names (request/rviz_class_names.h).
#include "request/rviz_config.h"

#include <algorithm>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/internal/yaml_section.h"
#include "common/number_text.h"
#include "request/rviz_class_names.h"
#include "request/internal/rviz_displays.h"
#include "request/internal/rviz_properties.h"

namespace urdfsnap::request {
namespace {

using Section = YamlSection;

// One entry of the file's display tree, and whether RViz would draw it.
struct Display {
  Section section;
  bool enabled = false;
};

// The displays urdfsnap follows, by class, in file order.
struct Displays {
  std::vector<Display> grids;
  std::vector<Display> robot_models;
  std::vector<Display> tfs;
  std::vector<display::DisplaySettings> messages;  // the enabled message displays, in file order
  std::vector<std::string> skipped;  // classes urdfsnap does not draw, each once, in file order
};

// Walks the "Displays" list of the root or of an rviz/Group display.
void CollectDisplays(const Section& parent, bool parent_enabled, Displays& displays,
                     Warnings& warnings) {
  const YAML::Node list = parent.Entry("Displays");
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) parent.Fail("Displays", "a list of displays");
  for (const YAML::Node& item : list) {
    std::string class_id;
    std::string name;
    const Section untitled = RvizSection(parent.path(), item, "display");
    untitled.ReadString("Class", class_id);
    untitled.ReadString("Name", name);
    if (class_id.empty()) untitled.Fail("Class", "a display class such as rviz/Grid");
    const Section section = RvizSection(parent.path(), item, class_id + " display '" + name + "'");

    // a display's checkbox: Display::load reads "Value", then "Enabled"; unset means unchecked
    // (src/rviz/display.cpp). A disabled group disables its children (setDisableChildrenIfFalse).
    bool enabled = false;
    section.ReadBool("Value", enabled);
    section.ReadBool("Enabled", enabled);
    const Display display{section, enabled && parent_enabled};

    switch (ClassifyDisplay(class_id)) {
      case DisplayClass::kGrid: displays.grids.push_back(display); break;
      case DisplayClass::kRobotModel: displays.robot_models.push_back(display); break;
      case DisplayClass::kTf: displays.tfs.push_back(display); break;
      case DisplayClass::kGroup:
        CollectDisplays(section, display.enabled, displays, warnings);
        break;
      case DisplayClass::kMarker: case DisplayClass::kMarkerArray: case DisplayClass::kPath:
      case DisplayClass::kPoseArray: case DisplayClass::kAxes: case DisplayClass::kPointCloud2:
      case DisplayClass::kLaserScan:
        if (display.enabled) {
          displays.messages.push_back(ReadMessageDisplay(ClassifyDisplay(class_id), section, name, warnings));
        }
        break;
      case DisplayClass::kOther:
        if (std::find(displays.skipped.begin(), displays.skipped.end(), class_id) ==
            displays.skipped.end()) {
          displays.skipped.push_back(class_id);
        }
        warnings.Add(parent.path() + ": skipped display class '" + class_id +
                     "', which urdfsnap does not draw");
        break;
    }
  }
}

// The display of one class that urdfsnap follows: the first enabled one, else the first one (then
// that display is off), else none. Further enabled ones, which RViz would draw too, are warned of.
const Display* Chosen(const std::vector<Display>& displays, Warnings& warnings) {
  const auto enabled = [](const Display& display) { return display.enabled; };
  const auto first = std::find_if(displays.begin(), displays.end(), enabled);
  if (first == displays.end()) return displays.empty() ? nullptr : &displays.front();
  for (auto other = std::find_if(first + 1, displays.end(), enabled); other != displays.end();
       other = std::find_if(other + 1, displays.end(), enabled)) {
    other->section.Warn("Enabled", "is true, but urdfsnap draws only the first enabled display "
                        "of a class", warnings);
  }
  return &*first;
}

// The Global Options of src/rviz/visualization_manager.cpp (L172-179).
void ReadGlobalOptions(const Section& manager, scene::SceneOptions& scene) {
  const std::optional<Section> global = manager.Child("Global Options", "Global Options");
  if (!global) return;
  ReadColour(*global, "Background Color", scene.background);
  ReadFrame(*global, "Fixed Frame", scene.fixed_frame);
}

// The Grid display's properties (src/rviz/default_plugin/grid_display.cpp L50-99).
void ReadGrid(const Display& display, const std::string& fixed_frame, scene::GridOptions& grid,
              Warnings& warnings) {
  const Section& section = display.section;
  grid.enabled = display.enabled;
  section.ReadInt("Plane Cell Count", grid.plane_cell_count, 1);
  section.ReadNumber("Cell Size", grid.cell_size, 0.0001);
  ReadColour(section, "Color", grid.colour);
  double alpha = grid.alpha;
  section.ReadNumber("Alpha", alpha, 0, 1);
  grid.alpha = static_cast<float>(alpha);
  if (section.Value("Plane").IsDefined()) {
    std::string plane;
    section.ReadString("Plane", plane);
    if (plane == "XY") {
      grid.plane = scene::GridOptions::Plane::kXY;
    } else if (plane == "XZ") {
      grid.plane = scene::GridOptions::Plane::kXZ;
    } else if (plane == "YZ") {
      grid.plane = scene::GridOptions::Plane::kYZ;
    } else {
      section.Fail("Plane", "XY, XZ or YZ");
    }
  }
  ReadVector(section, "Offset", grid.offset);

  // what urdfsnap's grid cannot follow
  std::string frame = kFixedFrameString;
  ReadFrame(section, "Reference Frame", frame);
  if (frame != kFixedFrameString && frame != fixed_frame) {
    section.Warn("Reference Frame", "is not the fixed frame; urdfsnap draws the grid in the fixed "
                 "frame", warnings);
  }
  int normal_cells = 0;
  section.ReadInt("Normal Cell Count", normal_cells, 0);
  if (normal_cells != 0) {
    section.Warn("Normal Cell Count", "is not 0; urdfsnap draws a flat grid", warnings);
  }
  std::string style = "Lines";
  section.ReadString("Line Style", style);
  if (style != "Lines") {
    section.Warn("Line Style", "is not Lines; urdfsnap draws 1-pixel lines", warnings);
  }
}

// The RobotModel display's properties (src/rviz/default_plugin/robot_model_display.cpp L60-86;
// RViz 2's robot_model_display.cpp L89-146 has the same names); a disabled display hides the robot.
// Where the description comes from ("Robot Description" in RViz 1, "Description Source", "Topic"
// and "File" in RViz 2) is the model argument's job.
void ReadRobotModel(const Display& display, scene::SceneOptions& scene, Warnings& warnings) {
  display.section.ReadBool("Visual Enabled", scene.show_visual);
  display.section.ReadBool("Collision Enabled", scene.show_collision);
  display.section.ReadNumber("Alpha", scene.alpha, 0, 1);
  if (!display.enabled) scene.show_visual = scene.show_collision = false;
  std::string tf_prefix;
  display.section.ReadString("TF Prefix", tf_prefix);
  if (!tf_prefix.empty()) {
    display.section.Warn("TF Prefix", "is not empty; urdfsnap names frames by their links",
                         warnings);
  }
}

// The TF display's properties (src/rviz/default_plugin/tf_display.cpp L164-191).
void ReadTf(const Display& display, scene::TfOptions& tf, Warnings& warnings) {
  const Section& section = display.section;
  tf.enabled = display.enabled;
  section.ReadBool("Show Names", tf.show_names);
  section.ReadBool("Show Axes", tf.show_axes);
  section.ReadBool("Show Arrows", tf.show_arrows);
  section.ReadNumber("Marker Scale", tf.marker_scale);
  double marker_alpha = 1;
  section.ReadNumber("Marker Alpha", marker_alpha, 0, 1);
  if (marker_alpha != 1) {
    section.Warn("Marker Alpha", "is not 1; urdfsnap draws opaque TF markers", warnings);
  }
  // "Frames": "All Enabled" and one checkbox per frame, saved under the frame's name
  // (TFDisplay::load, rviz_default_plugins/displays/tf/tf_display.cpp)
  const std::optional<Section> frames = section.Child("Frames", section.name() + ": 'Frames'");
  if (!frames) return;
  bool all_enabled = true;
  frames->ReadBool("All Enabled", all_enabled);
  bool each_enabled = true;
  for (const auto& entry : section.Entry("Frames")) {
    if (!entry.first.IsScalar() || entry.first.Scalar() == "All Enabled") continue;
    bool enabled = true;
    frames->ReadBool(entry.first.Scalar().c_str(), enabled);
    each_enabled = each_enabled && enabled;
  }
  if (!all_enabled || !each_enabled) {
    section.Warn("Frames", "hides some frames; urdfsnap draws every frame", warnings);
  }
}

// Views/Current (src/rviz/view_manager.cpp) when it is an Orbit view: its properties in
// src/rviz/default_plugin/view_controllers/orbit_view_controller.cpp L58-88 and the near clip of
// src/rviz/view_controller.cpp L58-62, with their limits. Returns whether the file has such a view.
bool ReadView(const Section& manager, scene::OrbitView& view, std::string& target_frame, Warnings& warnings) {
  const std::optional<Section> views = manager.Child("Views", "Views");
  if (!views) return false;
  const std::optional<Section> current = views->Child("Current", "Views/Current");
  if (!current) return false;
  std::string class_id;
  current->ReadString("Class", class_id);
  if (!IsOrbitView(class_id)) {
    current->Warn("Class", "is '" + class_id + "', not rviz/Orbit; urdfsnap keeps its default view",
                  warnings);
    return false;
  }
  constexpr double kMaxPitch = std::numbers::pi / 2 - 0.001;
  current->ReadNumber("Distance", view.distance, 0.001);
  current->ReadNumber("Yaw", view.yaw);
  current->ReadNumber("Pitch", view.pitch, -kMaxPitch, kMaxPitch);
  ReadVector(*current, "Focal Point", view.focal);
  current->ReadNumber("Field of View", view.fov_y, 0.001, std::numbers::pi / 2);
  current->ReadNumber("Near Clip Distance", view.near_clip, 0.001, 10000);

  std::string target = kFixedFrameString;
  ReadFrame(*current, "Target Frame", target);
  target_frame = target == kFixedFrameString ? "" : target;

  // what urdfsnap's orbit camera cannot follow
  bool invert_z = false;
  current->ReadBool("Invert Z Axis", invert_z);
  if (invert_z) current->Warn("Invert Z Axis", "is true; urdfsnap keeps +Z up", warnings);
  return true;
}

// Throws when the file has no display urdfsnap follows and no orbit view: RViz would show nothing
// urdfsnap can reproduce, so rendering its defaults would hide the mistake.
void RequireSomethingUsable(const std::string& path, const Displays& displays, bool has_view) {
  if (has_view || !displays.grids.empty() || !displays.robot_models.empty() ||
      !displays.tfs.empty() || !displays.messages.empty()) {
    return;
  }
  std::string skipped;
  for (const std::string& class_id : displays.skipped) {
    skipped += (skipped.empty() ? "'" : ", '") + class_id + "'";
  }
  throw Error(SourceLocation{path, 0},
              "nothing urdfsnap can use: no Grid, RobotModel, TF or message display and no Orbit view" +
                  (skipped.empty() ? std::string() : "; skipped display classes " + skipped));
}

}  // namespace

RvizConfig ReadRvizConfig(const std::string& path, const RvizConfig& defaults, Warnings& warnings) {
  std::string text;
  try {
    text = ReadFileBounded(path);
  } catch (const FileReadError& e) {
    throw Error(SourceLocation{path, 0}, std::string("cannot read the .rviz file: ") + e.what());
  }
  return ParseRvizConfig(text, path, defaults, warnings);
}

RvizConfig ParseRvizConfig(const std::string& text, const std::string& path,
                           const RvizConfig& defaults, Warnings& warnings) {
  const YAML::Node root = LoadYaml(text, path);
  if (!root.IsMap() || !root["Visualization Manager"].IsDefined()) {
    throw Error(SourceLocation{path, 0},
                "expected an .rviz file with a 'Visualization Manager' section");
  }
  const Section manager = RvizSection(path, root["Visualization Manager"], "Visualization Manager");

  RvizConfig config = defaults;
  ReadGlobalOptions(manager, config.scene);

  Displays displays;
  CollectDisplays(manager, true, displays, warnings);
  if (const Display* grid = Chosen(displays.grids, warnings)) {
    ReadGrid(*grid, config.scene.fixed_frame, config.scene.grid, warnings);
  } else {
    config.scene.grid.enabled = false;  // RViz draws no grid without a Grid display
  }
  if (const Display* robot_model = Chosen(displays.robot_models, warnings)) {
    ReadRobotModel(*robot_model, config.scene, warnings);
  }
  if (const Display* tf = Chosen(displays.tfs, warnings)) ReadTf(*tf, config.scene.tf, warnings);

  const bool has_view = ReadView(manager, config.view, config.target_frame, warnings);
  RequireSomethingUsable(path, displays, has_view);
  config.displays = std::move(displays.messages);
  return config;
}

}  // namespace urdfsnap::request
