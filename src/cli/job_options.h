// --jobs N for the commands whose work is split over worker processes on one machine (animate's
// frame sequences, dataset, docs), the hidden options their workers are started with, and the
// command's callback that ends the process by a stopping signal after its clean-up.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace urdfsnap::cli {

struct JobOptions {
  int jobs = 0;               // --jobs: worker processes; 0 = one per usable core
  int worker_pieces = 0;      // a worker's: the pieces its parent cut the work into
  // a worker's: where it leaves its files for its parent, a suffix of their names (animate,
  // dataset) or the parent's folder (docs)
  std::string worker_output;

  bool worker() const { return worker_pieces > 0; }

  // How many worker processes to start: --jobs, by default one per core this process may use; 1
  // (the work done in this process) for a worker itself, when `one_process` (a shard of a larger
  // job, work that does not split), or when the command line names standard input (a worker could
  // not read it again).
  int WorkerCount(bool one_process) const;

  // Adds --jobs, saying `help`, and the workers' hidden options to `command`.
  void AddOptions(CLI::App& command, const std::string& help);

  // The options that make this command a worker: the work cut into `pieces` pieces (contiguous
  // runs of frames, samples or pictures, each worker taking the next as it finishes one, so that a
  // worker slowed by other programs takes fewer), its files left at `output` (worker_output).
  static std::vector<std::string> WorkerOptions(int pieces, const std::string& output);
};

// Runs `run`; when it ends by StoppedBySignal (its clean-up done), ends this process by that signal.
void RunStoppable(const std::function<void()>& run);

}  // namespace urdfsnap::cli
