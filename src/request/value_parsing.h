// Parsers for the option values the commands share: image sizes "WxH" and vectors "X,Y,Z".
#pragma once

#include <string>

#include <Eigen/Core>

namespace urdfsnap::request {

struct ImageSize {
  int width = 640;
  int height = 480;
};

// "640x480" → {640, 480}; throws urdfsnap::Error naming `option` for anything else, for sides
// below 1 or above image::kMaxImageSide.
ImageSize ParseImageSize(const std::string& text, const std::string& option);

// "X,Y,Z" → vector (finite numbers only); throws urdfsnap::Error naming `option`.
Eigen::Vector3d ParseVector3(const std::string& text, const std::string& option);

// A finite number; throws urdfsnap::Error naming `option`.
double ParseFinite(const std::string& text, const std::string& option);

}  // namespace urdfsnap::request
