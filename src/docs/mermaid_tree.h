// The kinematic tree as a Mermaid flowchart, which GitHub draws from a ```mermaid block: one box
// per link, an arrow per joint labelled with its name and type (solid for joints that move, dotted
// for fixed ones).
#pragma once

#include <optional>
#include <string>

#include "docs/page_model.h"

namespace urdfsnap::docs {

// The largest diagram GitHub's Mermaid draws with its default configuration (maxEdges 500,
// maxTextSize 50000 characters); larger trees get a nested list instead.
inline constexpr int kMermaidMaxEdges = 500;
inline constexpr size_t kMermaidMaxText = 50000;

// The flowchart's text ("flowchart TD\n  L0[\"base\"]\n  L0 -->|\"..\"| L1[\"arm\"]\n..."), without
// the fence; std::nullopt when the tree is beyond GitHub's limits.
std::optional<std::string> MermaidTree(const RobotPage& page);

}  // namespace urdfsnap::docs
