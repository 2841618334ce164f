// The one place warnings and command output reach the user: warnings on stderr (errors under
// --strict), documents on stdout with write failures reported.
#include <cstdio>

#include "cli/command.h"
#include "common/error.h"
#include "snapshot/case_record.h"

namespace urdfsnap::cli {

bool& StrictWarnings() {
  static bool strict = false;
  return strict;
}

namespace {

void PrintFirstWarnings(const Warnings& warnings, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    std::fprintf(stderr, "urdfsnap: warning: %s\n", warnings.messages()[i].c_str());
  }
}

}  // namespace

void PrintWarnings(const Warnings& warnings) {
  const auto& messages = warnings.messages();
  if (!StrictWarnings() || messages.empty()) return PrintFirstWarnings(warnings, messages.size());
  PrintFirstWarnings(warnings, messages.size() - 1);
  throw Error(messages.back() + " (a warning; --strict makes it an error)");
}

void PrintWarningsBeforeError(const Warnings& warnings) {
  PrintFirstWarnings(warnings, warnings.messages().size());
}

void WriteToStdout(std::string_view text) {
  std::fwrite(text.data(), 1, text.size(), stdout);
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    throw Error("cannot write to standard output");
  }
}

void PrintCaseLine(const char* word, const std::string& name, const std::string& message) {
  std::printf("%-8s %s: %s\n", word, name.c_str(), message.c_str());
  std::fflush(stdout);
  // a case that could not be rendered is bad input: its error on stderr too, where CI logs and
  // scripts look (the message names the suite file and line)
  if (std::string_view(word) == snapshot::StatusWord(snapshot::CaseStatus::kError)) {
    std::fprintf(stderr, "urdfsnap: error: %s\n", message.c_str());
  }
}

}  // namespace urdfsnap::cli
