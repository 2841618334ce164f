// The table of image kinds and their extensions, and the one check against it.
#include "image/image_file_names.h"

#include "common/error.h"
#include "common/file_extension.h"

namespace urdfsnap::image {

namespace {

struct Format {
  const char* extension;
  const char* what;
};

struct KindFormats {
  ImageKind kind;
  Format first, second;   // second.extension null when there is one
};

constexpr KindFormats kFormats[] = {
    {ImageKind::kColour, {".png", "8-bit RGB"}, {nullptr, nullptr}},
    {ImageKind::kDepth, {".png", "16-bit millimetres"}, {".npy", "float32 metres"}},
    {ImageKind::kLabels, {".png", "16-bit labels"}, {nullptr, nullptr}},
    {ImageKind::kMask, {".png", "8-bit mask"}, {nullptr, nullptr}},
    {ImageKind::kDepthGolden, {".png", "16-bit millimetres"}, {nullptr, nullptr}},
};

}  // namespace

void CheckImageFileName(const std::string& path, ImageKind kind, const std::string& option) {
  const std::string extension = LowerCaseExtension(path);
  for (const KindFormats& formats : kFormats) {
    if (formats.kind != kind) continue;
    if (extension == formats.first.extension || (formats.second.extension && extension == formats.second.extension)) {
      return;
    }
    std::string expected = std::string(formats.first.extension) + " (" + formats.first.what + ")";
    if (formats.second.extension) {
      expected += std::string(" or ") + formats.second.extension + " (" + formats.second.what + ")";
    }
    throw Error(option + " '" + path + "': expected a " + expected + " file" +
                (extension.empty() ? "" : "; urdfsnap does not write " + extension + " images"));
  }
}

}  // namespace urdfsnap::image
