// CameraInfo files read with yaml-cpp (common's located YamlReader): both ROS layouts into one struct, every error located.
#include "camera/camera_info.h"

#include <cmath>
#include <optional>

#include <yaml-cpp/yaml.h>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/internal/yaml_reader.h"
#include "common/number_text.h"
#include "image/image.h"

namespace urdfsnap::camera {

namespace {

// each matrix's key in a calibration file, a ROS 2 message and a ROS 1 message
constexpr std::initializer_list<const char*> kIntrinsicKeys = {"camera_matrix", "k", "K"};
constexpr std::initializer_list<const char*> kProjectionKeys = {"projection_matrix", "p", "P"};

// common's YamlReader over the file's root map, with the spellings of the layouts.
class Reader : public YamlReader {
 public:
  Reader(const YAML::Node& root, const std::string& path) : YamlReader(path), root_(root) {}

  // The first of `keys` the file has (layouts and ROS versions spell them differently), and its
  // spelling there; the first key and an undefined node when it has none.
  struct Found {
    YAML::Node node;
    std::string key;
  };
  Found Find(std::initializer_list<const char*> keys) const {
    for (const char* key : keys) {
      if (root_[key]) return {root_[key], key};
    }
    return {YAML::Node(YAML::NodeType::Undefined), *keys.begin()};
  }

  int Side(std::initializer_list<const char*> keys) const {
    const auto [node, key] = Find(keys);
    if (!node) Fail(node, "missing '" + key + "' (the image size)");
    const double value = Number(node, key);
    if (value != std::floor(value) || value < 1 || value > image::kMaxImageSide) {
      Fail(node, key + ": expected a whole number of pixels from 1 to " + std::to_string(image::kMaxImageSide) +
                     ", got " + node.Scalar());
    }
    return static_cast<int>(value);
  }

  // The numbers of a matrix: a plain list (a message) or {rows, cols, data} (a calibration file).
  std::vector<double> MatrixNumbers(const YAML::Node& node, const std::string& key) const {
    const YAML::Node list = node.IsMap() ? node["data"] : node;
    if (!list.IsSequence()) {
      Fail(node, key + ": expected a list of numbers" + (node.IsMap() ? " under 'data'" : ""));
    }
    std::vector<double> numbers;
    for (const YAML::Node& item : list) numbers.push_back(Number(item, key));
    return numbers;
  }

  template <int Rows, int Cols>
  Eigen::Matrix<double, Rows, Cols> Matrix(std::initializer_list<const char*> keys, bool required,
                                           const Eigen::Matrix<double, Rows, Cols>& fallback) const {
    const auto [node, key] = Find(keys);
    if (!node) {
      if (required) Fail(node, "missing '" + key + "'");
      return fallback;
    }
    const std::vector<double> numbers = MatrixNumbers(node, key);
    if (numbers.size() != Rows * Cols) {
      Fail(node, key + ": expected " + std::to_string(Rows * Cols) + " numbers (" + std::to_string(Rows) +
                     "x" + std::to_string(Cols) + ", row-major), got " + std::to_string(numbers.size()));
    }
    Eigen::Matrix<double, Rows, Cols> m;
    for (int r = 0; r < Rows; ++r) {
      for (int c = 0; c < Cols; ++c) m(r, c) = numbers[r * Cols + c];
    }
    return m;
  }

 private:
  YAML::Node root_;
};

}  // namespace

Intrinsics CameraInfo::RawIntrinsics() const { return {K(0, 0), K(1, 1), K(0, 2), K(1, 2)}; }

Intrinsics CameraInfo::RectifiedIntrinsics() const {
  if (P.isZero()) return RawIntrinsics();
  return {P(0, 0), P(1, 1), P(0, 2), P(1, 2)};
}

namespace {

// "the focal lengths fx and fy must be positive, got 0 and 500" unless they are.
std::optional<std::string> FocalProblem(const Intrinsics& k) {
  if (k.fx > 0 && k.fy > 0) return std::nullopt;
  return "the focal lengths fx and fy must be positive, got " + FormatNumber(k.fx) + " and " + FormatNumber(k.fy);
}

}  // namespace

void CheckCameraInfoMessage(CameraInfo& info, const std::string& where) {
  if (info.width < 1 || info.height < 1 || info.width > image::kMaxImageSide || info.height > image::kMaxImageSide) {
    throw Error(where + ": camera image size " + image::SizeText(info.width, info.height) + " is outside 1x1 to " +
                image::SizeText(image::kMaxImageSide, image::kMaxImageSide));
  }
  std::string why;
  const std::optional<Distortion> distortion = MakeDistortion(info.distortion_model, info.D, why);
  if (!distortion) throw Error(where + ": " + why);
  info.distortion = *distortion;
  if (const auto problem = FocalProblem(info.RawIntrinsics())) throw Error(where + ": k: " + *problem);
  if (!info.P.isZero()) {
    if (const auto problem = FocalProblem(info.RectifiedIntrinsics())) throw Error(where + ": p: " + *problem);
  }
}

CameraInfo ParseCameraInfo(std::string_view text, const std::string& path) {
  // `ros2 topic echo` ends each message with "---"; the first document is the message
  YAML::Node root = LoadYaml(std::string(text), path);
  if (!root.IsMap()) {
    throw Error(SourceLocation{path, 0},
                "expected a camera calibration (image_width, camera_matrix, ...) or a CameraInfo "
                "message (width, k, ...)");
  }
  const Reader r(root, path);
  CameraInfo info;
  info.width = r.Side({"image_width", "width"});
  info.height = r.Side({"image_height", "height"});
  info.K = r.Matrix<3, 3>(kIntrinsicKeys, true, {});
  info.R = r.Matrix<3, 3>({"rectification_matrix", "r", "R"}, false, Eigen::Matrix3d::Identity());
  info.P = r.Matrix<3, 4>(kProjectionKeys, false, Eigen::Matrix<double, 3, 4>::Zero());
  const YAML::Node model = r.Find({"distortion_model"}).node;
  if (model && !model.IsScalar()) r.Fail(model, "distortion_model: expected a name such as plumb_bob");
  info.distortion_model = model ? model.Scalar() : "";
  const auto [d, d_key] = r.Find({"distortion_coefficients", "d", "D"});
  if (d) info.D = r.MatrixNumbers(d, d_key);
  std::string why;
  const std::optional<Distortion> distortion = MakeDistortion(info.distortion_model, info.D, why);
  if (!distortion) r.Fail(model ? model : d, why);
  info.distortion = *distortion;
  const YAML::Node header = root["header"];
  if (header.IsMap() && header["frame_id"].IsScalar()) info.frame_id = header["frame_id"].Scalar();

  const auto check_focal = [&](const Intrinsics& k, std::initializer_list<const char*> keys) {
    if (const auto problem = FocalProblem(k)) {
      const auto [node, key] = r.Find(keys);
      r.Fail(node, key + ": " + *problem);
    }
  };
  check_focal(info.RawIntrinsics(), kIntrinsicKeys);
  if (!info.P.isZero()) check_focal(info.RectifiedIntrinsics(), kProjectionKeys);
  return info;
}

CameraInfo ReadCameraInfo(const std::string& path) {
  try {
    return ParseCameraInfo(ReadFileBounded(path), path);
  } catch (const FileReadError& e) {
    throw Error(SourceLocation{path, 0}, std::string("cannot read the camera info: ") + e.what());
  }
}

}  // namespace urdfsnap::camera
