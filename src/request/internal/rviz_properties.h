// How RViz 1.14 saves the property types that several displays share (frames, colours, vectors)
// and how they are read back from a `.rviz` file, limited as RViz's property classes limit them
// (src/rviz/properties/*.cpp in ros-visualization/rviz).
#pragma once

#include <string>

#include <Eigen/Core>

#include "common/internal/yaml_section.h"

namespace urdfsnap::request {

// What a frame property holds when it follows the fixed frame
// (TfFrameProperty::FIXED_FRAME_STRING, src/rviz/properties/tf_frame_property.cpp).
inline constexpr const char* kFixedFrameString = "<Fixed Frame>";

// A section of the file: RViz saves a property with sub-properties as a map with its "Value".
YamlSection RvizSection(const std::string& path, const YAML::Node& map, const std::string& name);

// A TF frame name; RViz drops a leading '/' (TfFrameProperty::setValue, tf_frame_property.cpp).
void ReadFrame(const YamlSection& section, const char* key, std::string& out);

// ColorProperty's "R; G; B" with each integer limited to 0..255 (parseColor, parse_color.cpp).
void ReadColour(const YamlSection& section, const char* key, Eigen::Vector3f& out);

// VectorProperty's map of X, Y and Z, all three or none (VectorProperty::load,
// vector_property.cpp).
void ReadVector(const YamlSection& section, const char* key, Eigen::Vector3d& out);

}  // namespace urdfsnap::request
