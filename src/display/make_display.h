// The one place a display's settings become a display: each settings type of DisplayKind maps to
// its class here (PointCloud2 and LaserScan join by adding theirs).
#pragma once

#include <memory>

#include "display/display.h"
#include "display/display_settings.h"
#include "display/marker_shapes.h"

namespace urdfsnap::display {

// `fixed_frame`: the frame the scene is drawn in (the Axes display's default reference frame).
std::unique_ptr<Display> MakeDisplay(const DisplaySettings& settings, const std::string& fixed_frame,
                                     const MarkerResources& resources);

}  // namespace urdfsnap::display
