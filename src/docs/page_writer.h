// A whole docs page into a folder: its pictures and animations, README.md and index.html; or only
// the documents, when worker processes made the pictures.
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

// Writes the page's two documents into `folder`, `tf_left_out` being the names its TF picture
// leaves out (RenderPageImages, TfLeftOut): the last step of a page, after every picture of it is
// in the folder. Throws urdfsnap::Error when a document cannot be written.
void WritePageDocuments(const RobotPage& page, const std::vector<LeftOutName>& tf_left_out,
                        const std::filesystem::path& folder);

}  // namespace urdfsnap::docs
