// The one place a docs page makes its animations (each joint's sweep, the turntable): frames
// rendered on demand and encoded as they come, so memory does not grow with the frame count.
#pragma once

#include <functional>
#include <string>

#include "docs/page_model.h"
#include "image/image.h"

namespace urdfsnap::docs {

// The animation formats docs pages can have, by extension (".gif", ".webp"); empty when this build
// writes none, and then pages have no animations.
std::vector<std::string> AnimationExtensions();

// Writes an animation of `count` frames of `size` at `fps` frames per second to `path` (its
// extension one of AnimationExtensions()); render(k, frame) draws frame k into `frame`. Throws
// urdfsnap::Error (an encoder or write failure; nothing is left at `path` then).
void WriteAnimation(const std::string& path, PictureSize size, double fps, int count,
                    const std::function<void(int, image::Image&)>& render);

}  // namespace urdfsnap::docs
