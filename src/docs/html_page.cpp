// HtmlPage: the Markdown page's content as HTML5, every robot-given text escaped, the style from
// the embedded page.css, no script (nothing that could fail in a browser console).
#include "docs/html_page.h"

#include "docs/embedded_page_files.h"
#include "common/markup_text.h"

namespace urdfsnap::docs {

namespace {

using Cells = std::vector<std::string>;

std::string Img(const std::string& file, const std::string& alt, const PictureSize& size) {
  return "<img src=\"" + EscapeMarkup(file) + "\" width=\"" + std::to_string(size.width) + "\" height=\"" +
         std::to_string(size.height) + "\" alt=\"" + EscapeMarkup(alt) + "\">";
}

std::string Figure(const std::string& image, const std::string& caption) {
  return "<figure>" + image + "<figcaption>" + EscapeMarkup(caption) + "</figcaption></figure>\n";
}

std::string MaybeLinked(const std::string& text, const std::string& anchor) {
  return anchor.empty() ? EscapeMarkup(text) : "<a href=\"#" + anchor + "\">" + EscapeMarkup(text) + "</a>";
}

// A table whose cells are already HTML.
std::string Grid(const Cells& header, const std::vector<Cells>& rows) {
  std::string text = "<table>\n<tr>";
  for (const std::string& cell : header) text += "<th>" + EscapeMarkup(cell) + "</th>";
  text += "</tr>\n";
  for (const Cells& row : rows) {
    text += "<tr>";
    for (const std::string& cell : row) text += "<td>" + cell + "</td>";
    text += "</tr>\n";
  }
  return text + "</table>\n";
}

std::string Head(const RobotPage& page) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"generator\" content=\"urdfsnap docs\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         EscapeMarkup(page.robot_name) + " · robot description</title>\n<style>\n" +
         std::string(EmbeddedPageFile("page.css")) + "</style>\n</head>\n<body>\n";
}

std::string Intro(const RobotPage& page) {
  std::string text = "<header>\n<h1>" + EscapeMarkup(page.robot_name) + "</h1>\n<p class=\"source\">" +
                     EscapeMarkup(page.source_note) + "</p>\n</header>\n";
  text += "<figure class=\"hero\">" + Img(page.hero_file, page.robot_name + " as RViz shows it", page.view_size) +
          "</figure>\n";
  // the TF view at its own size on a row of its own, so that its names stay readable
  std::string tf;
  text += "<div class=\"strip\">\n";
  for (const View& view : Views(page)) {
    std::string& row = view.file == page.tf_file ? tf : text;
    row += Figure(Img(view.file, view.alt, view.size), view.caption);
  }
  text += "</div>\n";
  if (page.collision_file.empty()) text += "<p class=\"note\">The robot has no collision geometry.</p>\n";
  text += tf;
  if (!page.tf_note.empty()) text += "<p class=\"note\">" + EscapeMarkup(page.tf_note) + "</p>\n";
  text += "<nav><ul><li><a href=\"#tree\">Kinematic tree</a></li><li><a href=\"#joints\">Joints</a></li>"
          "<li><a href=\"#joint-by-joint\">Joint by joint</a></li><li><a href=\"#links\">Links</a></li></ul></nav>\n";
  return text;
}

std::string Tree(const RobotPage& page) {
  // links are in depth-first order: close the lists of the deeper levels before each node
  std::string text = "<section id=\"tree\">\n<h2>Kinematic tree</h2>\n<ul class=\"tree\">";
  int open = 0;   // nested lists open below the top one
  for (size_t i = 0; i < page.tree.size(); ++i) {
    const TreeNode& node = page.tree[i];
    if (i > 0 && node.depth > page.tree[i - 1].depth) {
      text += "\n<ul>";
      ++open;
    } else if (i > 0) {
      text += "</li>";
      for (; open > node.depth; --open) text += "</ul></li>";
    }
    text += "\n<li><span class=\"link\">" + EscapeMarkup(node.link) + "</span>";
    if (node.parent >= 0) {
      text += " <span class=\"joint-name\">(" + MaybeLinked(node.joint, node.anchor) + ", " + node.joint_type +
              ")</span>";
    }
  }
  if (!page.tree.empty()) text += "</li>";
  for (; open > 0; --open) text += "</ul></li>";
  return text + "\n</ul>\n</section>\n";
}

std::string Section(const RobotPage& page, const JointSection& section) {
  std::string text = "<section class=\"joint\" id=\"" + section.anchor + "\" data-joint=\"" +
                     EscapeMarkup(section.name) + "\">\n<h3>" + EscapeMarkup(section.name) + "</h3>\n<p>" +
                     EscapeMarkup(section.summary);
  text += "</p>\n<div class=\"strip\">\n";
  for (const Picture& picture : section.pictures) {
    text += Figure(Img(picture.file, picture.alt, page.joint_size),
                   picture.label + ": " + picture.value);
  }
  text += "</div>\n";
  if (!section.sweep_file.empty()) {
    text += "<div class=\"sweep\">" +
            Figure(Img(section.sweep_file, section.name + " moving through its range", page.joint_size),
                   "moving through its range") +
            "</div>\n";
  }
  return text + "</section>\n";
}

std::string JointSections(const RobotPage& page) {
  std::string text = "<section id=\"joint-by-joint\">\n<h2>Joint by joint</h2>\n<p class=\"note\">" +
                     EscapeMarkup(page.sections_note) + "</p>\n";
  for (const JointSection& section : page.sections) text += Section(page, section);
  return text + "</section>\n";
}

// A table of the page model's as a <section> with a heading.
std::string TableSection(const char* id, const char* title, const Table& table) {
  std::vector<Cells> rows;
  for (const auto& row : table.rows) {
    Cells cells;
    for (const Cell& cell : row) cells.push_back(MaybeLinked(cell.text, cell.anchor));
    rows.push_back(std::move(cells));
  }
  return std::string("<section id=\"") + id + "\">\n<h2>" + title + "</h2>\n" +
         Grid(table.header, rows) + "</section>\n";
}

}  // namespace

std::string HtmlPage(const RobotPage& page) {
  return Head(page) + Intro(page) + Tree(page) + TableSection("joints", "Joints", JointsTable(page)) +
         JointSections(page) + TableSection("links", "Links", LinksTable(page)) +
         "</body>\n</html>\n";
}

}  // namespace urdfsnap::docs
