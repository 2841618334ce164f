// Reading .rviz files: every honoured property of a file laid out as RViz 1.14 saves it and of one
// as RViz 2 saves it, defaults for missing keys, RViz's limits, errors with file and line, and
// warnings (unit).
#include "request/rviz_config.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <variant>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"

namespace urdfsnap::request {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Saved by RViz 1.14 with every honoured property away from its default (keys sorted, floats as
// RViz prints them), plus a display class urdfsnap does not draw.
constexpr const char* kEveryProperty = R"(Panels:
  - Class: rviz/Displays
    Help Height: 78
    Name: Displays
    Property Tree Widget:
      Expanded:
        - /Global Options1
      Splitter Ratio: 0.5
    Tree Height: 549
  - Class: rviz/Views
    Expanded:
      - /Current View1
    Name: Views
    Splitter Ratio: 0.5
Preferences:
  PromptSaveOnExit: true
Toolbars:
  toolButtonStyle: 2
Visualization Manager:
  Class: ""
  Displays:
    - Alpha: 0.25
      Cell Size: 0.5
      Class: rviz/Grid
      Color: 10; 20; 30
      Enabled: true
      Line Style:
        Line Width: 0.029999999329447746
        Value: Lines
      Name: Grid
      Normal Cell Count: 0
      Offset:
        X: 1
        Y: -2
        Z: 0.5
      Plane: XZ
      Plane Cell Count: 4
      Reference Frame: <Fixed Frame>
      Value: true
    - Alpha: 0.5
      Class: rviz/RobotModel
      Collision Enabled: true
      Enabled: true
      Links:
        All Links Enabled: true
        Expand Joint Details: false
        Expand Link Details: false
        Expand Tree: false
        Link Tree Style: Links in Alphabetic Order
      Name: RobotModel
      Robot Description: robot_description
      TF Prefix: ""
      Update Interval: 0
      Value: true
      Visual Enabled: false
    - Class: rviz/TF
      Enabled: true
      Frame Timeout: 15
      Frames:
        All Enabled: true
      Marker Alpha: 1
      Marker Scale: 2.5
      Name: TF
      Show Arrows: false
      Show Axes: false
      Show Names: false
      Tree:
        {}
      Update Interval: 0
      Value: true
    - Class: rviz/MarkerArray
      Enabled: true
      Marker Topic: /visualization_marker_array
      Name: MarkerArray
      Namespaces:
        {}
      Queue Size: 100
      Value: true
  Enabled: true
  Global Options:
    Background Color: 255; 128; 0
    Default Light: true
    Fixed Frame: /link_02
    Frame Rate: 30
  Name: root
  Tools:
    - Class: rviz/Interact
      Hide Inactive Objects: true
    - Class: rviz/MoveCamera
  Value: true
  Views:
    Current:
      Class: rviz/Orbit
      Distance: 3.25
      Enable Stereo Rendering:
        Stereo Eye Separation: 0.05999999865889549
        Stereo Focal Distance: 1
        Swap Stereo Eyes: false
        Value: false
      Field of View: 0.5
      Focal Point:
        X: 0.10000000149011612
        Y: -0.20000000298023224
        Z: 0.30000001192092896
      Focal Shape Fixed Size: true
      Focal Shape Size: 0.05000000074505806
      Invert Z Axis: false
      Name: Current View
      Near Clip Distance: 0.05
      Pitch: -0.25
      Target Frame: <Fixed Frame>
      Yaw: 5.5
    Saved: ~
Window Geometry:
  Displays:
    collapsed: false
  Height: 846
  Hide Left Dock: false
  Hide Right Dock: false
  QMainWindow State: 000000ff00000000fd00000004000000000000015600000
  Views:
    collapsed: false
  Width: 1200
  X: 72
  Y: 27
)";

struct RvizConfigTest : ::testing::Test {
  // Writes `text` to a file of its own and reads it on top of `defaults`.
  RvizConfig Read(const std::string& text, const RvizConfig& defaults = {}) {
    std::ofstream(path) << text;
    return ReadRvizConfig(path, defaults, warnings);
  }
  // The message ReadRvizConfig throws for `text`.
  std::string ErrorFor(const std::string& text) {
    try {
      Read(text);
    } catch (const Error& error) {
      return error.what();
    }
    return "(no error)";
  }
  // one file per test: ctest runs the tests of this binary in parallel processes
  const std::string path = ::testing::TempDir() + "rviz_config_test_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".rviz";
  Warnings warnings;
};

TEST_F(RvizConfigTest, ReadsEveryPropertyOfAFileRvizWrote) {
  const RvizConfig config = Read(kEveryProperty);
  const scene::SceneOptions& scene = config.scene;
  EXPECT_EQ(scene.fixed_frame, "link_02");  // RViz drops the leading '/'
  EXPECT_TRUE(scene.background.isApprox(Eigen::Vector3f(1, 128 / 255.f, 0)));

  EXPECT_TRUE(scene.grid.enabled);
  EXPECT_EQ(scene.grid.plane_cell_count, 4);
  EXPECT_EQ(scene.grid.cell_size, 0.5);
  EXPECT_TRUE(scene.grid.colour.isApprox(Eigen::Vector3f(10, 20, 30) / 255.f));
  EXPECT_EQ(scene.grid.alpha, 0.25f);
  EXPECT_EQ(scene.grid.plane, scene::GridOptions::Plane::kXZ);
  EXPECT_EQ(scene.grid.offset, Eigen::Vector3d(1, -2, 0.5));

  EXPECT_FALSE(scene.show_visual);
  EXPECT_TRUE(scene.show_collision);
  EXPECT_EQ(scene.alpha, 0.5);

  EXPECT_TRUE(scene.tf.enabled);
  EXPECT_FALSE(scene.tf.show_names);
  EXPECT_FALSE(scene.tf.show_axes);
  EXPECT_FALSE(scene.tf.show_arrows);
  EXPECT_EQ(scene.tf.marker_scale, 2.5);

  const scene::OrbitView& view = config.view;
  EXPECT_EQ(view.distance, 3.25);
  EXPECT_EQ(view.yaw, 5.5);
  EXPECT_EQ(view.pitch, -0.25);
  EXPECT_TRUE(view.focal.isApprox(Eigen::Vector3d(0.1, -0.2, 0.3), 1e-7));
  EXPECT_EQ(view.fov_y, 0.5);
  EXPECT_EQ(view.near_clip, 0.05);
  EXPECT_EQ(view.far_clip, scene::OrbitView{}.far_clip);

  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(config.displays.size(), 1u);   // the MarkerArray display, read by rviz_displays
  EXPECT_TRUE(std::holds_alternative<display::MarkerSettings>(config.displays[0].kind));
}

TEST_F(RvizConfigTest, MrmSampleIsTheCloseView) {
  const RvizConfig config =
      ReadRvizConfig(URDFSNAP_SOURCE_DIR "/tests/data/mrm.rviz", {}, warnings);
  EXPECT_EQ(config.scene.fixed_frame, "base_link");
  EXPECT_NEAR(config.view.yaw, 0.6, 1e-7);
  EXPECT_NEAR(config.view.pitch, 0.35, 1e-7);
  EXPECT_EQ(config.view.distance, 4.5);
  EXPECT_TRUE(config.view.focal.isApprox(Eigen::Vector3d(0, 0, 1.2), 1e-7));
  EXPECT_NEAR(config.view.fov_y, scene::OrbitView{}.fov_y, 1e-7);
  EXPECT_NEAR(config.view.near_clip, scene::OrbitView{}.near_clip, 1e-9);
  // everything else is RViz's default: grid and robot on, TF off
  const scene::SceneOptions defaults;
  EXPECT_EQ(config.scene.background, defaults.background);
  EXPECT_TRUE(config.scene.grid.enabled);
  EXPECT_EQ(config.scene.grid.plane_cell_count, defaults.grid.plane_cell_count);
  EXPECT_EQ(config.scene.grid.colour, defaults.grid.colour);
  EXPECT_EQ(config.scene.grid.alpha, defaults.grid.alpha);
  EXPECT_TRUE(config.scene.show_visual);
  EXPECT_FALSE(config.scene.show_collision);
  EXPECT_FALSE(config.scene.tf.enabled);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(config.displays.size(), 1u);  // the MarkerArray display
}

TEST_F(RvizConfigTest, MissingKeysKeepTheDefaults) {
  RvizConfig defaults;
  defaults.scene.fixed_frame = "base";
  defaults.scene.alpha = 0.3;
  defaults.scene.grid.cell_size = 2;
  defaults.scene.tf.marker_scale = 3;
  defaults.view.yaw = 1;
  defaults.view.focal = {1, 2, 3};
  const RvizConfig config = Read(R"(Visualization Manager:
  Displays:
    - Class: rviz/Grid
      Enabled: true
    - Class: rviz/RobotModel
      Enabled: true
    - Class: rviz/TF
      Enabled: true
  Views:
    Current:
      Class: rviz/Orbit
)",
                                 defaults);
  EXPECT_EQ(config.scene.fixed_frame, "base");
  EXPECT_EQ(config.scene.alpha, 0.3);
  EXPECT_TRUE(config.scene.show_visual);
  EXPECT_EQ(config.scene.grid.cell_size, 2);
  EXPECT_EQ(config.scene.grid.plane, scene::GridOptions::Plane::kXY);
  EXPECT_TRUE(config.scene.tf.enabled);
  EXPECT_EQ(config.scene.tf.marker_scale, 3);
  EXPECT_EQ(config.view.yaw, 1);
  EXPECT_EQ(config.view.focal, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(config.view.distance, scene::OrbitView{}.distance);
  EXPECT_TRUE(warnings.empty());
}

TEST_F(RvizConfigTest, GridIsOffWithoutAnEnabledGridDisplay) {
  const std::string orbit = "  Views:\n    Current:\n      Class: rviz/Orbit\n";
  EXPECT_FALSE(Read("Visualization Manager:\n  Displays: []\n" + orbit).scene.grid.enabled);
  EXPECT_FALSE(Read("Visualization Manager:\n  Class: \"\"\n" + orbit).scene.grid.enabled);
  EXPECT_FALSE(Read(R"(Visualization Manager:
  Displays:
    - Class: rviz/Grid
      Enabled: false
      Value: false
)").scene.grid.enabled);
}

TEST_F(RvizConfigTest, EnabledFollowsRvizsCheckbox) {
  // Display::load (display.cpp): "Value", then "Enabled"; neither means unchecked
  const char* kTf = "Visualization Manager:\n  Displays:\n    - Class: rviz/TF\n";
  EXPECT_TRUE(Read(std::string(kTf) + "      Value: true\n").scene.tf.enabled);
  EXPECT_FALSE(Read(std::string(kTf) + "      Value: true\n      Enabled: false\n").scene.tf.enabled);
  EXPECT_FALSE(Read(std::string(kTf) + "      Show Names: false\n").scene.tf.enabled);
}

TEST_F(RvizConfigTest, DisabledRobotModelHidesVisualAndCollision) {
  const RvizConfig config = Read(R"(Visualization Manager:
  Displays:
    - Class: rviz/RobotModel
      Collision Enabled: true
      Enabled: false
      Visual Enabled: true
)");
  EXPECT_FALSE(config.scene.show_visual);
  EXPECT_FALSE(config.scene.show_collision);
}

TEST_F(RvizConfigTest, DisplaysInGroupsCountAndFollowTheGroup) {
  const char* kGroup = R"(Visualization Manager:
  Displays:
    - Class: rviz/Group
      Enabled: %s
      Name: Robot
      Displays:
        - Class: rviz/Grid
          Enabled: true
          Cell Size: 0.25
)";
  char text[256];
  std::snprintf(text, sizeof(text), kGroup, "true");
  const RvizConfig on = Read(text);
  EXPECT_TRUE(on.scene.grid.enabled);
  EXPECT_EQ(on.scene.grid.cell_size, 0.25);
  std::snprintf(text, sizeof(text), kGroup, "false");
  EXPECT_FALSE(Read(text).scene.grid.enabled);
}

TEST_F(RvizConfigTest, ValuesAreLimitedAsRvizPropertiesLimitThem) {
  const RvizConfig config = Read(R"(Visualization Manager:
  Global Options:
    Background Color: 300; -5; 12
  Displays:
    - Class: rviz/Grid
      Enabled: true
      Alpha: 1.5
      Cell Size: 0
      Plane Cell Count: 0
    - Class: rviz/RobotModel
      Enabled: true
      Alpha: -1
  Views:
    Current:
      Class: rviz/Orbit
      Distance: 0
      Field of View: 3
      Near Clip Distance: 0
      Pitch: 2
)");
  EXPECT_TRUE(config.scene.background.isApprox(Eigen::Vector3f(1, 0, 12 / 255.f)));
  EXPECT_EQ(config.scene.grid.alpha, 1.f);
  EXPECT_EQ(config.scene.grid.cell_size, 0.0001);
  EXPECT_EQ(config.scene.grid.plane_cell_count, 1);
  EXPECT_EQ(config.scene.alpha, 0);
  EXPECT_EQ(config.view.distance, 0.001);
  EXPECT_EQ(config.view.fov_y, std::numbers::pi / 2);
  EXPECT_EQ(config.view.near_clip, 0.001);
  EXPECT_EQ(config.view.pitch, std::numbers::pi / 2 - 0.001);
}

// A broken file and the "LINE: message" it must give.
struct BadFile {
  const char* text;
  const char* located_message;
};

TEST_F(RvizConfigTest, BadFilesAreErrorsAtTheirLine) {
  const BadFile cases[] = {
      {"Visualization Manager:\n  Displays: [\n", "3: bad YAML: "},
      {"Panels: []\n", "expected an .rviz file with a 'Visualization Manager' section"},
      {"Visualization Manager:\n  Global Options:\n    Background Color: red\n",
       "3: Global Options: 'Background Color': expected a colour \"R; G; B\" (three integers), "
       "got 'red'"},
      {"Visualization Manager:\n  Global Options:\n    Background Color: 1; 2\n",
       "3: Global Options: 'Background Color': expected a colour"},
      {"Visualization Manager:\n  Displays:\n    - Class: rviz/Grid\n      Name: Grid\n"
       "      Cell Size: big\n",
       "5: rviz/Grid display 'Grid': 'Cell Size': expected a number, got 'big'"},
      {"Visualization Manager:\n  Displays:\n    - Class: rviz/Grid\n      Plane: XW\n",
       "4: rviz/Grid display '': 'Plane': expected XY, XZ or YZ, got 'XW'"},
      {"Visualization Manager:\n  Displays:\n    - Class: rviz/Grid\n      Plane Cell Count: 2.5\n",
       "4: rviz/Grid display '': 'Plane Cell Count': expected an integer, got '2.5'"},
      {"Visualization Manager:\n  Displays:\n    - Class: rviz/TF\n      Enabled: maybe\n",
       "4: rviz/TF display '': 'Enabled': expected true or false, got 'maybe'"},
      {"Visualization Manager:\n  Displays:\n    - Name: Grid\n",
       "3: display: 'Class': expected a display class such as rviz/Grid, got nothing"},
      {"Visualization Manager:\n  Displays: {}\n",
       "2: Visualization Manager: 'Displays': expected a list of displays, got a map"},
      {"Visualization Manager:\n  Views:\n    Current:\n      Class: rviz/Orbit\n"
       "      Focal Point:\n        X: 1\n        Y: 2\n",
       "5: Views/Current: 'Focal Point': expected a map of X, Y and Z, got a map"},
      {"Visualization Manager:\n  Views:\n    Current:\n      Class: rviz/Orbit\n"
       "      Focal Point: 3\n",
       "5: Views/Current: 'Focal Point': expected a map, got '3'"},
      {"Visualization Manager:\n  Views:\n    Current:\n      Class: rviz/Orbit\n"
       "      Yaw: [1]\n",
       "5: Views/Current: 'Yaw': expected a number, got a list"},
  };
  for (const BadFile& bad : cases) {
    SCOPED_TRACE(bad.text);
    const std::string message = ErrorFor(bad.text);
    const bool has_line = std::isdigit(static_cast<unsigned char>(bad.located_message[0]));
    EXPECT_THAT(message, HasSubstr((has_line ? path + ":" : path + ": ") + bad.located_message));
  }
}

TEST_F(RvizConfigTest, MissingFileIsAnError) {
  try {
    ReadRvizConfig(path + ".missing", {}, warnings);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()), path + ".missing: cannot read the .rviz file: No such file or directory");
  }
}

