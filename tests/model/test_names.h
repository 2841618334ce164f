// Test names for data-driven (parameterised) tests: a case's label with every character that
// GoogleTest does not allow in a name replaced by '_'.
#pragma once

#include <cctype>
#include <string>

namespace urdfsnap::model::test {

inline std::string TestName(std::string label) {
  for (char& c : label) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return label;
}

}  // namespace urdfsnap::model::test
