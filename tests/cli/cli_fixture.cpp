// RunUrdfsnap with popen, and the per-test folder.
#include "cli_fixture.h"

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace urdfsnap::cli_test {

Result RunUrdfsnap(const std::string& arguments, const std::string& environment) {
  const std::string command = (environment.empty() ? "" : "env " + environment + " ") +
                              std::string(URDFSNAP_BINARY) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void CliTest::SetUp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = "cli_" + std::string(info->test_suite_name()) + "_" + info->name();
  std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests: "Formats/Test", ".../mp4"
  folder_.emplace(name);
  dir_ = folder_->path();
}

void CliTest::TearDown() { folder_.reset(); }

std::string CliTest::Write(const std::string& name, const std::string& text) const {
  std::ofstream(Path(name), std::ios::binary) << text;
  return Path(name);
}

}  // namespace urdfsnap::cli_test
