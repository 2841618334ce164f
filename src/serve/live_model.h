// The model the live view shows, kept in step with its files: loaded again when one of them
// changes, or, while it cannot be loaded, now and then (a missing file may have appeared). Each
// load that changes what the server shows gets a new generation number, which is how the page
// notices a reload. Thread-safe.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "model/robot.h"
#include "serve/file_watcher.h"
#include "serve/frame_source.h"

namespace urdfsnap::serve {

struct ModelState {
  int generation = 0;
  std::shared_ptr<const model::Robot> robot;  // null when the model cannot be loaded
  std::string error;                          // why not: the located error, as `render` says it
  std::vector<std::string> warnings;          // the model's warnings
  size_t watched_files = 0;
};

class LiveModel {
 public:
  // `model_file` is watched whatever happens.
  explicit LiveModel(std::string model_file);

  // Loads the model with `load` (which throws urdfsnap::Error when it cannot be loaded or shown,
  // e.g. a mesh is missing) and watches the files it read (with the previous ones too when it
  // fails: the fix may be in any of them). The generation goes up unless the outcome is the same
  // error as before. Returns the new state.
  std::shared_ptr<const ModelState> Load(const std::function<WatchedModel()>& load);

  // True when the model should be loaded again: a watched file changed (and then stayed
  // unchanged for `settle`, so that a save in several writes is read once, complete), or the
  // model is broken and `retry` has passed since the last load.
  bool NeedsLoad(std::chrono::milliseconds settle = std::chrono::milliseconds(100),
                 std::chrono::milliseconds retry = std::chrono::seconds(2));

  std::shared_ptr<const ModelState> State() const;

 private:
  const std::string model_file_;
  std::mutex load_mutex_;  // one Load or NeedsLoad at a time (the watcher)
  FileWatcher watcher_;
  bool changed_during_load_ = false;
  std::chrono::steady_clock::time_point last_load_;
  mutable std::mutex state_mutex_;
  std::shared_ptr<const ModelState> state_ = std::make_shared<ModelState>();
};

}  // namespace urdfsnap::serve
