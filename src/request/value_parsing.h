// Parsers for the option values the commands share: numbers, image sizes "WxH", vectors "X,Y,Z"
// and colours "R,G,B". Every number is read by common/number_text.h's grammar (the one joint
// values use too: finite, an optional leading '+', nothing else around it).
#pragma once

#include <string>

#include <Eigen/Core>

#include "render/render_settings.h"

namespace urdfsnap::request {

// A finite number; throws urdfsnap::Error naming `option`.
double ParseFinite(const std::string& text, const std::string& option);

// A finite number from `low` to `high`; throws urdfsnap::Error naming `option` and the range.
double ParseInRange(const std::string& text, const std::string& option, double low, double high);

// "640x480" → {640, 480}; throws urdfsnap::Error naming `option` for anything else, for sides
// below 1 or above image::kMaxImageSide.
render::ImageSize ParseImageSize(const std::string& text, const std::string& option);

// --fit-margin for an image of `size`: "0.05" (a fraction of each side, 0 to 0.45) or "12px"
// (pixels, fewer than half the smaller side); throws urdfsnap::Error naming `option` and the forms.
render::FitMargin ParseFitMargin(const std::string& text, const std::string& option, render::ImageSize size);

// "X,Y,Z" → vector (finite numbers only); throws urdfsnap::Error naming `option`.
Eigen::Vector3d ParseVector3(const std::string& text, const std::string& option);

// "R,G,B" with each from 0 to 255, "#RRGGBB", "#RGB" or a CSS colour name ("white", "grey", ...; any
// case) → colour from 0 to 1; throws urdfsnap::Error naming `option` and the accepted forms.
Eigen::Vector3f ParseColour(const std::string& text, const std::string& option);

}  // namespace urdfsnap::request
