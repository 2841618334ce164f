// LoadMeshFiles: a worker per core pulling paths from one list; errors are kept, not thrown, so the
// caller can report them at the link that names the file.
#include "geometry/mesh_loading.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace urdfsnap::geometry {

std::map<std::string, MeshLoad> LoadMeshFiles(const std::set<std::string>& paths) {
  const std::vector<std::string> files(paths.begin(), paths.end());
  std::vector<MeshLoad> loads(files.size());
  std::atomic<size_t> next = 0;
  const auto work = [&] {
    for (size_t i = next++; i < files.size(); i = next++) {
      try {
        loads[i].file = LoadMeshFile(files[i]);
      } catch (...) {
        loads[i].error = std::current_exception();
      }
    }
  };
  const size_t workers = std::min<size_t>(files.size(), std::max(1u, std::thread::hardware_concurrency()));
  if (workers <= 1) {
    work();
  } else {
    std::vector<std::jthread> pool;
    for (size_t w = 0; w < workers; ++w) pool.emplace_back(work);
  }
  std::map<std::string, MeshLoad> by_path;
  for (size_t i = 0; i < files.size(); ++i) by_path.emplace(files[i], std::move(loads[i]));
  return by_path;
}

}  // namespace urdfsnap::geometry