TEST_F(RvizConfigTest, UnknownDisplayClassesWarnOncePerClass) {
  const RvizConfig config = Read(R"(Visualization Manager:
  Displays:
    - Class: rviz/Map
      Enabled: true
      Name: Map A
    - Class: rviz/Map
      Enabled: true
      Name: Map B
    - Class: rviz/Image
      Enabled: true
      Name: Cloud
  Views:
    Current:
      Class: rviz/Orbit
)");
  EXPECT_THAT(warnings.messages(),
              ElementsAre(path + ": skipped display class 'rviz/Map', which urdfsnap "
                                 "does not draw",
                          path + ": skipped display class 'rviz/Image', which urdfsnap "
                                 "does not draw"));
  EXPECT_FALSE(config.scene.grid.enabled);
}

TEST_F(RvizConfigTest, OtherViewsKeepTheDefaultViewWithAWarning) {
  RvizConfig defaults;
  defaults.view.yaw = 1.25;
  const RvizConfig config = Read(R"(Visualization Manager:
  Views:
    Current:
      Class: rviz/TopDownOrtho
      Scale: 10
  Displays:
    - Class: rviz/Grid
)",
                                 defaults);
  EXPECT_EQ(config.view.yaw, 1.25);
  EXPECT_THAT(warnings.messages(),
              ElementsAre(path + ":4: Views/Current: 'Class' is 'rviz/TopDownOrtho', not "
                                 "rviz/Orbit; urdfsnap keeps its default view"));
}

