// Consistency checks of Image values.
#include "image/image.h"

#include <cstddef>
#include <string>

#include "common/error.h"

namespace urdfsnap::image {

std::string SizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

std::string SizeText(const Image& image) { return SizeText(image.width, image.height); }

void CheckImageSize(int width, int height, std::string_view role) {
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide) {
    throw Error(std::string(role) + ": image size " + SizeText(width, height) + " is outside 1x1 to " +
                std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide));
  }
}

void CheckImage(const Image& image, std::string_view role) {
  const std::string size = SizeText(image);
  CheckImageSize(image.width, image.height, role);
  const std::size_t expected = std::size_t(image.width) * std::size_t(image.height) * 3;
  if (image.rgb.size() != expected) {
    throw Error(std::string(role) + ": a " + size + " RGB image needs " + std::to_string(expected) +
                " bytes, got " + std::to_string(image.rgb.size()));
  }
}

}  // namespace urdfsnap::image
