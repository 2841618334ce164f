// A command's work made in parallel worker processes on one machine (`docs --jobs N`): this
// program started again (posix_spawn of /proc/self/exe, before any GL context is made) with the
// command line it was given and, after the command's name, options that make it a worker. The work
// is cut into pieces (shards K/M of it, M a few times the workers), handed to the workers one at a
// time as they finish the one before, so that a worker with cheaper pieces takes more of them and
// all end together (the parent may take pieces too, drawing beside its workers). Each worker is a process with its own GL context: Mesa's llvmpipe rasterises
// the contexts of one process on one shared set of threads, so only processes keep every core busy.
//
// What a worker and its parent say to each other:
//   worker's stdout  "next": it wants a piece; the parent answers on the worker's stdin with the
//                    piece's number K ("3\n"), or closes it when none is left (the worker ends)
//                    a number: the images the worker has finished so far, all pieces together
//                    (the parent sums them into its one progress line)
//   worker's stderr  "urdfsnap: warning: TEXT" (gathered into the parent's warnings, each once),
//                    "urdfsnap: error: TEXT" with a status other than 0 (the parent's error, once,
//                    the other workers stopped); any other line is passed on to the parent's stderr,
//                    each distinct line once (every worker says the same --verbose backend line)
// SIGINT and SIGTERM to the parent stop every worker before the parent ends by the same signal.
#pragma once

#include <sys/types.h>

#include <csignal>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/warnings.h"

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
  // Starts `count` workers, each running this process's command line with `options` inserted
  // after the first word equal to `command` ("docs"), to make `pieces` pieces. Blocks SIGINT and
  // SIGTERM in the calling thread until the destructor (so construct it before other threads
  // start); the workers start with the signal mask the caller had. Throws urdfsnap::Error when a
  // worker cannot be started (those already started are stopped).
  WorkerProcesses(int count, const std::string& command, const std::vector<std::string>& options, int pieces);
  // Stops (SIGTERM) and reaps every worker still running, then restores the signal mask.
  ~WorkerProcesses();
  WorkerProcesses(const WorkerProcesses&) = delete;
  WorkerProcesses& operator=(const WorkerProcesses&) = delete;

  // Hands out the pieces and waits until every worker has ended, calling `progress` with the
  // images done by all of them together as their counts arrive and adding their warnings to
  // `warnings`. Throws urdfsnap::Error with the first failing worker's error (or how it ended,
  // when it said nothing) after stopping the others; StoppedBySignal on SIGINT or SIGTERM.
  void Wait(const std::function<void(std::int64_t done)>& progress, Warnings& warnings);

  // Sends `line` (no newline in it) to every worker's stdin before the pieces, for ReadParentLine:
  // what the parent works out once for all of them (animate's camera fitted over every frame).
  void Tell(const std::string& line);

  // For a parent that draws pieces too, on another thread than Wait's: the next piece's number,
  // taken as a worker would take it, or nullopt when none is left.
  std::optional<int> TakePiece();
  // For that parent when its own pieces failed: makes Wait, on the other thread, stop every worker
  // and return.
  void Interrupt();

 private:
  struct Worker {
    pid_t pid = -1;
    int in = -1;                       // write end of its stdin, -1 once closed
    int out = -1, err = -1;            // read ends of its stdout and stderr, -1 once at their end
    std::string out_line, err_line;    // the part of a line read so far
    std::int64_t done = 0;
    std::string error;                 // its "urdfsnap: error:" text
  };

  void Start(Worker& worker, const std::vector<std::string>& arguments);
  // Reads what is waiting on `fd` of `worker`, answering its requests for pieces; false at its end.
  bool Drain(Worker& worker, int fd, Warnings& warnings);
  // The next piece's number to `worker`, or the end of its stdin when none is left.
  void HandOut(Worker& worker);
  // The error Wait throws for worker `index` that ended with `status` (waitpid's).
  std::string Failure(size_t index, int status) const;
  void StopAll();
  void CloseInterrupt();

  std::vector<Worker> workers_;
  int pieces_ = 0;
  std::mutex next_piece_mutex_;   // HandOut's and TakePiece's threads
  int next_piece_ = 1;
  int interrupt_[2] = {-1, -1};   // a pipe: a byte on it ends Wait
  sigset_t caller_mask_;
  struct sigaction caller_sigpipe_ {};
  int signal_fd_ = -1;
  std::set<std::string> passed_on_;   // the workers' other stderr lines already passed on
};

// A worker's side: the number of the next piece to make, asked of the parent; nullopt when none
// is left.
std::optional<int> NextPiece();

// A worker's side: the next line its parent sent with Tell, without the newline; nullopt when the
// parent closed the worker's stdin instead.
std::optional<std::string> ReadParentLine();

// A worker's side: the images it has finished so far, on stdout (the parent's progress).
void ReportImagesDone(std::int64_t done);

// A worker's side: SIGTERM when its parent ends, however it ends (a parent killed with SIGKILL
// cannot stop its workers itself).
void StopWhenParentEnds();

}  // namespace urdfsnap::cli
