// `urdfsnap serve` run by a test as a user would: started in the background, its address read
// from the first line of stdout, stopped with a signal, its stderr and exit status kept; plus an
// HTTP client for it and its resident memory.
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>

#include <httplib.h>

namespace urdfsnap::serve_test {

class ServeProcess {
 public:
  // Runs `urdfsnap serve ARGUMENTS` (split by the shell) and waits up to `deadline_seconds` for
  // its first line. started() is false when it exited or printed something else first.
  explicit ServeProcess(const std::string& arguments, int deadline_seconds = 60);
  // Stops it with SIGKILL if Stop() was not called.
  ~ServeProcess();
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  bool started() const { return port_ > 0; }
  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  const std::string& first_line() const { return first_line_; }
  // A client for the server (5 s timeouts).
  std::unique_ptr<httplib::Client> Client() const;
  // Its resident set size now, in kB (0 when it has exited).
  long RssKb() const;
  // Sends `signal`, waits up to `deadline_seconds` for the exit; returns the exit status, or -1
  // when it was killed by a signal or had to be killed after the deadline.
  int Stop(int signal, int deadline_seconds = 20);
  // Everything it wrote to stderr up to now (after Stop: all of it).
  std::string Stderr();
  // Waits until stderr holds `text` (up to `deadline_seconds`); true when it does.
  bool WaitForStderr(const std::string& text, int deadline_seconds = 20);

 private:
  void Drain(int timeout_ms);

  pid_t pid_ = -1;
  int port_ = 0;
  int out_fd_ = -1, err_fd_ = -1;
  std::string out_, err_, first_line_;
};

// A new connection to 127.0.0.1:port (its socket, -1 when it cannot be made), for the caller to
// use and close.
int ConnectLoopback(int port);

// Sends `bytes` to 127.0.0.1:port on a fresh connection, reads until the server closes it or
// `timeout_ms` pass, and returns what came back.
std::string RawExchange(int port, const std::string& bytes, int timeout_ms = 3000);

}  // namespace urdfsnap::serve_test