TEST_F(RvizConfigTest, PropertiesUrdfsnapCannotFollowAreWarnings) {
  const RvizConfig config = Read(R"(Visualization Manager:
  Global Options:
    Fixed Frame: base_link
  Displays:
    - Class: rviz/Grid
      Enabled: true
      Name: Grid
      Reference Frame: link_01
      Normal Cell Count: 2
      Line Style:
        Line Width: 0.05
        Value: Billboards
    - Class: rviz/Grid
      Enabled: true
      Name: Grid 2
    - Class: rviz/TF
      Enabled: true
      Name: TF
      Marker Alpha: 0.5
  Views:
    Current:
      Class: rviz/Orbit
      Invert Z Axis: true
      Target Frame: link_01
)");
  EXPECT_THAT(
      warnings.messages(),
      ElementsAre(path + ":14: rviz/Grid display 'Grid 2': 'Enabled' is true, but urdfsnap draws "
                         "only the first enabled display of a class",
                  path + ":8: rviz/Grid display 'Grid': 'Reference Frame' is not the fixed frame; "
                         "urdfsnap draws the grid in the fixed frame",
                  path + ":9: rviz/Grid display 'Grid': 'Normal Cell Count' is not 0; urdfsnap "
                         "draws a flat grid",
                  path + ":10: rviz/Grid display 'Grid': 'Line Style' is not Lines; urdfsnap "
                         "draws 1-pixel lines",
                  path + ":19: rviz/TF display 'TF': 'Marker Alpha' is not 1; urdfsnap draws "
                         "opaque TF markers",
                  path + ":23: Views/Current: 'Invert Z Axis' is true; urdfsnap keeps +Z up"));
  // the view's Target Frame is followed (--follow)
  EXPECT_EQ(config.target_frame, "link_01");
}

