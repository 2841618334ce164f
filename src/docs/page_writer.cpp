// WritePage: the documents after the pictures, so that a page with both documents is complete.
#include "docs/page_writer.h"

#include "common/atomic_file.h"
#include "docs/html_page.h"
#include "docs/markdown_page.h"

namespace urdfsnap::docs {

void WritePage(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page, const PageLook& look,
               const std::vector<PageImage>& files, const std::filesystem::path& folder, Warnings& warnings,
               const Progress& progress) {
  WritePageDocuments(page, RenderPageImages(robot, page, look, files, folder, warnings, progress), folder);
}

void WritePageDocuments(const RobotPage& page, const std::vector<LeftOutName>& tf_left_out,
                        const std::filesystem::path& folder) {
  RobotPage written = page;
  written.tf_note = LeftOutNote(tf_left_out);
  WriteFileAtomically((folder / kMarkdownFile).string(), MarkdownPage(written));
  WriteFileAtomically((folder / kHtmlFile).string(), HtmlPage(written));
}

}  // namespace urdfsnap::docs
