// Fuzz target: the xacro processor on one file (includes and load_yaml may name others). Any
// outcome but a result or urdfsnap::Error is a bug: a crash, a sanitizer report, another exception
// type (a message without the file), a hang or unbounded memory.
//
// ExpandFile starts a thread with a 256 MiB stack per call, whose unmapping (with ASan's shadow)
// costs more than most inputs; the target runs the same Processor on one such thread, started
// once, to keep millions of executions within reach.
#include <pthread.h>

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <string>

#include "common/error.h"
#include "fuzz_evaluation_budget.h"
#include "fuzz_work_dir.h"
#include "xacro/internal/processor.h"

namespace {

struct Worker {
  std::mutex mutex;
  std::condition_variable changed;
  std::string path;  // the input to expand; empty when there is none
  bool busy = false;

  // the worker's loop: wait for an input, expand it, report back
  static void* Loop(void* self) {
    auto& w = *static_cast<Worker*>(self);
    while (true) {
      std::unique_lock lock(w.mutex);
      w.changed.wait(lock, [&] { return w.busy; });
      urdfsnap::xacro::Options options;
      options.args = {{"arg", "1.5"}};
      // the same limit code with smaller budgets, so that runaway inputs end in milliseconds
      options.max_document_bytes = std::size_t{8} << 20;
      const auto budget = urdfsnap::fuzz::SmallEvaluationBudget();
      urdfsnap::Warnings warnings;
      try {
        urdfsnap::xacro::Processor(options, warnings).Run(w.path);
      } catch (const urdfsnap::Error&) {
      }
      w.busy = false;
      w.changed.notify_all();
    }
    return nullptr;
  }

  void Start() {
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, std::size_t{256} << 20);  // as ExpandFile's thread
    pthread_t thread;
    if (pthread_create(&thread, &attr, &Loop, this) != 0) std::abort();
    pthread_attr_destroy(&attr);
  }

  void Expand(const std::string& input) {
    std::unique_lock lock(mutex);
    path = input;
    busy = true;
    changed.notify_all();
    changed.wait(lock, [&] { return !busy; });
  }
};

// never destroyed: at exit the thread still waits on its condition variable, whose destruction
// would wait for it forever
Worker& worker = *new Worker;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  urdfsnap::fuzz::EnterFreshWorkDir();
  worker.Start();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  worker.Expand(urdfsnap::fuzz::WriteInput("robot.xacro", data, size));
  return 0;
}
