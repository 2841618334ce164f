// Fuzz target: snapshot suite files (YAML) read into cases, in a fresh working folder (goldens
// that lead out of it are refused), then the cases of a shard selected and their outputs planned
// as `snapshot check --report` and `update` plan them. Only urdfsnap::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "fuzz_work_dir.h"
#include "snapshot/case_selection.h"
#include "snapshot/golden_files.h"
#include "snapshot/run_outputs.h"
#include "snapshot/suite_file.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  urdfsnap::fuzz::EnterFreshWorkDir();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  const std::string path = fuzz::WriteInput("suite.yaml", data, size);
  try {
    const snapshot::Suite suite = snapshot::ReadSuite(path);
    const auto cases = snapshot::SelectCases(suite, {}, shard::Shard{1, 2});
    OutputPlan check;
    snapshot::AddSuiteInputs(check, suite, cases, true);
    snapshot::PlanReports(check, {"report", "junit.xml", "results.json"}, snapshot::CaseNames(cases));
    OutputPlan update;
    snapshot::AddSuiteInputs(update, suite, cases, false);
    for (const snapshot::SnapshotCase* c : cases) snapshot::PlanGoldens(update, *c);
    check.Prepare();  // the folders it makes go again with the plans, never committed
    update.Prepare();
  } catch (const Error&) {
  }
  return 0;
}
