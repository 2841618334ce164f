// The Axes display at its frame's pose at the time drawn.
#include "display/axes_display.h"

#include "display/arrow_shapes.h"

namespace urdfsnap::display {

AxesDisplay::AxesDisplay(AxesSettings settings, std::string fixed_frame)
    : settings_(std::move(settings)),
      frame_(settings_.reference_frame.empty() ? std::move(fixed_frame) : settings_.reference_frame) {}

void AxesDisplay::Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
                       Warnings& warnings) const {
  const std::optional<Eigen::Isometry3d> X_FA = lookup(frame_, time_ns);
  if (!X_FA) {
    warnings.Add("Axes display: no transform from frame '" + frame_ + "' to the fixed frame; not drawn");
    return;
  }
  AddAxes(*X_FA, settings_.length, settings_.radius, 1, scene);
}

}  // namespace urdfsnap::display
