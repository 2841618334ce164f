// Settings to display classes.
#include "display/make_display.h"

#include "display/axes_display.h"
#include "display/marker_display.h"
#include "display/path_display.h"
#include "display/pose_array_display.h"

namespace urdfsnap::display {
namespace {
template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
}  // namespace

std::unique_ptr<Display> MakeDisplay(const DisplaySettings& settings, const std::string& fixed_frame,
                                     const MarkerResources& resources) {
  return std::visit(
      Overloaded{
          [&](const MarkerSettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<MarkerDisplay>(settings.topic, s, resources);
          },
          [&](const PathSettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<PathDisplay>(settings.topic, s);
          },
          [&](const PoseArraySettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<PoseArrayDisplay>(settings.topic, s);
          },
          [&](const AxesSettings& s) -> std::unique_ptr<Display> {
            return std::make_unique<AxesDisplay>(s, fixed_frame);
          }},
      settings.kind);
}

}  // namespace urdfsnap::display
