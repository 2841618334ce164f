// A job queue with one worker.
#include "serve/render_thread.h"

#include <utility>

namespace urdfsnap::serve {

RenderThread::RenderThread(size_t max_waiting, gl::BackendChoice backend)
    : max_waiting_(max_waiting), backend_(std::move(backend)), thread_([this] { Loop(); }) {}

RenderThread::~RenderThread() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

std::future<void> RenderThread::Post(Job job) {
  std::promise<void> done;
  std::future<void> future = done.get_future();
  jobs_.emplace_back(std::move(job), std::move(done));
  wake_.notify_one();
  return future;
}

bool RenderThread::TryRun(Job job) {
  std::future<void> done;
  {
    const std::lock_guard lock(mutex_);
    if (jobs_.size() >= max_waiting_) return false;
    done = Post(std::move(job));
  }
  done.get();
  return true;
}

void RenderThread::Run(Job job) {
  std::future<void> done;
  {
    const std::lock_guard lock(mutex_);
    done = Post(std::move(job));
  }
  done.get();
}

void RenderThread::Loop() {
  FrameSource frames(backend_);  // made, used and destroyed on this thread
  for (;;) {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
    if (jobs_.empty()) return;  // stopping, nothing left
    auto [job, done] = std::move(jobs_.front());
    jobs_.pop_front();
    lock.unlock();
    try {
      job(frames);
      done.set_value();
    } catch (...) {
      done.set_exception(std::current_exception());
    }
  }
}

}  // namespace urdfsnap::serve
