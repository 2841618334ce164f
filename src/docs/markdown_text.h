// Robot names (which URDF lets hold any character) as literal text in GitHub-flavoured Markdown
// and in Mermaid diagram labels.
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap::docs {

// `text` as literal Markdown inline text, also inside a table cell, a heading or an image's alt
// text: every ASCII character that can start or end markup (\ ` * _ [ ] < > | # ! ~ & { }) is
// backslash-escaped, except underscores with letters or digits on both sides (which CommonMark
// never reads as emphasis, so "link_01" and "a__b" stay readable); control characters become '?'.
std::string MarkdownText(std::string_view text);

// `text` inside a quoted Mermaid label ("..."): ASCII other than letters, digits, space and
// _ - . / : , ( ) + = as Mermaid's "#<decimal>;" codes (the quote, #, &, <, >, %, `, | ...),
// control characters as '?'. UTF-8 is kept.
std::string MermaidText(std::string_view text);

}  // namespace urdfsnap::docs
