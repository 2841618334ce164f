// Text inside HTML pages and XML reports (snapshot reports, docs pages): the five characters markup gives a meaning escaped.
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap {

// & < > " ' as entities, control characters other than tab and newline as '?' (XML 1.0 has no
// way to write them); everything else unchanged (the reports are UTF-8).
std::string EscapeMarkup(std::string_view text);

}  // namespace urdfsnap
