// DrawBesideWorkers: Wait on a second thread, this process's pieces on the calling one.
#include "cli/pieces_beside_workers.h"

#include <signal.h>

#include <atomic>
#include <ctime>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace urdfsnap::cli {

namespace {

// Thrown out of this process's own piece once its workers have failed or were stopped (the
// exception Wait threw says which).
struct WorkersEnded {};

// Throws StoppedBySignal for a SIGINT or SIGTERM waiting for this process, taking it: once Wait has
// returned, nothing reads them (they stay blocked until the WorkerProcesses are destroyed).
void ThrowIfStopped() {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  const timespec now{};
  const int signal = sigtimedwait(&stop, nullptr, &now);
  if (signal > 0) throw StoppedBySignal{signal};
}

}  // namespace

void DrawBesideWorkers(WorkerProcesses& workers, const DrawOnePiece& draw_piece,
                       const std::function<void(std::int64_t done)>& progress, Warnings& worker_warnings) {
  std::mutex progress_mutex;   // `progress` and the counts below, updated by both threads
  std::int64_t by_workers = 0, by_this = 0;
  std::atomic<bool> workers_ended = false, workers_done = false;
  std::exception_ptr waited;
  std::thread waiter([&] {
    try {
      workers.Wait([&](std::int64_t done) {
        const std::lock_guard lock(progress_mutex);
        progress((by_workers = done) + by_this);
      }, worker_warnings);
      workers_done = true;
    } catch (...) {
      waited = std::current_exception();
      workers_ended = true;
    }
  });
  try {
    std::int64_t done = 0;
    while (const std::optional<int> piece = workers.TakePiece()) {
      done += draw_piece(*piece, [&](std::int64_t written) {
        if (workers_ended) throw WorkersEnded{};
        if (workers_done) ThrowIfStopped();   // this process's last pieces stop as the workers would
        const std::lock_guard lock(progress_mutex);
        progress(by_workers + (by_this = done + written));
      });
    }
  } catch (const WorkersEnded&) {
    // Wait's exception, below
  } catch (...) {
    workers.Interrupt();
    waiter.join();
    throw;
  }
  waiter.join();
  if (waited) std::rethrow_exception(waited);
  ThrowIfStopped();
}

}  // namespace urdfsnap::cli
