// The connections of the live view's clients that are waiting for a request, counted per client
// address, so that idle or slowly sending connections (a slowloris) cannot take every connection
// thread: past a limit per client, or past a limit over all clients, the connection that has
// waited longest is shut down, and the new one is served. A connection that has sent its request
// is being answered and is never shut down for this.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "serve/connection_limits.h"

namespace urdfsnap::serve {

class ClientConnections {
 public:
  explicit ClientConnections(ConnectionLimits limits) : limits_(limits) {}

  // Registers socket `fd` of client address `client`, waiting for its first request; returns its
  // id. Connections over a limit are shut down (shutdown(2): their reads end at once).
  std::uint64_t Open(const std::string& client, int fd);
  // The connection `id` waits for a request again (keep-alive), the wait counting from now.
  void Wait(std::uint64_t id);
  // The connection `id` has sent its request and is being answered.
  void Answer(std::uint64_t id);
  // The connection `id` is closed (before its socket is closed).
  void Close(std::uint64_t id);

  // How many connections wait now (for tests).
  std::size_t waiting() const;

 private:
  struct Connection {
    std::string client;
    int fd = -1;
    std::uint64_t waiting_since = 0;  // the order its wait began; 0: being answered, or shut down
  };
  void ShutDownOldest(const std::string* client);
  void EnforceLimits(const std::string& client);
  std::size_t WaitingOf(const std::string* client) const;

  ConnectionLimits limits_;
  mutable std::mutex mutex_;
  std::map<std::uint64_t, Connection> connections_;
  std::uint64_t next_id_ = 1, next_wait_ = 1;
};

}  // namespace urdfsnap::serve
