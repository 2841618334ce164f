// JobOptions: CLI11 options; RunStoppable: StoppedBySignal turned into EndBySignal.
#include "cli/job_options.h"

#include "cli/worker_processes.h"
#include "common/usable_cores.h"

namespace urdfsnap::cli {

void JobOptions::AddOptions(CLI::App& command, const std::string& help) {
  command.add_option("--jobs", jobs, help)->check(CLI::Range(1, 256));
  command.add_option("--worker-pieces", worker_pieces)->group("");   // WorkerProcesses' own
  command.add_option("--worker-output", worker_output)->group("");
}

int JobOptions::WorkerCount(bool one_process) const {
  if (worker() || one_process || ReadsStandardInput(OwnCommandLine())) return 1;
  return jobs > 0 ? jobs : UsableCores();
}

std::vector<std::string> JobOptions::WorkerOptions(int pieces, const std::string& output) {
  // a worker takes the pieces it is handed, whatever shard a job engine's variables name
  return {"--no-shard", "--worker-pieces", std::to_string(pieces), "--worker-output", output};
}

void RunStoppable(const std::function<void()>& run) {
  try {
    run();
  } catch (const StoppedBySignal& stopped) {
    EndBySignal(stopped.signal);
  }
}

}  // namespace urdfsnap::cli
