// NumPy .npy files (format version 1.0) of float32 images, readable by numpy.load: the depth image
// in metres with NaN where there is no robot (ROS's 32FC1 convention).
#pragma once

#include <string>
#include <vector>

namespace urdfsnap::image {

// The .npy bytes of a height x width array of little-endian float32 (C order, top row first).
// Throws urdfsnap::Error when the value count does not match the size.
std::string EncodeNpyFloat32(int width, int height, const std::vector<float>& values);

// Encodes and writes to `path` atomically (see WriteFileAtomically).
void WriteNpyFloat32(int width, int height, const std::vector<float>& values, const std::string& path);

}  // namespace urdfsnap::image
