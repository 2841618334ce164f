// Fuzz target: snapshot results files (JSON from another machine's CI job) read and merged as
// `snapshot merge` does, in a fresh working folder (a report_dir that leads out of it is refused,
// one inside finds nothing). Only urdfsnap::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/error.h"
#include "fuzz_work_dir.h"
#include "snapshot/results_file.h"
#include "snapshot/results_merge.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  urdfsnap::fuzz::EnterFreshWorkDir();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  try {
    const std::string path = fuzz::WriteInput("results.json", data, size);
    snapshot::RunResults results = snapshot::ReadResults(path);
    const std::string version = results.urdfsnap_version;
    std::vector<snapshot::ShardFile> files;
    files.push_back({path, std::move(results)});
    const snapshot::MergedResults merged = snapshot::MergeResults(std::move(files), version);
    OutputPlan outputs;  // never committed: nothing is left in the folder
    snapshot::CollectReportImages(outputs, merged, "merged");
  } catch (const Error&) {
  }
  return 0;
}
