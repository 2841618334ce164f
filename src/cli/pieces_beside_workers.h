// A command that draws pieces of its work itself beside its worker processes (`animate --jobs N`,
// `dataset --jobs N`: this process and N-1 workers), taking them from the same counter as the
// workers: one process fewer to start, read the model into and set up llvmpipe in.
#pragma once

#include <cstdint>
#include <functional>

#include "cli/worker_processes.h"
#include "common/warnings.h"

namespace urdfsnap::cli {

// Draws one piece (its number), calling its argument with the images of the piece done so far;
// returns how many images the piece has.
using DrawOnePiece = std::function<std::int64_t(int piece, const std::function<void(std::int64_t done)>& progress)>;

// Draws pieces taken with workers.TakePiece by `draw_piece` on this thread while workers.Wait runs
// on a second one, until no piece is left and every worker has ended. `progress` gets the images
// done by everyone together (called from either thread, never from both at once); the workers'
// warnings go to `worker_warnings` (`draw_piece` keeps this process's own: Warnings is one
// thread's). When the workers fail or a signal stops them, this process's piece is abandoned at
// its next progress call and Wait's exception thrown; when `draw_piece` throws, the workers are
// stopped and its exception thrown. A SIGINT or SIGTERM that arrives after the workers have ended
// stops this process's pieces too (StoppedBySignal), as Wait would have.
void DrawBesideWorkers(WorkerProcesses& workers, const DrawOnePiece& draw_piece,
                       const std::function<void(std::int64_t done)>& progress, Warnings& worker_warnings);

}  // namespace urdfsnap::cli
