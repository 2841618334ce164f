// Which file formats each kind of image urdfsnap writes comes in, decided from the file name's
// extension in this one place, so that `-o pose.jpg` is refused by name before anything is drawn
// instead of writing PNG bytes under a JPEG name. Every command and suite key that names an image
// output (render -o/--depth/--labels/--mask, animate's depth and label sequences, snapshot goldens)
// asks here.
#pragma once

#include <string>

namespace urdfsnap::image {

enum class ImageKind {
  kColour,   // 8-bit RGB: .png
  kDepth,    // .png (16-bit millimetres) or .npy (float32 metres)
  kLabels,   // 16-bit link labels: .png
  kMask,     // 8-bit robot mask: .png
  kDepthGolden,   // a snapshot's depth golden, compared as 16-bit millimetres: .png
};

// Throws urdfsnap::Error "OPTION 'PATH': expected a .png ... file" naming the extensions `kind` is
// written as, unless `path` ends in one of them (in any letter case).
void CheckImageFileName(const std::string& path, ImageKind kind, const std::string& option);

}  // namespace urdfsnap::image
