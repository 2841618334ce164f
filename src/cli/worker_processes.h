// A command's shards made in parallel worker processes on one machine (`docs --jobs N`): this
// program started again (posix_spawn of /proc/self/exe, before any GL context is made) with the
// command line it was given and, after the command's name, options that make it worker K of N.
// Each worker is a process of its own with its own GL context: Mesa's llvmpipe rasterises the
// contexts of one process on one shared set of threads, so only processes keep every core busy.
//
// What a worker says, and how its parent takes it:
//   stdout  one line per finished image, the count of its shard's images done so far ("17\n"):
//           the parent sums them into its one progress line
//   stderr  "urdfsnap: warning: TEXT" (gathered into the parent's warnings, each once),
//           "urdfsnap: error: TEXT" with a status other than 0 (the parent's error, once, the
//           other workers stopped); any other line is passed on to the parent's stderr
// SIGINT and SIGTERM to the parent stop every worker before the parent ends by the same signal.
#pragma once

#include <sys/types.h>

#include <csignal>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/warnings.h"
#include "shard/shard_spec.h"

namespace urdfsnap::cli {

// Thrown by WorkerProcesses::Wait when SIGINT or SIGTERM arrived: the workers are stopped. The
// caller lets its own clean-up run (temporary folders removed), then calls EndBySignal.
struct StoppedBySignal {
  int signal;
};

// Ends this process by `signal` with its default action, as if it had never been caught (the
// shell then reports an interrupted command, status 128 + signal).
[[noreturn]] void EndBySignal(int signal);

// Whether the command line names standard input as a file (/dev/stdin, /dev/fd/0 or
// /proc/self/fd/0, alone or after "="): a worker could not read it again.
bool ReadsStandardInput(const std::vector<std::string>& arguments);

// This process's command line (/proc/self/cmdline), its program first.
std::vector<std::string> OwnCommandLine();

class WorkerProcesses {
 public:
  // Starts `count` workers, worker k (1-based) running this process's command line with
  // `options({k, count})` inserted after the first word equal to `command` ("docs"). Blocks
  // SIGINT and SIGTERM in the calling thread until the destructor (so construct it before other
  // threads start); the workers start with the signal mask the caller had. Throws urdfsnap::Error
  // when a worker cannot be started (those already started are stopped).
  WorkerProcesses(int count, const std::string& command,
                  const std::function<std::vector<std::string>(shard::Shard)>& options);
  // Stops (SIGTERM) and reaps every worker still running, then restores the signal mask.
  ~WorkerProcesses();
  WorkerProcesses(const WorkerProcesses&) = delete;
  WorkerProcesses& operator=(const WorkerProcesses&) = delete;

  // Waits until every worker has ended, calling `progress` with the images done by all of them
  // together as their counts arrive and adding their warnings to `warnings`. Throws
  // urdfsnap::Error with the first failing worker's error (or how it ended, when it said nothing)
  // after stopping the others; StoppedBySignal on SIGINT or SIGTERM.
  void Wait(const std::function<void(std::int64_t done)>& progress, Warnings& warnings);

 private:
  struct Worker {
    shard::Shard shard;
    pid_t pid = -1;
    int out = -1, err = -1;            // read ends of its stdout and stderr, -1 once at their end
    std::string out_line, err_line;    // the part of a line read so far
    std::int64_t done = 0;
    std::string error;                 // its "urdfsnap: error:" text
  };

  void Start(Worker& worker, const std::vector<std::string>& arguments);
  // Reads what is waiting on `fd` of `worker`; false at its end.
  bool Drain(Worker& worker, int fd, Warnings& warnings);
  // The error Wait throws for a worker that ended with `status` (waitpid's).
  std::string Failure(const Worker& worker, int status) const;
  void StopAll();

  std::vector<Worker> workers_;
  sigset_t caller_mask_;
  int signal_fd_ = -1;
};

// A worker's side: its shard's images done so far, on stdout (the parent's progress).
void ReportImagesDone(std::int64_t done);

// A worker's side: SIGTERM when its parent ends, however it ends (a parent killed with SIGKILL
// cannot stop its workers itself).
void StopWhenParentEnds();

}  // namespace urdfsnap::cli
