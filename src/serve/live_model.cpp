// Loading, watching and the generation count of the live view's model.
#include "serve/live_model.h"

#include <set>
#include <thread>


namespace urdfsnap::serve {

LiveModel::LiveModel(std::string model_file) : model_file_(std::move(model_file)) {}

std::shared_ptr<const ModelState> LiveModel::Load(const std::function<WatchedModel()>& load) {
  const std::lock_guard load_lock(load_mutex_);
  const std::shared_ptr<const ModelState> before = State();
  auto next = std::make_shared<ModelState>();
  std::set<std::string> files{model_file_};
  try {
    WatchedModel loaded = load();
    files.insert(loaded.files.begin(), loaded.files.end());
    next->robot = std::move(loaded.robot);
    next->warnings = std::move(loaded.warnings);
  } catch (const std::exception& e) {  // urdfsnap::Error, and bad_alloc on a runaway model
    next->error = e.what();
    // keep watching what the last good load read too: the fix may be in any of those files
    for (const auto& file : watcher_.files()) files.insert(file);
  }
  changed_during_load_ = watcher_.Watch({files.begin(), files.end()});
  last_load_ = std::chrono::steady_clock::now();
  next->watched_files = files.size();
  const bool same_error = !next->robot && !before->robot && next->error == before->error &&
                          before->generation > 0;
  next->generation = same_error ? before->generation : before->generation + 1;
  const std::lock_guard state_lock(state_mutex_);
  state_ = next;
  return next;
}

bool LiveModel::NeedsLoad(std::chrono::milliseconds settle, std::chrono::milliseconds retry) {
  const std::lock_guard load_lock(load_mutex_);
  if (changed_during_load_) return true;
  if (watcher_.Changed()) {
    // an editor may write a file in several steps: wait until a look finds nothing new
    for (int looks = 0; looks < 10; ++looks) {
      std::this_thread::sleep_for(settle);
      if (!watcher_.Changed()) break;
    }
    return true;
  }
  return !State()->robot && std::chrono::steady_clock::now() - last_load_ >= retry;
}

std::shared_ptr<const ModelState> LiveModel::State() const {
  const std::lock_guard state_lock(state_mutex_);
  return state_;
}

}  // namespace urdfsnap::serve
