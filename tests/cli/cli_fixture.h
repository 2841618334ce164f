// What the command-line tests share: running the urdfsnap binary and a fresh folder per test.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "support/gl_required.h"  // URDFSNAP_REQUIRE_GL() for the tests that render
#include "support/temp_folder.h"

namespace urdfsnap::cli_test {

inline const std::filesystem::path kSource = URDFSNAP_SOURCE_DIR;
inline const std::string kMrm = (kSource / "models/mrm_description/urdf/mrm.urdf").string();

struct Result {
  int status;          // exit status, -1 when killed by a signal
  std::string output;  // stdout and stderr together
};

// Runs "urdfsnap ARGUMENTS" through the shell with `environment` ("VAR=value" words) added to the
// test's environment less the job engines' shard variables (CI_NODE_INDEX, SLURM_ARRAY_TASK_ID, ...).
Result RunUrdfsnap(const std::string& arguments, const std::string& environment = "");
// The same for another copy of the binary at `program`.
Result RunProgram(const std::string& program, const std::string& arguments,
                  const std::string& environment = "");

// Runs "urdfsnap ARGUMENTS" with every file it writes refused past 4 KB (as on a full disk) and
// expects the command's one error line for it ("urdfsnap: error: ...: cannot write: File too
// large"), exit status 2.
void ExpectTheOneFullDiskError(const std::string& arguments);

// Runs "urdfsnap ARGUMENTS" (with --jobs 2) in the background, sends it SIGTERM once a file with
// "part" in its name (a worker's or the command's own, under its temporary name) is in `folder`,
// and expects exactly one worker process to have run beside the command, the command to end by
// that signal (status 143) and no worker to be left.
void ExpectSigtermStopsTheOneWorker(const std::string& arguments, const std::string& folder);

// The bytes of a file ("" when it cannot be read).
std::string ReadBytes(const std::string& path);

// Every file below `folder` by its path relative to it, with its bytes (none when it is missing).
std::map<std::string, std::string> FilesBelow(const std::string& folder);

// A fresh, empty folder per test, removed afterwards.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  // Writes `text` to the file `name` in the folder and returns its path.
  std::string Write(const std::string& name, const std::string& text) const;
  // Runs "urdfsnap ARGUMENTS", expects success (exit 0) and returns its output.
  std::string Ok(const std::string& arguments);
  // The bytes "urdfsnap render ARGUMENTS -o FILE" writes, FILE a new PNG in the folder each call.
  std::string Render(const std::string& arguments);
  int renders_ = 0;   // Render's files so far
  std::optional<test::TempFolder> folder_;
  std::filesystem::path dir_;  // folder_'s path
};

}  // namespace urdfsnap::cli_test
