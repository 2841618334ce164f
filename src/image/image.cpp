// Consistency checks of Image values.
#include "image/image.h"

#include <cstddef>
#include <string>

#include "common/error.h"

namespace urdfsnap::image {

std::string SizeText(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void CheckImage(const Image& image, std::string_view role) {
  const std::string size = SizeText(image);
  if (image.width <= 0 || image.height <= 0 || image.width > kMaxImageSide ||
      image.height > kMaxImageSide) {
    throw Error(std::string(role) + ": image size " + size + " is outside 1x1 to " +
                std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide));
  }
  const std::size_t expected = std::size_t(image.width) * std::size_t(image.height) * 3;
  if (image.rgb.size() != expected) {
    throw Error(std::string(role) + ": a " + size + " RGB image needs " + std::to_string(expected) +
                " bytes, got " + std::to_string(image.rgb.size()));
  }
}

}  // namespace urdfsnap::image
