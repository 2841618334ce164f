// EscapeMarkup for the snapshot reports (HTML, JUnit XML) and the docs page.
#include "common/markup_text.h"

namespace urdfsnap {

std::string EscapeMarkup(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      // control characters are not allowed in XML 1.0 at all
      default: out += (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n') ? '?' : ch;
    }
  }
  return out;
}

}  // namespace urdfsnap
