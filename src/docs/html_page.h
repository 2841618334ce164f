// The page as one self-contained HTML file (index.html): the same content as the Markdown, with
// its style inside and its images by relative path, so it works from disk, offline; the tree as
// a nested list.
#pragma once

#include <string>

#include "docs/page_model.h"

namespace urdfsnap::docs {

// The HTML text of `page`; the same page always gives the same bytes. Every movable joint's
// section is a <section class="joint" id="joint-..." data-joint="NAME">.
std::string HtmlPage(const RobotPage& page);

}  // namespace urdfsnap::docs
