// Plain-text facts of a docs page: std::to_chars with a fixed number of significant digits.
#include "docs/fact_text.h"

#include <charconv>
#include <numbers>

namespace urdfsnap::docs {

namespace {

std::string Degrees(double radians) { return ShortNumber(radians * 180 / std::numbers::pi, 4) + "°"; }

bool IsAngular(const model::Joint& joint) {
  return joint.type == model::JointType::kRevolute || joint.type == model::JointType::kContinuous;
}

std::string Vector3Text(const Eigen::Vector3d& v) {
  std::string text = "(";
  text += ShortNumber(v.x()) + ", " + ShortNumber(v.y()) + ", " + ShortNumber(v.z()) + ")";
  return text;
}

// The last part of a mesh URI or path: "base.stl" for "package://arm/meshes/base.stl".
std::string FileName(const std::string& uri) {
  const size_t slash = uri.find_last_of('/');
  return slash == std::string::npos ? uri : uri.substr(slash + 1);
}

}  // namespace

std::string ShortNumber(double value, int digits) {
  char buffer[64];
  const auto [end, error] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  if (error != std::errc()) return "?";
  std::string text(buffer, end);
  if (text == "-0") text = "0";   // a negative zero reads as 0
  return text;
}

std::string PositionText(const model::Joint& joint, double value) {
  if (IsAngular(joint)) return ShortNumber(value) + " rad (" + Degrees(value) + ")";
  return ShortNumber(value) + " m";
}

std::string LimitsText(const model::Joint& joint) {
  switch (joint.type) {
    case model::JointType::kRevolute:
      return ShortNumber(joint.lower) + " to " + ShortNumber(joint.upper) + " rad (" + Degrees(joint.lower) +
             " to " + Degrees(joint.upper) + ")";
    case model::JointType::kPrismatic:
      return ShortNumber(joint.lower) + " to " + ShortNumber(joint.upper) + " m";
    case model::JointType::kContinuous: return "none (continuous)";
    default: return "—";
  }
}

std::string AxisText(const model::Joint& joint) {
  if (joint.type == model::JointType::kFixed || joint.type == model::JointType::kFloating) return "—";
  return Vector3Text(joint.axis);
}

std::string ShapeText(const model::Shape& shape) {
  switch (shape.type) {
    case model::Shape::Type::kBox:
      return "box " + ShortNumber(shape.box_size.x()) + " × " + ShortNumber(shape.box_size.y()) + " × " +
             ShortNumber(shape.box_size.z()) + " m";
    case model::Shape::Type::kCylinder:
      return "cylinder r " + ShortNumber(shape.radius) + " m, length " + ShortNumber(shape.length) + " m";
    case model::Shape::Type::kSphere: return "sphere r " + ShortNumber(shape.radius) + " m";
    case model::Shape::Type::kMesh: break;
  }
  std::string text = "mesh " + (shape.mesh_uri.empty() ? std::string("(no file)") : FileName(shape.mesh_uri));
  const Eigen::Vector3d& s = shape.mesh_scale;
  if (s.x() == s.y() && s.y() == s.z()) {
    if (s.x() != 1) text += ", scale " + ShortNumber(s.x());
  } else {
    text += ", scale " + Vector3Text(s);
  }
  return text;
}

}  // namespace urdfsnap::docs
