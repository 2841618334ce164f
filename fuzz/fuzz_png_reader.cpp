// Fuzz target: the PNG reader of `diff`. Only urdfsnap::Error may come out; a decoded image must be
// consistent and survive an encode/decode round trip unchanged.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "common/error.h"
#include "image/png_reader.h"
#include "image/png_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  image::Image decoded;
  try {
    decoded = image::DecodePng(std::string_view(reinterpret_cast<const char*>(data), size), "in.png");
  } catch (const Error&) {
    return 0;
  }
  image::CheckImage(decoded, "decoded PNG");
  // small images only: the round trip is a check of the decoder, not a benchmark of the encoder
  if (decoded.rgb.size() > (1u << 20)) return 0;
  const std::vector<std::uint8_t> encoded = image::EncodePng(decoded);
  const std::string_view bytes(reinterpret_cast<const char*>(encoded.data()), encoded.size());
  if (image::DecodePng(bytes, "round trip").rgb != decoded.rgb) std::abort();
  return 0;
}
