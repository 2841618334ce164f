// The facts of a docs page as short plain text, the same in the Markdown and the HTML: numbers
// rounded for reading, joint limits and values with their units, shapes with their sizes.
// Locale-independent and the same on every machine, so a regenerated page is byte-identical.
#pragma once

#include <string>

#include "model/robot.h"

namespace urdfsnap::docs {

// `value` with at most `digits` significant digits, no trailing zeros, no "-0": 0.785398 for π/4
// (6 digits), "1e-07", "90" for 90.0000001.
std::string ShortNumber(double value, int digits = 6);

// A joint position with its unit: "0.5 rad (28.65°)" for revolute and continuous joints, "0.1 m"
// for prismatic ones.
std::string PositionText(const model::Joint& joint, double value);

// The joint's limits with units: "-1.5708 to 1.5708 rad (-90° to 90°)", "0 to 0.2 m",
// "none (continuous)", or "—" for joints without motion (fixed, floating, planar).
std::string LimitsText(const model::Joint& joint);

// The joint's axis in its frame, "(0, 0, 1)", or "—" for fixed and floating joints.
std::string AxisText(const model::Joint& joint);

// "box 0.1 × 0.2 × 0.3 m", "cylinder r 0.05 m, length 0.3 m", "sphere r 0.1 m",
// "mesh base.stl", "mesh arm.dae, scale 0.001".
std::string ShapeText(const model::Shape& shape);

}  // namespace urdfsnap::docs
