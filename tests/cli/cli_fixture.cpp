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
  return RunProgram(URDFSNAP_BINARY, arguments, environment);
}

Result RunProgram(const std::string& program, const std::string& arguments,
                  const std::string& environment) {
  // a job engine's shard variables around the test run (a GitLab parallel: job, a Slurm array)
  // must not shard the suites the tests check; modules are found as a user's urdfsnap finds them
  const std::string command =
      "env -u CI_NODE_INDEX -u CI_NODE_TOTAL -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX "
      "-u URDFSNAP_SHARD_COUNT -u URDFSNAP_MODULE_DIR " + environment + " " + program + " " +
      arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

void ExpectTheOneFullDiskError(const std::string& arguments) {
  const Result r = RunProgram("sh -c 'trap \"\" XFSZ; ulimit -f 8; exec \"$0\" \"$@\"' " + std::string(URDFSNAP_BINARY),
                              arguments);
  EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
  EXPECT_EQ(r.output.rfind("urdfsnap: error: ", 0), 0u) << arguments << "\n" << r.output;
  EXPECT_NE(r.output.find(": cannot write: File too large"), std::string::npos) << arguments << "\n" << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << arguments << "\n" << r.output;
}

void ExpectSigtermStopsTheOneWorker(const std::string& arguments, const std::string& folder) {
  const std::string workers = "pgrep -f -- \"--worker-[p]ieces.*" + folder + "\"";
  const std::string script =
      "sh -c '\"$0\" \"$@\" & pid=$!; "
      "while ! ls " + folder + " 2>/dev/null | grep -q part; do kill -0 $pid 2>/dev/null || break; sleep 0.02; done; "
      "echo workers $(" + workers + " | wc -l); "
      "kill -TERM $pid; wait $pid; echo status $?; "
      "sleep 0.2; " + workers + " || echo no workers' " + std::string(URDFSNAP_BINARY);
  const Result r = RunProgram(script, arguments);
  EXPECT_NE(r.output.find("workers 1\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("status 143"), std::string::npos) << r.output;   // 128 + SIGTERM
  EXPECT_NE(r.output.find("no workers"), std::string::npos) << r.output;
}

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::map<std::string, std::string> FilesBelow(const std::string& folder) {
  std::map<std::string, std::string> files;
  if (!std::filesystem::exists(folder)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) {
      files[std::filesystem::relative(entry.path(), folder).generic_string()] = ReadBytes(entry.path().string());
    }
  }
  return files;
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

std::string CliTest::Ok(const std::string& arguments) {
  const Result result = RunUrdfsnap(arguments);
  EXPECT_EQ(result.status, 0) << "urdfsnap " << arguments << "\n" << result.output;
  return result.output;
}

std::string CliTest::Render(const std::string& arguments) {
  const std::string out = Path("render_" + std::to_string(renders_++) + ".png");
  Ok("render " + arguments + " -o " + out);
  return ReadBytes(out);
}

}  // namespace urdfsnap::cli_test
