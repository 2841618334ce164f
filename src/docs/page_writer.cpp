// WritePage: the documents after the pictures, so that a page with both documents is complete.
#include "docs/page_writer.h"

#include "common/atomic_file.h"
#include "docs/html_page.h"
#include "docs/markdown_page.h"

namespace urdfsnap::docs {

void WritePage(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page, const PageLook& look,
               const std::vector<PageImage>& files, const std::filesystem::path& folder, Warnings& warnings,
               const Progress& progress) {
  RobotPage written = page;
  written.tf_note = LeftOutNote(RenderPageImages(robot, page, look, files, folder, warnings, progress));
  WriteFileAtomically((folder / kMarkdownFile).string(), MarkdownPage(written));
  WriteFileAtomically((folder / kHtmlFile).string(), HtmlPage(written));
}

}  // namespace urdfsnap::docs
