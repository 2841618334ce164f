// Strict parsing of option values: the whole text must be used, numbers must be finite.
#include "request/value_parsing.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "common/error.h"
#include "common/number_text.h"
#include "image/image.h"

namespace urdfsnap::request {

namespace {

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

}  // namespace

double ParseFinite(const std::string& text, const std::string& option) {
  double value = 0;
  if (!ParseNumber(text, value)) {
    throw Error(option + " '" + text + "': expected a finite number");
  }
  return value;
}

double ParseInRange(const std::string& text, const std::string& option, double low, double high) {
  const double value = ParseFinite(text, option);
  if (value < low || value > high) {
    throw Error(option + " '" + text + "': expected a value from " + FormatNumber(low) + " to " +
                FormatNumber(high));
  }
  return value;
}

render::ImageSize ParseImageSize(const std::string& text, const std::string& option) {
  const auto parts = Split(text, 'x');
  double w = 0, h = 0;
  if (parts.size() != 2 || !ParseNumber(parts[0], w) || !ParseNumber(parts[1], h) ||
      w != std::floor(w) || h != std::floor(h)) {
    throw Error(option + " '" + text + "': expected WIDTHxHEIGHT in pixels, e.g. 640x480");
  }
  if (w < 1 || h < 1 || w > image::kMaxImageSide || h > image::kMaxImageSide) {
    throw Error(option + " '" + text + "': each side must be between 1 and " +
                std::to_string(image::kMaxImageSide) + " pixels");
  }
  return {static_cast<int>(w), static_cast<int>(h)};
}

Eigen::Vector3d ParseVector3(const std::string& text, const std::string& option) {
  const auto parts = Split(text, ',');
  Eigen::Vector3d v;
  if (parts.size() != 3 || !ParseNumber(parts[0], v.x()) || !ParseNumber(parts[1], v.y()) ||
      !ParseNumber(parts[2], v.z())) {
    throw Error(option + " '" + text + "': expected three finite numbers X,Y,Z");
  }
  return v;
}

Eigen::Vector3f ParseColour(const std::string& text, const std::string& option) {
  const Eigen::Vector3d rgb = ParseVector3(text, option);
  if (rgb.minCoeff() < 0 || rgb.maxCoeff() > 255) {
    throw Error(option + " '" + text + "': expected R,G,B from 0 to 255");
  }
  return (rgb / 255).cast<float>();
}

}  // namespace urdfsnap::request
