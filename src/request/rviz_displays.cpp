// Each message display's properties, as RViz 1.14's *_display.cpp constructors name them (the
// names RViz 2 gives differently are read too: "Topic" for markers, PoseArray's "Arrow 2D Length"
// and "Arrow 3D ..." properties).
#include "request/internal/rviz_displays.h"

#include "request/internal/rviz_point_clouds.h"
#include "request/internal/rviz_properties.h"

namespace urdfsnap::request {
namespace {

float ReadAlpha(const YamlSection& section, float alpha) {
  double value = alpha;
  section.ReadNumber("Alpha", value, 0, 1);
  return static_cast<float>(value);
}

// marker_display.cpp: "Marker Topic" (RViz 2: "Topic") and "Namespaces", a checkbox per namespace.
display::MarkerSettings ReadMarkers(bool array, const YamlSection& section, std::string& topic) {
  display::MarkerSettings settings;
  settings.array = array;
  topic = array ? "/visualization_marker_array" : "/visualization_marker";
  section.ReadString("Topic", topic);
  section.ReadString("Marker Topic", topic);
  const std::optional<YamlSection> namespaces = section.Child("Namespaces", section.name() + ": 'Namespaces'");
  if (namespaces) {
    for (const auto& entry : section.Entry("Namespaces")) {
      if (!entry.first.IsScalar() || entry.first.Scalar() == "Value") continue;
      bool shown = true;
      namespaces->ReadBool(entry.first.Scalar().c_str(), shown);
      settings.namespaces[entry.first.Scalar()] = shown;
    }
  }
  return settings;
}

// path_display.cpp
display::PathSettings ReadPath(const YamlSection& section, Warnings& warnings) {
  display::PathSettings settings;
  std::string style = "Lines";
  section.ReadString("Line Style", style);
  if (style == "Billboards") {
    settings.line_style = display::PathSettings::LineStyle::kBillboards;
  } else if (style != "Lines") {
    section.Fail("Line Style", "Lines or Billboards");
  }
  ReadColour(section, "Color", settings.colour);
  settings.alpha = ReadAlpha(section, settings.alpha);
  section.ReadNumber("Line Width", settings.line_width, 0.001);
  section.ReadInt("Buffer Length", settings.buffer_length, 1);
  ReadVector(section, "Offset", settings.offset);
  std::string pose_style = "None";
  section.ReadString("Pose Style", pose_style);
  if (pose_style != "None") section.Warn("Pose Style", "is not None; urdfsnap draws the path's line only", warnings);
  return settings;
}

// pose_array_display.cpp (RViz 2: "Arrow 2D Length" and "Arrow 3D Head Radius" ...)
display::PoseArraySettings ReadPoseArray(const YamlSection& section) {
  display::PoseArraySettings settings;
  if (section.Value("Shape").IsDefined()) {
    std::string shape;
    section.ReadString("Shape", shape);
    if (shape == "Arrow (Flat)") {
      settings.shape = display::PoseArraySettings::Shape::kArrowFlat;
    } else if (shape == "Arrow (3D)") {
      settings.shape = display::PoseArraySettings::Shape::kArrow3d;
    } else if (shape == "Axes") {
      settings.shape = display::PoseArraySettings::Shape::kAxes;
    } else {
      section.Fail("Shape", "Arrow (Flat), Arrow (3D) or Axes");
    }
  }
  ReadColour(section, "Color", settings.colour);
  settings.alpha = ReadAlpha(section, settings.alpha);
  const struct {
    const char* rviz1;
    const char* rviz2;
    double& out;
  } numbers[] = {{"Arrow Length", "Arrow 2D Length", settings.arrow_length},
                 {"Head Radius", "Arrow 3D Head Radius", settings.head_radius},
                 {"Head Length", "Arrow 3D Head Length", settings.head_length},
                 {"Shaft Radius", "Arrow 3D Shaft Radius", settings.shaft_radius},
                 {"Shaft Length", "Arrow 3D Shaft Length", settings.shaft_length},
                 {"Axes Length", "Axes Length", settings.axes_length},
                 {"Axes Radius", "Axes Radius", settings.axes_radius}};
  for (const auto& n : numbers) {
    section.ReadNumber(n.rviz1, n.out, 0.0001);
    section.ReadNumber(n.rviz2, n.out, 0.0001);
  }
  return settings;
}

// axes_display.cpp
display::AxesSettings ReadAxes(const YamlSection& section) {
  display::AxesSettings settings;
  std::string frame = kFixedFrameString;
  ReadFrame(section, "Reference Frame", frame);
  if (frame != kFixedFrameString) settings.reference_frame = frame;
  section.ReadNumber("Length", settings.length, 0.0001);
  section.ReadNumber("Radius", settings.radius, 0.0001);
  return settings;
}

}  // namespace

bool IsMessageDisplay(DisplayClass kind) {
  return kind == DisplayClass::kMarker || kind == DisplayClass::kMarkerArray || kind == DisplayClass::kPath ||
         kind == DisplayClass::kPoseArray || kind == DisplayClass::kAxes || kind == DisplayClass::kPointCloud2 ||
         kind == DisplayClass::kLaserScan;
}

display::DisplaySettings ReadMessageDisplay(DisplayClass kind, const YamlSection& section,
                                            const std::string& name, Warnings& warnings) {
  display::DisplaySettings settings{name, "", display::AxesSettings{}};
  if (kind == DisplayClass::kMarker || kind == DisplayClass::kMarkerArray) {
    settings.kind = ReadMarkers(kind == DisplayClass::kMarkerArray, section, settings.topic);
    return settings;
  }
  if (kind != DisplayClass::kAxes) section.ReadString("Topic", settings.topic);
  if (kind == DisplayClass::kPath) settings.kind = ReadPath(section, warnings);
  if (kind == DisplayClass::kPoseArray) settings.kind = ReadPoseArray(section);
  if (kind == DisplayClass::kAxes) settings.kind = ReadAxes(section);
  if (kind == DisplayClass::kPointCloud2 || kind == DisplayClass::kLaserScan) {
    settings.kind = display::CloudSettings{kind == DisplayClass::kLaserScan, ReadPointCloudSettings(section, warnings)};
  }
  return settings;
}

}  // namespace urdfsnap::request
