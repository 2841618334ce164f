// JPEG decoding into RGB images, for camera images a bag carries as sensor_msgs/CompressedImage
// (image_transport's "jpeg" format). stb_image's decoder: an accurate integer IDCT and
// interpolating chroma upsampling, as OpenCV's imdecode (libjpeg's defaults) that ROS's
// compressed image transport uses. (Textures go through texture/jpeg_texture.h instead, which
// decodes as RViz's FreeImage codec does.)
#pragma once

#include <string>
#include <string_view>

#include "image/image.h"

namespace urdfsnap::image {

// True when `bytes` start as a JPEG file does (the SOI marker).
bool LooksLikeJpeg(std::string_view bytes);

// Decodes the JPEG `bytes` as 8-bit RGB, top row first (grey becomes three equal channels).
// Throws urdfsnap::Error "NAME: ..." for data that is not a JPEG, one larger than kMaxImageSide on
// a side (checked in its header before anything is allocated), or one that fails to decode.
Image DecodeJpeg(std::string_view bytes, const std::string& name);

}  // namespace urdfsnap::image
