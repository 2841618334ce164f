// ParseJson: nlohmann_json's parse errors turned into located urdfsnap::Errors.
#include "common/json_text.h"

#include <algorithm>

#include "common/error.h"

namespace urdfsnap {

int LineAt(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + std::min(offset, text.size()),
                                         '\n'));
}

nlohmann::ordered_json ParseJson(const std::string& text, const std::string& path) {
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::out_of_range& e) {
    // a number beyond a double ("1e999"; found by fuzzing: this escaped without the file)
    const std::string what = e.what();
    const size_t bracket = what.find("] ");
    throw Error(SourceLocation{path, 0},
                "bad JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  } catch (const nlohmann::json::parse_error& e) {
    // what() reads "[json.exception.parse_error.101] parse error at line L, column C: ..."
    const std::string what = e.what();
    const size_t colon = what.find(": ");
    throw Error(SourceLocation{path, LineAt(text, e.byte > 0 ? e.byte - 1 : 0)},
                "bad JSON: " + (colon == std::string::npos ? what : what.substr(colon + 2)));
  }
}

}  // namespace urdfsnap
