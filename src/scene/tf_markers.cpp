// TF axes and parent arrows built from RViz's unit cylinder and cone, sized and coloured as RViz's
// TF display sizes and colours them, and the frame names as camera-facing text labels.
#include "scene/tf_markers.h"

#include "texture/glyph_atlas.h"
#include "scene/primitive_meshes.h"
#include "scene/text_layout.h"

namespace urdfsnap::scene {

namespace {

// tf_display.cpp: `new Axes(..., 0.2, 0.02)`; axes.cpp scales a unit-diameter cylinder by
// (0.02, 0.2, 0.02), so each axis is 0.2 m long with radius 0.01 m.
constexpr double kAxisLength = 0.2;
constexpr double kAxisDiameter = 0.02;
// tf_display.cpp: arrow shaft diameter 0.01, head diameter 0.04 and length 0.1 (all × scale).
constexpr double kShaftDiameter = 0.01;
constexpr double kHeadDiameter = 0.04;
constexpr double kHeadLength = 0.1;
const Eigen::Vector4f kShaftColour{0.8f, 0.8f, 0.3f, 1};
const Eigen::Vector4f kHeadColour{1.0f, 0.1f, 0.6f, 1};
// tf_display.cpp: `new MovableText(frame, "Liberation Sans", 0.1)`, white, H_CENTER and V_BELOW,
// its node at the frame's origin and scaled by the marker scale
constexpr float kNameHeight = 0.1f;

void Add(const std::shared_ptr<const geometry::TriangleMesh>& mesh, const Eigen::Affine3d& X_FG,
         const Eigen::Vector4f& rgba, Scene& scene) {
  scene.items.push_back({mesh, X_FG, rgba, -1, nullptr, 1, Eigen::Vector3f::Zero()});
}

// A unit mesh along +Z stretched to `length` with `diameter`, its centre at `centre`, its +Z
// turned onto `direction`.
Eigen::Affine3d Along(const Eigen::Vector3d& centre, const Eigen::Vector3d& direction,
                      double diameter, double length) {
  const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), direction);
  return Eigen::Translation3d(centre) * turn * Eigen::Scaling(diameter, diameter, length);
}

void AddAxes(const Eigen::Isometry3d& X_FL, double scale, Scene& scene) {
  const double length = kAxisLength * scale;
  const Eigen::Vector4f colours[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d direction = X_FL.linear().col(axis);
    Add(UnitCylinderMesh(),
        Along(X_FL.translation() + direction * length / 2, direction, kAxisDiameter * scale, length),
        colours[axis], scene);
  }
}

// arrow.cpp: the shaft runs from the frame towards the parent, the head's base sits at the
// shaft's end; the head is shortened to a tenth of the distance when the frames are close.
void AddParentArrow(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double scale,
                    Scene& scene) {
  const Eigen::Vector3d offset = to - from;
  const double distance = offset.norm();
  if (distance <= 0.001) return;   // RViz hides the arrow
  const Eigen::Vector3d direction = offset / distance;
  const double head = distance < kHeadLength * scale ? kHeadLength * scale * distance : kHeadLength * scale;
  const double shaft = distance - head;
  Add(UnitCylinderMesh(), Along(from + direction * shaft / 2, direction, kShaftDiameter * scale, shaft),
      kShaftColour, scene);
  Add(UnitConeMesh(), Along(from + direction * (shaft + head / 2), direction, kHeadDiameter * scale, head),
      kHeadColour, scene);
}

}  // namespace

Eigen::Vector4f NameColourOn(const Eigen::Vector3f& background) {
  const float luma = 0.2126f * background.x() + 0.7152f * background.y() + 0.0722f * background.z();
  return luma > 0.6f ? Eigen::Vector4f(0, 0, 0, 1) : Eigen::Vector4f::Ones();
}

std::vector<TextLabel> MakeTfNameLabels(const std::vector<std::string>& frames, const TfOptions& options) {
  const std::shared_ptr<const texture::GlyphAtlas> atlas = texture::BuildGlyphAtlas(texture::FindLiberationSans(), CodePointsOf(frames));
  std::vector<TextLabel> labels;
  for (const std::string& name : frames) {
    labels.push_back({atlas->texture, LayOutText(*atlas, name, kNameHeight * static_cast<float>(options.marker_scale)),
                      Eigen::Vector3d::Zero(), Eigen::Vector4f::Ones()});
  }
  return labels;
}

std::vector<TextLabel> MakeTfNameLabels(const model::Robot& robot, const TfOptions& options) {
  return MakeTfNameLabels(robot.LinkNames(), options);
}

void AddTfFrames(const std::vector<Eigen::Isometry3d>& X_FT, const std::vector<int>& parents,
                 const TfOptions& options, const std::vector<TextLabel>& names, Scene& scene) {
  for (size_t i = 0; i < X_FT.size(); ++i) {
    if (options.show_axes) AddAxes(X_FT[i], options.marker_scale, scene);
    if (options.show_arrows && parents[i] >= 0) {
      AddParentArrow(X_FT[i].translation(), X_FT[parents[i]].translation(), options.marker_scale, scene);
    }
    if (i < names.size()) {
      scene.labels.push_back(names[i]);
      scene.labels.back().anchor = X_FT[i].translation();
      scene.labels.back().rgba = options.name_colour;
    }
  }
}

}  // namespace urdfsnap::scene
