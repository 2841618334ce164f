// The page as GitHub-flavoured Markdown (README.md): the robot's pictures, its kinematic tree as a
// Mermaid diagram, the joints and links tables and a section per movable joint, with relative
// links to the images.
#pragma once

#include <string>

#include "docs/page_model.h"

namespace urdfsnap::docs {

// The Markdown text of `page`; the same page always gives the same bytes.
std::string MarkdownPage(const RobotPage& page);

}  // namespace urdfsnap::docs