// Laid out as RViz 2 (Humble) saves a package's view_robot.rviz, as ur_description ships one, with
// a TF display added: rviz_default_plugins/* and rviz_common/* classes, QoS maps for topics.
constexpr const char* kRviz2Config = R"(Panels:
  - Class: rviz_common/Displays
    Name: Displays
  - Class: rviz_common/Views
    Name: Views
Visualization Manager:
  Class: ""
  Displays:
    - Alpha: 0.5
      Cell Size: 0.25
      Class: rviz_default_plugins/Grid
      Color: 160; 160; 164
      Enabled: true
      Line Style:
        Line Width: 0.05000000074505806
        Value: Lines
      Name: Floor
      Normal Cell Count: 0
      Offset:
        X: 0
        Y: 0
        Z: 0.009999999776482582
      Plane: XY
      Plane Cell Count: 20
      Reference Frame: <Fixed Frame>
      Value: true
    - Class: rviz_common/Group
      Displays:
        - Alpha: 0.75
          Class: rviz_default_plugins/RobotModel
          Collision Enabled: true
          Description File: ""
          Description Source: Topic
          Description Topic:
            Depth: 5
            Durability Policy: Volatile
            History Policy: Keep Last
            Reliability Policy: Reliable
            Value: /robot_description
          Enabled: true
          Links:
            All Links Enabled: true
            base_link:
              Alpha: 1
              Show Axes: false
              Show Trail: false
              Value: true
          Name: RobotModel
          TF Prefix: ""
          Update Interval: 0
          Value: true
          Visual Enabled: false
      Enabled: true
      Name: Robot
    - Class: rviz_default_plugins/TF
      Enabled: true
      Filter (blacklist): ""
      Filter (whitelist): ""
      Frame Timeout: 15
      Frames:
        All Enabled: true
        base_link:
          Value: true
        tool0:
          Value: true
      Marker Scale: 0.5
      Name: TF
      Show Arrows: true
      Show Axes: true
      Show Names: false
      Tree:
        base_link:
          tool0:
            {}
      Update Interval: 0
      Value: true
    - Class: rviz_default_plugins/Image
      Enabled: true
      Name: LaserScan
  Enabled: true
  Global Options:
    Background Color: 48; 48; 48
    Fixed Frame: base_link
    Frame Rate: 30
  Name: root
  Tools:
    - Class: rviz_default_plugins/Interact
      Hide Inactive Objects: true
  Transformation:
    Current:
      Class: rviz_default_plugins/TF
  Value: true
  Views:
    Current:
      Class: rviz_default_plugins/Orbit
      Distance: 3.493516445159912
      Enable Stereo Rendering:
        Stereo Eye Separation: 0.05999999865889549
        Stereo Focal Distance: 1
        Swap Stereo Eyes: false
        Value: false
      Focal Point:
        X: -0.0457618348300457
        Y: -0.07058511674404144
        Z: 0.49734944105148315
      Focal Shape Fixed Size: true
      Focal Shape Size: 0.05000000074505806
      Invert Z Axis: false
      Name: Current View
      Near Clip Distance: 0.009999999776482582
      Pitch: 0.15039828419685364
      Target Frame: <Fixed Frame>
      Value: Orbit (rviz)
      Yaw: 0.5353983640670776
    Saved: ~
)";

