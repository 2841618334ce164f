// ClientConnections: a map of the open connections; the oldest wait found by a scan (the map
// holds at most the server's connection threads, a few dozen).
#include "serve/client_connections.h"

#include <sys/socket.h>

namespace urdfsnap::serve {

std::uint64_t ClientConnections::Open(const std::string& client, int fd) {
  std::lock_guard lock(mutex_);
  const std::uint64_t id = next_id_++;
  connections_[id] = Connection{client, fd, next_wait_++};
  EnforceLimits(client);
  return id;
}

void ClientConnections::Wait(std::uint64_t id) {
  std::lock_guard lock(mutex_);
  const auto found = connections_.find(id);
  if (found == connections_.end()) return;
  found->second.waiting_since = next_wait_++;
  EnforceLimits(found->second.client);
}

void ClientConnections::Answer(std::uint64_t id) {
  std::lock_guard lock(mutex_);
  if (const auto found = connections_.find(id); found != connections_.end()) found->second.waiting_since = 0;
}

void ClientConnections::Close(std::uint64_t id) {
  std::lock_guard lock(mutex_);
  connections_.erase(id);
}

std::size_t ClientConnections::waiting() const {
  std::lock_guard lock(mutex_);
  return WaitingOf(nullptr);
}

std::size_t ClientConnections::WaitingOf(const std::string* client) const {
  std::size_t count = 0;
  for (const auto& [id, c] : connections_) {
    if (c.waiting_since != 0 && (!client || c.client == *client)) ++count;
  }
  return count;
}

void ClientConnections::ShutDownOldest(const std::string* client) {
  Connection* oldest = nullptr;
  for (auto& [id, c] : connections_) {
    if (c.waiting_since == 0 || (client && c.client != *client)) continue;
    if (!oldest || c.waiting_since < oldest->waiting_since) oldest = &c;
  }
  if (!oldest) return;
  // its thread is in poll or recv on the socket: both return, and the connection ends
  ::shutdown(oldest->fd, SHUT_RDWR);
  oldest->waiting_since = 0;
}

void ClientConnections::EnforceLimits(const std::string& client) {
  while (WaitingOf(&client) > limits_.per_client) ShutDownOldest(&client);
  while (WaitingOf(nullptr) > limits_.total) ShutDownOldest(nullptr);
}

}  // namespace urdfsnap::serve
