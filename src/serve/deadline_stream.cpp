// DeadlineStream: poll(2) against a deadline, recv into a small buffer, send with MSG_NOSIGNAL.
#include "serve/deadline_stream.h"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace urdfsnap::serve {

namespace {

// how often a wait looks whether the server is stopping
constexpr std::chrono::milliseconds kStopSlice{250};

void AddressOf(const sockaddr_storage& address, std::string& ip, int& port) {
  char text[INET6_ADDRSTRLEN] = "";
  if (address.ss_family == AF_INET) {
    const auto& a = reinterpret_cast<const sockaddr_in&>(address);
    inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
    port = ntohs(a.sin_port);
  } else if (address.ss_family == AF_INET6) {
    const auto& a = reinterpret_cast<const sockaddr_in6&>(address);
    inet_ntop(AF_INET6, &a.sin6_addr, text, sizeof text);
    port = ntohs(a.sin6_port);
  }
  ip = text;
}

}  // namespace

DeadlineStream::DeadlineStream(int fd, const std::atomic<int>& listening, StreamLimits limits)
    : fd_(fd), listening_(listening), limits_(limits) {
  BeginRequest();
}

void DeadlineStream::BeginRequest() {
  read_deadline_ = Clock::now() + limits_.request_time;
  writing_ = false;
  bytes_read_ = 0;
}

bool DeadlineStream::Poll(short events, Clock::time_point deadline) const {
  for (;;) {
    if (listening_.load() == INVALID_SOCKET) return false;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      spent_ = true;
      return false;
    }
    pollfd p{fd_, events, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min(left, kStopSlice).count()));
    if (ready > 0) return true;   // readable, writable, or closed (the read or write then says)
    if (ready < 0 && errno != EINTR) return false;
  }
}

bool DeadlineStream::WaitForRequest() {
  if (taken_ < buffered_) return true;  // a pipelined request is here already
  return Poll(POLLIN, read_deadline_);
}

bool DeadlineStream::is_readable() const {
  return taken_ < buffered_ || Poll(POLLIN, read_deadline_);
}

bool DeadlineStream::is_writable() const {
  const auto deadline = writing_ ? write_deadline_ : Clock::now() + limits_.response_time;
  return Poll(POLLOUT, deadline);
}

ssize_t DeadlineStream::read(char* ptr, size_t size) {
  if (taken_ == buffered_) {
    if (!Poll(POLLIN, read_deadline_)) return -1;
    ssize_t got;
    do {
      got = ::recv(fd_, buffer_, sizeof buffer_, 0);
    } while (got < 0 && errno == EINTR);
    if (got <= 0) return got;
    buffered_ = static_cast<std::size_t>(got);
    taken_ = 0;
  }
  const std::size_t budget = limits_.request_bytes - std::min(bytes_read_, limits_.request_bytes);
  const std::size_t n = std::min({size, buffered_ - taken_, budget});
  if (n == 0) {
    spent_ = true;  // the request's byte budget
    return -1;
  }
  std::memcpy(ptr, buffer_ + taken_, n);
  taken_ += n;
  bytes_read_ += n;
  return static_cast<ssize_t>(n);
}

ssize_t DeadlineStream::write(const char* ptr, size_t size) {
  if (!writing_) {
    writing_ = true;
    write_deadline_ = Clock::now() + limits_.response_time;
  }
  if (!Poll(POLLOUT, write_deadline_)) return -1;
  ssize_t sent;
  do {
    sent = ::send(fd_, ptr, size, MSG_NOSIGNAL);
  } while (sent < 0 && errno == EINTR);
  return sent;
}

void DeadlineStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (::getpeername(fd_, reinterpret_cast<sockaddr*>(&address), &length) == 0) AddressOf(address, ip, port);
}

void DeadlineStream::get_local_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length) == 0) AddressOf(address, ip, port);
}

}  // namespace urdfsnap::serve
