// A connection's socket as cpp-httplib reads requests from and writes responses to, with bounds
// the library's own socket stream lacks: each request must arrive whole (request line, headers and
// body) within a time and a byte budget, counted from when the server starts waiting for it, and
// each response must be taken by the client within a time. A client that sends a byte every few
// seconds, or headers without end, is cut off when its budget is spent instead of holding a
// connection thread (and memory) for as long as it likes.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <string>

#include <httplib.h>

#include "serve/connection_limits.h"

namespace urdfsnap::serve {

class DeadlineStream : public httplib::Stream {
 public:
  // `fd` is the connected socket (not owned); `listening` the server's listening socket, which
  // becomes INVALID_SOCKET when the server stops: waits then end within a quarter second.
  DeadlineStream(int fd, const std::atomic<int>& listening, StreamLimits limits);

  // Starts the budgets of the next request from now.
  void BeginRequest();
  // Waits until the client sends something (true), or the request's time ends, the client closes
  // or the server stops (false).
  bool WaitForRequest();
  // Whether the request's time or bytes ran out (the library then answers 400 and would read the
  // rest as the next request: the connection is to be closed instead).
  bool spent() const { return spent_; }

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  int socket() const override { return fd_; }

 private:
  using Clock = std::chrono::steady_clock;
  // Polls for `events` until `deadline`, in slices so that a stopping server is noticed; false
  // (and spent_ set) when the deadline passes first.
  bool Poll(short events, Clock::time_point deadline) const;

  int fd_;
  const std::atomic<int>& listening_;
  StreamLimits limits_;
  Clock::time_point read_deadline_, write_deadline_;
  bool writing_ = false;       // the response of the current request has begun
  mutable bool spent_ = false;
  std::size_t bytes_read_ = 0;  // of the current request
  char buffer_[4096];           // the library reads lines a byte at a time
  std::size_t buffered_ = 0, taken_ = 0;
};

}  // namespace urdfsnap::serve
