// The one thread that renders: it owns the FrameSource (the GL contexts, the loaded models) and
// runs jobs one after another, so every GL call and every render-sized allocation happens on one
// thread (the connection threads only wait for their job). At most `max_waiting` jobs wait; a
// request beyond them is turned away at once rather than queued without bound.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

#include "gl/backend.h"
#include "serve/frame_source.h"

namespace urdfsnap::serve {

class RenderThread {
 public:
  using Job = std::function<void(FrameSource&)>;

  // backend: the GL backend of the FrameSource's contexts.
  RenderThread(size_t max_waiting, gl::BackendChoice backend);
  // Finishes the job being run and the waiting ones, then ends the thread.
  ~RenderThread();
  RenderThread(const RenderThread&) = delete;
  RenderThread& operator=(const RenderThread&) = delete;

  // Runs `job` on the render thread and waits for it; rethrows what it throws. Returns false,
  // without running it, when `max_waiting` jobs are waiting already.
  bool TryRun(Job job);
  // Runs `job` on the render thread and waits for it, however many wait before it.
  void Run(Job job);

 private:
  std::future<void> Post(Job job);
  void Loop();

  const size_t max_waiting_;
  const gl::BackendChoice backend_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::pair<Job, std::promise<void>>> jobs_;
  bool stopping_ = false;
  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace urdfsnap::serve
