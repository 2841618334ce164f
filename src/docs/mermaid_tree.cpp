// MermaidTree: nodes named L<link index>, labels escaped with MermaidText.
#include "docs/mermaid_tree.h"

#include "docs/markdown_text.h"

namespace urdfsnap::docs {

std::optional<std::string> MermaidTree(const RobotPage& page) {
  if (page.tree.size() > static_cast<size_t>(kMermaidMaxEdges) + 1) return std::nullopt;
  std::string text = "flowchart TD\n";
  const auto node = [&](size_t i) {
    return std::string("L") + std::to_string(i) + "[\"" + MermaidText(page.tree[i].link) + "\"]";
  };
  for (size_t i = 0; i < page.tree.size(); ++i) {
    const TreeNode& n = page.tree[i];
    if (n.parent < 0) {
      text += "  " + node(i) + "\n";
      continue;
    }
    const char* arrow = n.joint_type == "fixed" ? " -.->|\"" : " -->|\"";
    text += "  L" + std::to_string(n.parent) + arrow + MermaidText(n.joint) + " (" + n.joint_type + ")\"| " +
            node(i) + "\n";
  }
  if (text.size() > kMermaidMaxText) return std::nullopt;
  return text;
}

}  // namespace urdfsnap::docs
