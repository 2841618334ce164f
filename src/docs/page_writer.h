// A whole docs page into a folder: its pictures and animations, README.md and index.html.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "common/warnings.h"
#include "docs/page_images.h"
#include "docs/page_model.h"

namespace urdfsnap::docs {

// The page's two documents.
inline constexpr const char* kMarkdownFile = "README.md";
inline constexpr const char* kHtmlFile = "index.html";

// Writes `page` of `robot` into `folder` (which should be empty: PageFolder or ScratchFolder): the
// pictures and animations of `files` (PageImages for the whole page, a shard's part of them) and
// both documents. Throws urdfsnap::Error as RenderPageImages does, or when a document cannot be
// written.
void WritePage(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page, const PageLook& look,
               const std::vector<PageImage>& files, const std::filesystem::path& folder, Warnings& warnings,
               const Progress& progress);

}  // namespace urdfsnap::docs
