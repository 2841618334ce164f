// Markup escaping for HTML pages and XML reports: the five meaningful characters as entities,
// control characters as '?', UTF-8 unchanged (unit).
#include "common/markup_text.h"

#include <gtest/gtest.h>

namespace urdfsnap {
namespace {

TEST(MarkupText, EscapesTheFiveCharactersAndControlCharacters) {
  EXPECT_EQ(EscapeMarkup("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
  EXPECT_EQ(EscapeMarkup("tab\tline\nbell\a"), "tab\tline\nbell?");
  EXPECT_EQ(EscapeMarkup("grün · 机器人"), "grün · 机器人");
}

}  // namespace
}  // namespace urdfsnap
