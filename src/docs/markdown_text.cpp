// MarkdownText and MermaidText: byte-wise escaping (UTF-8 sequences pass through unchanged).
#include "docs/markdown_text.h"

#include <cctype>
#include <cstring>

namespace urdfsnap::docs {

namespace {

bool IsAsciiAlnum(char c) { return static_cast<unsigned char>(c) < 128 && std::isalnum(static_cast<unsigned char>(c)); }

bool IsControl(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

}  // namespace

std::string MarkdownText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (IsControl(c)) {
      out += '?';
      continue;
    }
    // a run of underscores with letters or digits on both sides can neither open nor close emphasis
    bool inner_underscore = false;
    if (c == '_') {
      const size_t before = text.find_last_not_of('_', i), after = text.find_first_not_of('_', i);
      inner_underscore = before != std::string_view::npos && after != std::string_view::npos &&
                         IsAsciiAlnum(text[before]) && IsAsciiAlnum(text[after]);
    }
    if (std::strchr("\\`*_[]<>|#!~&{}", c) && !inner_underscore) out += '\\';
    out += c;
  }
  return out;
}

std::string MermaidText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (IsControl(c)) {
      out += '?';
    } else if (static_cast<unsigned char>(c) >= 128 || IsAsciiAlnum(c) || std::strchr(" _-./:,()+=", c)) {
      out += c;
    } else {
      out += '#';
      out += std::to_string(static_cast<int>(c));
      out += ';';
    }
  }
  return out;
}

}  // namespace urdfsnap::docs
