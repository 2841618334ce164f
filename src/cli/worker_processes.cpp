// WorkerProcesses: posix_spawn with the workers' stdout and stderr on pipes, a poll loop over the
// pipes and a signalfd for SIGINT and SIGTERM, waitpid for how each ended.
#include "cli/worker_processes.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/signalfd.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "common/error.h"

extern char** environ;

namespace urdfsnap::cli {

namespace {

constexpr std::string_view kWarning = "urdfsnap: warning: ";
constexpr std::string_view kError = "urdfsnap: error: ";

std::string SystemError(const std::string& what) { return what + ": " + std::strerror(errno); }

}  // namespace

void EndBySignal(int signal) {
  std::signal(signal, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, signal);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  raise(signal);
  _exit(128 + signal);   // only when the signal's default action does not end a process
}

bool ReadsStandardInput(const std::vector<std::string>& arguments) {
  for (const std::string& word : arguments) {
    for (const std::string_view name : {"/dev/stdin", "/dev/fd/0", "/proc/self/fd/0"}) {
      if (word == name || (word.ends_with(name) && word.size() > name.size() && word[word.size() - name.size() - 1] == '=')) {
        return true;
      }
    }
  }
  return false;
}

std::vector<std::string> OwnCommandLine() {
  std::ifstream file("/proc/self/cmdline", std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  std::vector<std::string> words;
  for (size_t start = 0; start < text.size();) {
    const size_t end = text.find('\0', start);
    words.push_back(text.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return words;
}

WorkerProcesses::WorkerProcesses(int count, const std::string& command, const std::vector<std::string>& options,
                                 int pieces)
    : pieces_(pieces) {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop, &caller_mask_);
  signal_fd_ = signalfd(-1, &stop, SFD_CLOEXEC);
  if (pipe2(interrupt_, O_CLOEXEC) != 0) interrupt_[0] = interrupt_[1] = -1;
  // a worker that has ended makes writing to its stdin fail (EPIPE), not end this process
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &caller_sigpipe_);
  std::vector<std::string> arguments = OwnCommandLine();
  const auto at = std::find(arguments.begin() + std::min<size_t>(1, arguments.size()), arguments.end(), command);
  try {
    if (signal_fd_ < 0) throw Error(SystemError("cannot start worker processes: signalfd"));
    if (interrupt_[0] < 0) throw Error(SystemError("cannot start worker processes: pipe"));
    if (at == arguments.end()) throw Error("cannot start worker processes: no '" + command + "' in this process's command line");
    arguments.insert(at + 1, options.begin(), options.end());
    workers_.resize(count);
    for (Worker& worker : workers_) Start(worker, arguments);
  } catch (...) {
    StopAll();
    if (signal_fd_ >= 0) close(signal_fd_);
    CloseInterrupt();
    sigaction(SIGPIPE, &caller_sigpipe_, nullptr);
    pthread_sigmask(SIG_SETMASK, &caller_mask_, nullptr);
    throw;
  }
}

WorkerProcesses::~WorkerProcesses() {
  StopAll();
  close(signal_fd_);
  CloseInterrupt();
  sigaction(SIGPIPE, &caller_sigpipe_, nullptr);
  pthread_sigmask(SIG_SETMASK, &caller_mask_, nullptr);
}

void WorkerProcesses::Start(Worker& worker, const std::vector<std::string>& arguments) {
  std::array<int, 2> in{-1, -1}, out{-1, -1}, err{-1, -1};
  if (pipe2(in.data(), O_CLOEXEC) != 0 || pipe2(out.data(), O_CLOEXEC) != 0 || pipe2(err.data(), O_CLOEXEC) != 0) {
    const std::string message = SystemError("cannot start worker processes: pipe");
    for (const int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) {
      if (fd >= 0) close(fd);
    }
    throw Error(message);
  }
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_adddup2(&files, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&files, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&files, err[1], STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setsigmask(&attributes, &caller_mask_);
  sigset_t sigpipe;   // as the caller had it, not ignored as here
  sigemptyset(&sigpipe);
  if (caller_sigpipe_.sa_handler != SIG_IGN) sigaddset(&sigpipe, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &sigpipe);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const int failed = posix_spawn(&worker.pid, "/proc/self/exe", &files, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&files);
  close(in[0]);
  close(out[1]);
  close(err[1]);
  worker.in = in[1];
  worker.out = out[0];
  worker.err = err[0];
  if (failed != 0) {
    worker.pid = -1;
    throw Error(std::string("cannot start worker processes: ") + std::strerror(failed));
  }
}

void WorkerProcesses::StopAll() {
  for (Worker& worker : workers_) {
    if (worker.pid > 0) kill(worker.pid, SIGTERM);
  }
  for (Worker& worker : workers_) {
    if (worker.pid > 0) {
      while (waitpid(worker.pid, nullptr, 0) < 0 && errno == EINTR) {
      }
      worker.pid = -1;
    }
    for (int* fd : {&worker.in, &worker.out, &worker.err}) {
      if (*fd >= 0) close(*fd);
      *fd = -1;
    }
  }
}

bool WorkerProcesses::Drain(Worker& worker, int fd, Warnings& warnings) {
  std::array<char, 4096> buffer;
  const ssize_t n = read(fd, buffer.data(), buffer.size());
  if (n < 0) return errno == EINTR || errno == EAGAIN;
  if (n == 0) return false;
  std::string& line = fd == worker.out ? worker.out_line : worker.err_line;
  for (const char c : std::string_view(buffer.data(), static_cast<size_t>(n))) {
    if (c != '\n') {
      line += c;
      continue;
    }
    if (fd == worker.out && line == "next") {
      HandOut(worker);
    } else if (fd == worker.out) {
      worker.done = std::strtoll(line.c_str(), nullptr, 10);
    } else if (line.starts_with(kWarning)) {
      warnings.Add(line.substr(kWarning.size()));
    } else if (line.starts_with(kError)) {
      worker.error = line.substr(kError.size());
    } else if (passed_on_.insert(line).second) {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
    line.clear();
  }
  return true;
}

void WorkerProcesses::HandOut(Worker& worker) {
  if (worker.in < 0) return;
  if (const std::optional<int> piece = TakePiece()) {
    const std::string line = std::to_string(*piece) + "\n";
    if (write(worker.in, line.data(), line.size()) == static_cast<ssize_t>(line.size())) return;
  }
  close(worker.in);   // no piece left (or the worker has gone: its end is read from its stdout)
  worker.in = -1;
}

std::string WorkerProcesses::Failure(size_t index, int status) const {
  const Worker& worker = workers_[index];
  if (!worker.error.empty()) return worker.error;
  const std::string who = "worker process " + std::to_string(index + 1) + " of " + std::to_string(workers_.size());
  if (WIFSIGNALED(status)) return who + " was ended by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  return who + " ended with status " + std::to_string(WEXITSTATUS(status)) + " and no error message";
}

void WorkerProcesses::Wait(const std::function<void(std::int64_t done)>& progress, Warnings& warnings) {
  size_t running = workers_.size();
  while (running > 0) {
    std::vector<pollfd> fds;
    std::vector<Worker*> owners;
    for (Worker& worker : workers_) {
      for (int fd : {worker.out, worker.err}) {
        if (fd < 0) continue;
        fds.push_back({fd, POLLIN, 0});
        owners.push_back(&worker);
      }
    }
    fds.push_back({interrupt_[0], POLLIN, 0});
    fds.push_back({signal_fd_, POLLIN, 0});
    if (poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw Error(SystemError("waiting for the worker processes: poll"));
    }
    if (fds[fds.size() - 2].revents & POLLIN) {
      StopAll();
      return;
    }
    if (fds.back().revents & POLLIN) {
      signalfd_siginfo info{};
      const ssize_t n = read(signal_fd_, &info, sizeof info);
      StopAll();
      throw StoppedBySignal{n == sizeof info ? static_cast<int>(info.ssi_signo) : SIGTERM};
    }
    for (size_t i = 0; i + 2 < fds.size(); ++i) {
      if (fds[i].revents == 0) continue;
      Worker& worker = *owners[i];
      if (Drain(worker, fds[i].fd, warnings)) continue;
      close(fds[i].fd);
      (fds[i].fd == worker.out ? worker.out : worker.err) = -1;
    }
    std::int64_t done = 0;
    for (const Worker& worker : workers_) done += worker.done;
    if (progress) progress(done);
    for (size_t index = 0; index < workers_.size(); ++index) {
      Worker& worker = workers_[index];
      if (worker.pid < 0 || worker.out >= 0 || worker.err >= 0) continue;
      int status = 0;
      while (waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
      }
      worker.pid = -1;
      if (worker.in >= 0) close(worker.in);
      worker.in = -1;
      --running;
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0) continue;
      const std::string failure = Failure(index, status);
      StopAll();
      throw Error(failure);
    }
  }
}

void WorkerProcesses::Tell(const std::string& line) {
  const std::string text = line + "\n";
  for (Worker& worker : workers_) {
    // a worker that has ended is reported by Wait
    if (worker.in >= 0 && write(worker.in, text.data(), text.size()) != static_cast<ssize_t>(text.size())) {
      close(worker.in);
      worker.in = -1;
    }
  }
}

std::optional<int> WorkerProcesses::TakePiece() {
  const std::lock_guard lock(next_piece_mutex_);
  if (next_piece_ > pieces_) return std::nullopt;
  return next_piece_++;
}

void WorkerProcesses::Interrupt() {
  const char byte = 0;
  while (write(interrupt_[1], &byte, 1) < 0 && errno == EINTR) {
  }
}

void WorkerProcesses::CloseInterrupt() {
  for (int& fd : interrupt_) {
    if (fd >= 0) close(fd);
    fd = -1;
  }
}

std::optional<std::string> ReadParentLine() {
  std::string line;
  for (int c = std::getchar(); c != '\n'; c = std::getchar()) {
    if (c == EOF) return std::nullopt;
    line += static_cast<char>(c);
  }
  return line;
}

std::optional<int> NextPiece() {
  std::printf("next\n");
  std::fflush(stdout);
  char line[32];
  if (std::fgets(line, sizeof line, stdin) == nullptr) return std::nullopt;
  return static_cast<int>(std::strtol(line, nullptr, 10));
}

void ReportImagesDone(std::int64_t done) {
  std::printf("%lld\n", static_cast<long long>(done));
  std::fflush(stdout);
}

void StopWhenParentEnds() { prctl(PR_SET_PDEATHSIG, SIGTERM); }

}  // namespace urdfsnap::cli