TEST_F(RvizConfigTest, ReadsRviz2ConfigsAsRviz1Ones) {
  const RvizConfig config = Read(kRviz2Config);
  const scene::SceneOptions& scene = config.scene;
  EXPECT_EQ(scene.fixed_frame, "base_link");
  EXPECT_TRUE(scene.grid.enabled);
  EXPECT_EQ(scene.grid.cell_size, 0.25);
  EXPECT_EQ(scene.grid.plane_cell_count, 20);
  EXPECT_EQ(scene.grid.alpha, 0.5f);
  EXPECT_NEAR(scene.grid.offset.z(), 0.01, 1e-9);
  EXPECT_FALSE(scene.show_visual);  // in an rviz_common/Group
  EXPECT_TRUE(scene.show_collision);
  EXPECT_EQ(scene.alpha, 0.75);
  EXPECT_TRUE(scene.tf.enabled);
  EXPECT_FALSE(scene.tf.show_names);
  EXPECT_EQ(scene.tf.marker_scale, 0.5);
  EXPECT_NEAR(config.view.distance, 3.4935164, 1e-6);
  EXPECT_NEAR(config.view.yaw, 0.5353984, 1e-6);
  EXPECT_NEAR(config.view.pitch, 0.1503983, 1e-6);
  EXPECT_TRUE(config.view.focal.isApprox(Eigen::Vector3d(-0.0457618, -0.0705851, 0.4973494), 1e-6));
  EXPECT_NEAR(config.view.near_clip, 0.01, 1e-9);
  EXPECT_THAT(warnings.messages(),
              ElementsAre(path + ": skipped display class 'rviz_default_plugins/Image', which "
                                 "urdfsnap does not draw"));
}

