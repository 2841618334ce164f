// MarkdownPage: GFM tables, a ```mermaid block (a nested list beyond GitHub's Mermaid limits),
// images by relative path, sections anchored by <a id> so the tables can link to them.
#include "docs/markdown_page.h"

#include "docs/markdown_text.h"
#include "docs/mermaid_tree.h"

namespace urdfsnap::docs {

namespace {

using Cells = std::vector<std::string>;

std::string Row(const Cells& cells) {
  std::string row = "|";
  for (const std::string& cell : cells) row += " " + cell + " |";
  return row + "\n";
}

std::string Grid(const Cells& header, const std::vector<Cells>& rows, const char* align = "---") {
  std::string text = Row(header);
  text += Row(Cells(header.size(), align));
  for (const Cells& row : rows) text += Row(row);
  return text + "\n";
}

std::string Image(const std::string& alt, const std::string& file) { return "![" + MarkdownText(alt) + "](" + file + ")"; }

// Text linking to a section when it has one.
std::string MaybeLinked(const std::string& text, const std::string& anchor) {
  return anchor.empty() ? MarkdownText(text) : std::string("[") + MarkdownText(text) + "](#" + anchor + ")";
}

std::string Intro(const RobotPage& page) {
  std::string text = "# " + MarkdownText(page.robot_name) + "\n\n" +
                     Image(page.robot_name + " as RViz shows it", page.hero_file) + "\n\n";
  text += MarkdownText(page.source_note) + "\n\n";
  // the TF view on its own, at its own size, so that its names stay readable
  Cells header, images;
  std::string tf;
  for (const View& view : Views(page)) {
    if (view.file == page.tf_file) {
      tf = MarkdownText(view.caption) + ":\n\n" + Image(view.alt, view.file) + "\n\n";
      continue;
    }
    header.push_back(view.caption);
    images.push_back(Image(view.alt, view.file));
  }
  if (!header.empty()) text += Grid(header, {images}, ":-:");
  if (page.collision_file.empty()) text += "The robot has no collision geometry.\n\n";
  text += tf;
  if (!page.tf_note.empty()) text += MarkdownText(page.tf_note) + "\n\n";
  return text;
}

std::string NestedList(const RobotPage& page) {
  std::string text;
  for (const TreeNode& node : page.tree) {
    text += std::string(2 * node.depth, ' ') + "- " + MarkdownText(node.link);
    if (node.parent >= 0) text += " (" + MaybeLinked(node.joint, node.anchor) + ", " + node.joint_type + ")";
    text += "\n";
  }
  return text + "\n";
}

std::string Tree(const RobotPage& page) {
  std::string text = "## Kinematic tree\n\n";
  if (const auto mermaid = MermaidTree(page)) {
    return text + "Links in boxes, joints on the arrows (dotted: fixed joints).\n\n```mermaid\n" + *mermaid +
           "```\n\n";
  }
  return text + "Each link with the joint from its parent (too large a tree for a Mermaid diagram).\n\n" +
         NestedList(page);
}

std::string Section(const JointSection& section) {
  std::string text = "<a id=\"" + section.anchor + "\"></a>\n\n### " + MarkdownText(section.name) + "\n\n" +
                     MarkdownText(section.summary);
  text += "\n\n";
  Cells header, images, values;
  for (const Picture& picture : section.pictures) {
    header.push_back(MarkdownText(picture.label));
    images.push_back(Image(picture.alt, picture.file));
    values.push_back(MarkdownText(picture.value));
  }
  text += Grid(header, {images, values}, ":-:");
  if (section.sweep_file.empty()) return text;
  return text + Image(section.name + " moving through its range", section.sweep_file) + "\n\n";
}

std::string JointSections(const RobotPage& page) {
  std::string text = "## Joint by joint\n\n" + MarkdownText(page.sections_note) + "\n\n";
  for (const JointSection& section : page.sections) text += Section(section);
  return text;
}

// A table of the page model's: cells escaped, linked where they have an anchor.
std::string TableText(const Table& table) {
  std::vector<Cells> rows;
  for (const auto& row : table.rows) {
    Cells cells;
    for (const Cell& cell : row) cells.push_back(MaybeLinked(cell.text, cell.anchor));
    rows.push_back(std::move(cells));
  }
  return Grid(table.header, rows);
}

}  // namespace

std::string MarkdownPage(const RobotPage& page) {
  std::string text = Intro(page) + Tree(page) + "## Joints\n\n" + TableText(JointsTable(page)) +
                     JointSections(page) + "## Links\n\n" + TableText(LinksTable(page));
  text.pop_back();   // one newline at the end
  return text;
}

}  // namespace urdfsnap::docs
