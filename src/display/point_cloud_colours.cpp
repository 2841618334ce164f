// The colour transformers, each as RViz writes it (point_cloud_transformers.cpp), over the points
// that survived the NaN filter (RViz's PointCloud2Display filters before transforming).
#include "display/point_cloud_colours.h"

#include <algorithm>
#include <cmath>

namespace urdfsnap::display {
namespace {

using Colour = PointCloudSettings::Colour;

constexpr std::uint8_t kInt32 = 5, kUint32 = 6, kFloat32 = 7;

// The rgb or rgba field RGB8 and MONO8 read (RViz takes the later of the two in the field list).
int PackedColourField(const PointCloudReader& cloud) { return std::max(cloud.Find("rgb"), cloud.Find("rgba")); }

bool Supports(const PointCloudReader& cloud, Colour colour) {
  switch (colour) {
    case Colour::kRgb8: case Colour::kMono8: {
      const int field = PackedColourField(cloud);
      if (field < 0) return false;
      const std::uint8_t type = cloud.Datatype(field);
      return type == kInt32 || type == kUint32 || type == kFloat32;
    }
    case Colour::kRgbF32: {
      const int r = cloud.Find("r");
      return r >= 0 && cloud.Find("g") >= 0 && cloud.Find("b") >= 0 && cloud.Datatype(r) == kFloat32;
    }
    default: return true;
  }
}

// Min and max of the finite values, or the given bounds.
void Bounds(const std::vector<float>& values, bool automatic, float given_min, float given_max, float& low, float& high) {
  if (!automatic) {
    low = given_min, high = given_max;
    return;
  }
  low = high = 0;
  bool any = false;
  for (float v : values) {
    if (!std::isfinite(v)) continue;
    low = any ? std::min(low, v) : v;
    high = any ? std::max(high, v) : v;
    any = true;
  }
}

std::vector<float> FieldValues(const PointCloudReader& cloud, int field, const std::vector<std::size_t>& indices) {
  std::vector<float> values;
  values.reserve(indices.size());
  for (std::size_t i : indices) values.push_back(cloud.Value(field, i));
  return values;
}

std::vector<Eigen::Vector4f> Intensity(const PointCloudReader& cloud, const std::vector<std::size_t>& indices,
                                       const PointCloudSettings& s) {
  std::vector<Eigen::Vector4f> colours(indices.size(), Eigen::Vector4f::Ones());
  int field = cloud.Find(s.channel);
  if (field < 0 && s.channel == "intensity") field = cloud.Find("intensities");
  if (field < 0) return colours;
  cloud.Check(field);
  const std::vector<float> values = FieldValues(cloud, field, indices);
  float low, high;
  Bounds(values, s.auto_intensity_bounds, s.min_intensity, s.max_intensity, low, high);
  // equal bounds divide by something huge, so that every point takes the same colour
  const float range = high - low == 0 ? 1e20f : high - low;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const float normalised = (values[k] - low) / range;
    if (s.use_rainbow) {
      const float value = 1.f - normalised;
      colours[k].head<3>() = RainbowColour(s.invert_rainbow ? 1.f - value : value);
    } else {
      const float t = std::clamp(normalised, 0.f, 1.f);
      colours[k].head<3>() = s.max_colour * t + s.min_colour * (1.f - t);
    }
  }
  return colours;
}

std::vector<Eigen::Vector4f> Packed(const PointCloudReader& cloud, const std::vector<std::size_t>& indices,
                                    bool mono) {
  const bool has_alpha = cloud.Find("rgb") < 0;   // only rgba: its top byte is alpha
  const int field = PackedColourField(cloud);
  cloud.Check(field);
  std::vector<Eigen::Vector4f> colours;
  colours.reserve(indices.size());
  for (std::size_t i : indices) {
    const std::uint32_t bits = cloud.Bits(field, i);
    Eigen::Vector4f c(((bits >> 16) & 0xff) / 255.f, ((bits >> 8) & 0xff) / 255.f, (bits & 0xff) / 255.f,
                      has_alpha ? (bits >> 24) / 255.f : 1.f);
    if (mono) c.head<3>().setConstant(0.2989f * c[0] + 0.5870f * c[1] + 0.1140f * c[2]);
    colours.push_back(c);
  }
  return colours;
}

std::vector<Eigen::Vector4f> RgbF32(const PointCloudReader& cloud, const std::vector<std::size_t>& indices) {
  const int r = cloud.Field("r"), g = cloud.Field("g"), b = cloud.Field("b");
  std::vector<Eigen::Vector4f> colours;
  colours.reserve(indices.size());
  for (std::size_t i : indices) colours.emplace_back(cloud.Value(r, i), cloud.Value(g, i), cloud.Value(b, i), 1.f);
  return colours;
}

std::vector<Eigen::Vector4f> Axis(const std::vector<float>& values, const PointCloudSettings& s) {
  float low, high;
  Bounds(values, s.auto_axis_bounds, s.min_value, s.max_value, low, high);
  const float range = high - low == 0 ? 0.001f : high - low;
  std::vector<Eigen::Vector4f> colours;
  colours.reserve(values.size());
  for (float v : values) {
    Eigen::Vector4f c = Eigen::Vector4f::Ones();
    c.head<3>() = RainbowColour(1.f - (v - low) / range);
    colours.push_back(c);
  }
  return colours;
}

}  // namespace

Eigen::Vector3f RainbowColour(float value) {
  // an HSV palette with hue from 0 to 5/6 only (getRainbowColor)
  value = std::clamp(value, 0.f, 1.f);
  const float h = value * 5.f + 1.f;
  const int i = static_cast<int>(std::floor(h));
  float f = h - static_cast<float>(i);
  if (!(i & 1)) f = 1 - f;   // i even
  const float n = 1 - f;
  if (i <= 1) return {n, 0, 1};
  if (i == 2) return {0, n, 1};
  if (i == 3) return {0, 1, n};
  if (i == 4) return {n, 1, 0};
  return {1, n, 0};
}

Colour ChooseColour(const PointCloudReader& cloud, const PointCloudSettings& settings) {
  if (settings.colour != Colour::kAuto && Supports(cloud, settings.colour)) return settings.colour;
  // point_cloud_common.cpp updateTransformers: RGB8 when it can, else the best score (Intensity
  // and AxisColor both score 255; of equals the last name in order wins: Intensity)
  return Supports(cloud, Colour::kRgb8) ? Colour::kRgb8 : Colour::kIntensity;
}

std::vector<Eigen::Vector4f> PointColours(const PointCloudReader& cloud, const std::vector<std::size_t>& indices,
                                          Colour colour, const PointCloudSettings& settings,
                                          const std::vector<float>& axis_values) {
  switch (colour) {
    case Colour::kRgb8: return Packed(cloud, indices, false);
    case Colour::kMono8: return Packed(cloud, indices, true);
    case Colour::kRgbF32: return RgbF32(cloud, indices);
    case Colour::kAxisColor: return Axis(axis_values, settings);
    case Colour::kFlatColor: {
      Eigen::Vector4f c = Eigen::Vector4f::Ones();
      c.head<3>() = settings.flat_colour;
      return std::vector<Eigen::Vector4f>(indices.size(), c);
    }
    case Colour::kAuto: case Colour::kIntensity: break;
  }
  return Intensity(cloud, indices, settings);
}

}  // namespace urdfsnap::display
