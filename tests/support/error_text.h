// The message of the error a piece of code throws, so that error tests read as one comparison:
//   EXPECT_EQ(ErrorText([&] { ParseCsvTrajectory(text, "bad.csv"); }), "bad.csv:3: ...");
#pragma once

#include <string>

#include "common/error.h"

namespace urdfsnap::test {

// what() of the `Exception` (urdfsnap::Error unless given) that `run` throws, or "(no error)".
template <typename Exception = Error, typename Run>
std::string ErrorText(Run&& run) {
  try {
    run();
  } catch (const Exception& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace urdfsnap::test