TEST_F(RvizConfigTest, NothingUsableIsAnErrorNamingWhatWasSkipped) {
  EXPECT_EQ(ErrorFor(R"(Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/Image
      Name: Scan
    - Class: rviz_default_plugins/Map
      Name: Map
  Views:
    Current:
      Class: rviz_default_plugins/TopDownOrtho
)"),
            path + ": nothing urdfsnap can use: no Grid, RobotModel, TF or message display and "
                   "no Orbit view; skipped display classes 'rviz_default_plugins/Image', "
                   "'rviz_default_plugins/Map'");
  EXPECT_EQ(ErrorFor("Visualization Manager:\n  Displays: []\n"),
            path + ": nothing urdfsnap can use: no Grid, RobotModel, TF or message display and "
                   "no Orbit view");
}

TEST_F(RvizConfigTest, Rviz2PropertiesUrdfsnapCannotFollowAreWarnings) {
  Read(R"(Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/RobotModel
      Enabled: true
      Name: Robot
      TF Prefix: left
    - Class: rviz_default_plugins/TF
      Enabled: true
      Name: TF
      Frames:
        All Enabled: true
        base_link:
          Value: false
)");
  EXPECT_THAT(warnings.messages(),
              ElementsAre(path + ":6: rviz_default_plugins/RobotModel display 'Robot': 'TF "
                                 "Prefix' is not empty; urdfsnap names frames by their links",
                          path + ":10: rviz_default_plugins/TF display 'TF': 'Frames' hides some "
                                 "frames; urdfsnap draws every frame"));
}

}  // namespace
}  // namespace urdfsnap::request
