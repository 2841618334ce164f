// JPEG decoding with libjpeg(-turbo), set up as FreeImage's default load sets it up.
#include "texture/jpeg_texture.h"

#include <csetjmp>
#include <cstdio>   // jpeglib.h needs FILE
#include <cstdlib>
#include <string>

#include <jpeglib.h>

#include "common/error.h"
#include "image/image.h"

namespace urdfsnap::texture {

namespace {

// libjpeg reports a fatal error through error_exit, which must not return: it jumps back to
// DecodeRgb with the message kept here.
struct ErrorManager {
  jpeg_error_mgr base;   // first, so that libjpeg's pointer to it is a pointer to this
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX] = "";
};

[[noreturn]] void JumpOut(j_common_ptr info) {
  auto* manager = reinterpret_cast<ErrorManager*>(info->err);
  (*info->err->format_message)(info, manager->message);
  std::longjmp(manager->jump, 1);
}

// libjpeg's warnings (recoverable corruption) are not printed; it goes on as FreeImage lets it.
void Silence(j_common_ptr) {}

enum class Outcome { kDecoded, kCmyk, kTooLarge, kFailed };

// Decodes into a malloc'ed buffer of width * height RGB bytes (*rgb, freed by the caller). Only
// trivially destructible state lives in this function, so that libjpeg's error can longjmp here;
// `info` and `errors` are the caller's.
Outcome DecodeRgb(std::string_view bytes, jpeg_decompress_struct& info, ErrorManager& errors,
                  unsigned char** rgb) {
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = JumpOut;
  errors.base.output_message = Silence;
  unsigned char* volatile buffer = nullptr;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    std::free(buffer);
    return Outcome::kFailed;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  Outcome refused = Outcome::kDecoded;
  if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK) refused = Outcome::kCmyk;
  if (info.image_width > image::kMaxImageSide || info.image_height > image::kMaxImageSide) refused = Outcome::kTooLarge;
  if (refused != Outcome::kDecoded) {
    jpeg_destroy_decompress(&info);
    return refused;
  }
  // FreeImage's PluginJPEG without JPEG_ACCURATE: the fast IDCT and no fancy upsampling
  info.dct_method = JDCT_IFAST;
  info.do_fancy_upsampling = FALSE;
  info.out_color_space = JCS_RGB;
  jpeg_start_decompress(&info);
  const size_t stride = static_cast<size_t>(info.output_width) * 3;
  buffer = static_cast<unsigned char*>(std::malloc(stride * info.output_height));
  if (!buffer) {
    jpeg_destroy_decompress(&info);
    std::snprintf(errors.message, sizeof errors.message, "out of memory");
    return Outcome::kFailed;
  }
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = buffer + info.output_scanline * stride;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  *rgb = buffer;
  return Outcome::kDecoded;
}

}  // namespace

bool IsJpeg(std::string_view bytes) {
  return bytes.size() >= 3 && static_cast<unsigned char>(bytes[0]) == 0xFF &&
         static_cast<unsigned char>(bytes[1]) == 0xD8 && static_cast<unsigned char>(bytes[2]) == 0xFF;
}

std::shared_ptr<TextureImage> DecodeJpegAsFreeImage(std::string_view bytes, const std::string& path) {
  jpeg_decompress_struct info{};
  ErrorManager errors;
  unsigned char* rgb = nullptr;
  const Outcome outcome = DecodeRgb(bytes, info, errors, &rgb);
  if (outcome == Outcome::kCmyk) return nullptr;
  if (outcome == Outcome::kTooLarge) {
    throw Error(SourceLocation{path}, "cannot read texture: image of " + std::to_string(info.image_width) + "x" +
                                          std::to_string(info.image_height) + " pixels is larger than " +
                                          std::to_string(image::kMaxImageSide) + " on a side");
  }
  if (outcome == Outcome::kFailed) throw Error(SourceLocation{path}, std::string("cannot read texture: ") + errors.message);
  auto texture = std::make_shared<TextureImage>();
  texture->width = static_cast<int>(info.output_width);
  texture->height = static_cast<int>(info.output_height);
  texture->channels = 4;
  const size_t pixels = static_cast<size_t>(texture->width) * texture->height;
  texture->texels.resize(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    texture->texels[4 * i] = rgb[3 * i];
    texture->texels[4 * i + 1] = rgb[3 * i + 1];
    texture->texels[4 * i + 2] = rgb[3 * i + 2];
    texture->texels[4 * i + 3] = 255;
  }
  std::free(rgb);
  jpeg_destroy_decompress(&info);
  return texture;
}

}  // namespace urdfsnap::texture
