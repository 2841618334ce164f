// FiniteNumber: the check every numeric option of the commands carries.
#include <cmath>
#include <string>

#include "cli/command.h"

namespace urdfsnap::cli {

CLI::Validator FiniteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value)) {
          return "expected a finite number, got '" + text + "'";
        }
        return "";
      },
      "");  // no word in --help: the range that follows says enough
}

}  // namespace urdfsnap::cli
