// fork/exec with stdout and stderr on pipes, a poll loop for the first line and for stderr, and
// a plain socket for requests no HTTP client would send.
#include "serve_process.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <thread>

namespace urdfsnap::serve_test {

namespace {

using Clock = std::chrono::steady_clock;

int MillisecondsLeft(Clock::time_point deadline) {
  return static_cast<int>(std::max<long>(
      0, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count()));
}

}  // namespace

ServeProcess::ServeProcess(const std::string& arguments, int deadline_seconds) {
  const std::string command = "exec " + std::string(URDFSNAP_BINARY) + " serve " + arguments;
  int out_pipe[2], err_pipe[2];
  if (pipe2(out_pipe, O_CLOEXEC) != 0 || pipe2(err_pipe, O_CLOEXEC) != 0) return;
  pid_ = fork();
  if (pid_ == 0) {
    const int null = open("/dev/null", O_RDONLY);
    dup2(null, 0);
    dup2(out_pipe[1], 1);
    dup2(err_pipe[1], 2);
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out_pipe[1]);
  close(err_pipe[1]);
  out_fd_ = out_pipe[0];
  err_fd_ = err_pipe[0];
  const auto deadline = Clock::now() + std::chrono::seconds(deadline_seconds);
  while (out_.find('\n') == std::string::npos && out_fd_ >= 0 && MillisecondsLeft(deadline) > 0) {
    Drain(MillisecondsLeft(deadline));
  }
  first_line_ = out_.substr(0, out_.find('\n'));
  std::smatch match;
  static const std::regex kAddress(R"(^urdfsnap: serving http://[^/]+:(\d+)/$)");
  if (std::regex_match(first_line_, match, kAddress)) port_ = std::stoi(match[1]);
}

ServeProcess::~ServeProcess() {
  if (pid_ > 0) Stop(SIGKILL);
}

void ServeProcess::Drain(int timeout_ms) {
  pollfd fds[2] = {{out_fd_, POLLIN, 0}, {err_fd_, POLLIN, 0}};
  std::string* sinks[2] = {&out_, &err_};
  int* owners[2] = {&out_fd_, &err_fd_};
  if (poll(fds, 2, timeout_ms) <= 0) return;
  for (int i = 0; i < 2; ++i) {
    if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    char buffer[65536];
    const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
    if (n > 0) {
      sinks[i]->append(buffer, static_cast<size_t>(n));
    } else {
      close(fds[i].fd);
      *owners[i] = -1;
    }
  }
}

std::unique_ptr<httplib::Client> ServeProcess::Client() const {
  auto client = std::make_unique<httplib::Client>("127.0.0.1", port_);
  client->set_connection_timeout(5);
  client->set_read_timeout(30);
  client->set_write_timeout(5);
  return client;
}

long ServeProcess::RssKb() const {
  std::ifstream status("/proc/" + std::to_string(pid_) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return 0;
}

int ServeProcess::Stop(int signal, int deadline_seconds) {
  if (pid_ <= 0) return -1;
  kill(pid_, signal);
  const auto deadline = Clock::now() + std::chrono::seconds(deadline_seconds);
  int status = 0;
  bool exited = false;
  while (!exited) {
    exited = waitpid(pid_, &status, WNOHANG) == pid_;
    if (!exited && MillisecondsLeft(deadline) == 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status, 0);
      status = -1;
      exited = true;
    }
    Drain(exited ? 0 : 20);
  }
  while (err_fd_ >= 0 || out_fd_ >= 0) Drain(1000);
  pid_ = -1;
  return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string ServeProcess::Stderr() {
  while (err_fd_ >= 0) {
    pollfd fd{err_fd_, POLLIN, 0};
    if (poll(&fd, 1, 0) <= 0) break;
    Drain(0);
  }
  return err_;
}

bool ServeProcess::WaitForStderr(const std::string& text, int deadline_seconds) {
  const auto deadline = Clock::now() + std::chrono::seconds(deadline_seconds);
  while (err_.find(text) == std::string::npos) {
    if (err_fd_ < 0 || MillisecondsLeft(deadline) == 0) return false;
    Drain(std::min(100, MillisecondsLeft(deadline)));
  }
  return true;
}

int ConnectLoopback(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (fd >= 0 && connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) return fd;
  if (fd >= 0) close(fd);
  return -1;
}

std::string RawExchange(int port, const std::string& bytes, int timeout_ms) {
  const int fd = ConnectLoopback(port);
  std::string reply;
  if (fd >= 0) {
    for (size_t sent = 0; sent < bytes.size();) {
      const ssize_t n = send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;  // the server closed it (e.g. after refusing the request line)
      sent += static_cast<size_t>(n);
    }
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    for (;;) {
      pollfd p{fd, POLLIN, 0};
      if (poll(&p, 1, MillisecondsLeft(deadline)) <= 0) break;
      char buffer[65536];
      const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      reply.append(buffer, static_cast<size_t>(n));
    }
  }
  if (fd >= 0) close(fd);
  return reply;
}

}  // namespace urdfsnap::serve_test
