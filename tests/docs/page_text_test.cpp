// The docs page as text: Markdown tables and escaping, the Mermaid tree and its limits, the HTML
// page's escaping, anchors and nested tree (unit, no GL).
#include <gtest/gtest.h>

#include "docs/html_page.h"
#include "docs/markdown_page.h"
#include "docs/markdown_text.h"
#include "docs/mermaid_tree.h"
#include "docs/test_robot.h"

namespace urdfsnap::docs {
namespace {

struct PageTextTest : ::testing::Test {
  Warnings warnings;
  model::Robot robot = model::LoadRobot(kGripperUrdf, "grip.urdf", warnings);
  RobotPage page = MakeRobotPage(robot, "grip.urdf", {}, {}, warnings);
};

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MarkdownText, EscapesWhatCanStartMarkupButKeepsInnerUnderscores) {
  EXPECT_EQ(MarkdownText("link_01"), "link_01");
  EXPECT_EQ(MarkdownText("base_link__link_01"), "base_link__link_01");
  EXPECT_EQ(MarkdownText("_private_"), "\\_private\\_");
  EXPECT_EQ(MarkdownText("a|b*c[d](e)<f>&g#h`i"), "a\\|b\\*c\\[d\\](e)\\<f\\>\\&g\\#h\\`i");
  EXPECT_EQ(MarkdownText("tab\there\nnew"), "tab?here?new");
  EXPECT_EQ(MarkdownText("ünï"), "ünï");
}

TEST(MermaidText, CodesEverythingThatMeansSomethingInALabel) {
  EXPECT_EQ(MermaidText("link_01 (a/b)"), "link_01 (a/b)");
  EXPECT_EQ(MermaidText("say \"hi\" #1 & <b>|%%`"), "say #34;hi#34; #35;1 #38; #60;b#62;#124;#37;#37;#96;");
  EXPECT_EQ(MermaidText("ünï"), "ünï");
}

TEST_F(PageTextTest, MermaidTreeHasABoxPerLinkAndAnArrowPerJoint) {
  const auto mermaid = MermaidTree(page);
  ASSERT_TRUE(mermaid);
  EXPECT_EQ(*mermaid,
            "flowchart TD\n"
            "  L0[\"base\"]\n"
            "  L0 -->|\"turn (continuous)\"| L1[\"column\"]\n"
            "  L1 -->|\"lift (prismatic)\"| L2[\"carriage\"]\n"
            "  L2 -->|\"wrist (revolute)\"| L3[\"hand\"]\n"
            "  L3 -->|\"finger_left (revolute)\"| L4[\"left\"]\n"
            "  L3 -->|\"finger_right (revolute)\"| L5[\"a#60;b#62;#124;#42;_x_\"]\n"
            "  L0 -.->|\"camera_mount (fixed)\"| L6[\"camera\"]\n");
}

TEST_F(PageTextTest, TreesBeyondGithubsMermaidLimitsBecomeANestedList) {
  RobotPage big = page;
  TreeNode node = big.tree[1];
  node.parent = 0;
  node.depth = 1;
  big.tree.resize(kMermaidMaxEdges + 2, node);
  EXPECT_FALSE(MermaidTree(big));
  const std::string markdown = MarkdownPage(big);
  EXPECT_FALSE(Contains(markdown, "```mermaid"));
  EXPECT_TRUE(Contains(markdown, "- base\n  - column ([turn](#joint-turn), continuous)\n"
                                 "    - carriage ([lift](#joint-lift), prismatic)\n"));
}

TEST_F(PageTextTest, MarkdownHasTablesImagesAndSections) {
  const std::string markdown = MarkdownPage(page);
  EXPECT_EQ(markdown.rfind("# grip\\&bot\n\n![grip\\&bot as RViz shows it](images/robot.png)\n", 0), 0u) << markdown;
  EXPECT_TRUE(Contains(markdown, "```mermaid\nflowchart TD\n"));
  EXPECT_TRUE(Contains(markdown, "| joint | type | parent → child | axis | limits | mimic (of leader) | default |\n"
                                 "| --- | --- | --- | --- | --- | --- | --- |\n"
                                 "| [turn](#joint-turn) | continuous | base → column | (0, 0, 1) | none (continuous) | — "
                                 "| 0 rad (0°) |\n"));
  EXPECT_TRUE(Contains(markdown, "| finger_right | revolute | hand → a\\<b\\>\\|\\*\\_x\\_ | (0, 1, 0) |"));
  EXPECT_TRUE(Contains(markdown, "<a id=\"joint-wrist\"></a>\n\n### wrist\n\n"));
  EXPECT_TRUE(Contains(markdown, "| lower limit | default | upper limit |\n| :-: | :-: | :-: |\n"
                                 "| ![wrist at lower limit, 0.5 rad (28.65°)](joints/wrist/lower.png) |"));
  EXPECT_TRUE(Contains(markdown, "![wrist moving through its range](joints/wrist/sweep.gif)"));
  EXPECT_TRUE(Contains(markdown, "| carriage | mesh carriage.stl, scale 0.001 | — | package://grip/meshes/carriage.stl | — |"));
  EXPECT_EQ(markdown.back(), '\n');
  EXPECT_EQ(markdown.substr(markdown.size() - 2), "|\n");
}

TEST_F(PageTextTest, MarkdownSaysWhenThereIsNoCollisionGeometryOrMotion) {
  const model::Robot still = model::LoadRobot(R"(<robot name="still"><link name="only"/></robot>)", "s.urdf", warnings);
  const std::string markdown = MarkdownPage(MakeRobotPage(still, "s.urdf", {}, {}, warnings));
  EXPECT_TRUE(Contains(markdown, "The robot has no collision geometry."));
  EXPECT_TRUE(Contains(markdown, "The robot has no movable joints."));
  EXPECT_FALSE(Contains(markdown, "collision.png"));
}

TEST_F(PageTextTest, HtmlEscapesEveryNameAndIsSelfContained) {
  const std::string html = HtmlPage(page);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n", 0), 0u);
  EXPECT_TRUE(Contains(html, "<meta name=\"generator\" content=\"urdfsnap docs\">"));
  EXPECT_TRUE(Contains(html, "<title>grip&amp;bot · robot description</title>"));
  EXPECT_TRUE(Contains(html, "<span class=\"link\">a&lt;b&gt;|*_x_</span>"));
  EXPECT_FALSE(Contains(html, "a<b>"));
  EXPECT_TRUE(Contains(html, "<style>\n/* The look of the index.html"));
  EXPECT_FALSE(Contains(html, "<script"));
  EXPECT_FALSE(Contains(html, "http"));   // nothing from the network
  EXPECT_TRUE(Contains(html, "<section class=\"joint\" id=\"joint-finger_left\" data-joint=\"finger_left\">"));
  EXPECT_TRUE(Contains(html, "<img src=\"joints/turn/half-turn.png\" width=\"320\" height=\"240\" "
                             "alt=\"turn at half turn (either way), 3.14159 rad (180°)\">"));
  EXPECT_EQ(html.substr(html.size() - 16), "</body>\n</html>\n");
}

TEST_F(PageTextTest, HtmlTreeNestsListsAsTheLinksNest) {
  const std::string html = HtmlPage(page);
  const size_t start = html.find("<ul class=\"tree\">"), end = html.find("</section>", start);
  std::string tree = html.substr(start, end - start);
  // count the lists and items: every one opened is closed, in order
  int depth = 0, deepest = 0;
  for (size_t i = 0; i < tree.size(); ++i) {
    if (tree.compare(i, 3, "<ul") == 0) deepest = std::max(deepest, ++depth);
    if (tree.compare(i, 5, "</ul>") == 0) --depth;
    ASSERT_GE(depth, 0);
  }
  EXPECT_EQ(depth, 0);
  EXPECT_EQ(deepest, 5);   // base > column > carriage > hand > fingers
  EXPECT_TRUE(Contains(tree, "<span class=\"link\">camera</span> <span class=\"joint-name\">(camera_mount, fixed)"));
  EXPECT_TRUE(Contains(tree, "(<a href=\"#joint-wrist\">wrist</a>, revolute)"));
}

}  // namespace
}  // namespace urdfsnap::docs
