// Strict parsing of option values: the whole text must be used, numbers must be finite.
#include "request/value_parsing.h"

#include <cctype>
#include <cmath>
#include <optional>
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

// The colour names people type, as CSS defines them (0-255 per channel).
struct ColourName {
  const char* name;
  double r, g, b;
};
constexpr ColourName kColourNames[] = {
    {"black", 0, 0, 0},       {"white", 255, 255, 255}, {"grey", 128, 128, 128},
    {"gray", 128, 128, 128},  {"lightgrey", 211, 211, 211}, {"lightgray", 211, 211, 211},
    {"darkgrey", 169, 169, 169}, {"darkgray", 169, 169, 169}, {"red", 255, 0, 0},
    {"green", 0, 128, 0},     {"blue", 0, 0, 255},      {"yellow", 255, 255, 0},
    {"cyan", 0, 255, 255},    {"magenta", 255, 0, 255}, {"orange", 255, 165, 0},
};

std::string Lowered(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::optional<Eigen::Vector3d> NamedColour(const std::string& text) {
  const std::string name = Lowered(text);
  for (const ColourName& colour : kColourNames) {
    if (name == colour.name) return Eigen::Vector3d(colour.r, colour.g, colour.b);
  }
  return std::nullopt;
}

std::string ColourNames() {
  std::string names;
  for (const ColourName& colour : kColourNames) names += (names.empty() ? "" : ", ") + std::string(colour.name);
  return names;
}

// "#RRGGBB" or "#RGB" (each digit doubled, as CSS reads it).
std::optional<Eigen::Vector3d> HexColour(const std::string& text) {
  const std::string digits = text.substr(1);
  if ((digits.size() != 6 && digits.size() != 3) ||
      digits.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
    return std::nullopt;
  }
  const size_t width = digits.size() / 3;
  Eigen::Vector3d rgb;
  for (int i = 0; i < 3; ++i) {
    const int value = std::stoi(digits.substr(i * width, width), nullptr, 16);
    rgb[i] = width == 1 ? value * 17 : value;
  }
  return rgb;
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

render::FitMargin ParseFitMargin(const std::string& text, const std::string& option, render::ImageSize size) {
  render::FitMargin margin;
  margin.pixels = text.size() > 2 && text.ends_with("px");
  const std::string number = margin.pixels ? text.substr(0, text.size() - 2) : text;
  const double most_pixels = (std::min(size.width, size.height) - 1) / 2.0;
  if (!ParseNumber(number, margin.amount) || margin.amount < 0 ||
      margin.amount > (margin.pixels ? most_pixels : 0.45)) {
    throw Error(option + " '" + text + "': expected a fraction of each side from 0 to 0.45 (e.g. 0.05) or " +
                "pixels from 0px to " + FormatForPeople(most_pixels) + "px for " + std::to_string(size.width) + "x" +
                std::to_string(size.height) + " (e.g. 12px)");
  }
  return margin;
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
  const std::string expected = "': expected R,G,B from 0 to 255 (e.g. 255,255,255), #RRGGBB or a "
                               "colour name (" + ColourNames() + ")";
  if (const std::optional<Eigen::Vector3d> named = NamedColour(text)) return (*named / 255).cast<float>();
  if (!text.empty() && text[0] == '#') {
    const std::optional<Eigen::Vector3d> hex = HexColour(text);
    if (!hex) throw Error(option + " '" + text + expected);
    return (*hex / 255).cast<float>();
  }
  const auto parts = Split(text, ',');
  Eigen::Vector3d rgb;
  if (parts.size() != 3 || !ParseNumber(parts[0], rgb.x()) || !ParseNumber(parts[1], rgb.y()) ||
      !ParseNumber(parts[2], rgb.z()) || rgb.minCoeff() < 0 || rgb.maxCoeff() > 255) {
    throw Error(option + " '" + text + expected);
  }
  return (rgb / 255).cast<float>();
}

}  // namespace urdfsnap::request
