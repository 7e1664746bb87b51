#include "process.h"
#include "cgroup.h"
#include "no_network.h"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>

namespace runner {

namespace {

using Clock = std::chrono::steady_clock;

// Keeps the head and the tail of a stream: a crash report is printed last.
class Capture {
 public:
  explicit Capture(std::size_t kept) : half_(kept / 2) {}
  void add(const char* data, std::size_t n) {
    total_ += n;
    const std::size_t into_head = head_.size() < half_ ? std::min(n, half_ - head_.size()) : 0;
    head_.append(data, into_head);
    tail_.append(data + into_head, n - into_head);
    if (tail_.size() > 2 * half_) tail_.erase(0, tail_.size() - half_);
  }
  std::size_t total() const { return total_; }
  std::string text() const {
    std::string tail = tail_.size() > half_ ? tail_.substr(tail_.size() - half_) : tail_;
    if (total_ > head_.size() + tail.size())
      return head_ + "\n[... " + std::to_string(total_ - head_.size() - tail.size()) +
             " bytes of output left out ...]\n" + tail;
    return head_ + tail;
  }

 private:
  std::size_t half_;
  std::size_t total_ = 0;
  std::string head_, tail_;
};

[[noreturn]] void exec_child(const std::vector<std::string>& argv, const Environment& env, const Limits& limits,
                             const std::string& directory, int output) {
  setsid();  // its own session and group: a time-out kills everything it started; no terminal
  dup2(output, 1);
  dup2(output, 2);
  close(output);
  const int null = open("/dev/null", O_RDONLY);
  if (null >= 0) dup2(null, 0);
  // Only its standard streams: nothing the grader inherited (an instructor's script or a
  // CI runner may leave descriptors open) or opened reaches a compile, a link or a judge.
  close_descriptors_from(std::max(3, limits.descriptors));
  for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
  if (!directory.empty() && chdir(directory.c_str()) != 0) {
    dprintf(2, "labkit: cannot enter %s: %s\n", directory.c_str(), strerror(errno));
    _exit(126);
  }
  if (!apply_limits(limits)) _exit(126);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  execvp(args[0], args.data());
  dprintf(2, "labkit: cannot run %s: %s\n", argv[0].c_str(), strerror(errno));
  _exit(127);
}

}  // namespace

void close_descriptors_from(int first) {
#ifdef SYS_close_range
  if (syscall(SYS_close_range, unsigned(first), ~0u, 0) == 0) return;
#endif
  rlimit open_files{};
  const long last = getrlimit(RLIMIT_NOFILE, &open_files) == 0 && open_files.rlim_cur != RLIM_INFINITY
                        ? long(std::min<rlim_t>(open_files.rlim_cur, rlim_t(1) << 20))
                        : 1L << 20;
  for (long fd = first; fd < last; ++fd) close(int(fd));
}

bool apply_limits(const Limits& limits) {
  rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  if (limits.memory_bytes > 0) {
    rlimit memory{limits.memory_bytes, limits.memory_bytes};
    setrlimit(RLIMIT_AS, &memory);
  }
  if (limits.file_bytes > 0) {
    rlimit file{limits.file_bytes, limits.file_bytes};
    setrlimit(RLIMIT_FSIZE, &file);
  }
  if (limits.processes > 0) {
    rlimit processes{rlim_t(limits.processes), rlim_t(limits.processes)};
    setrlimit(RLIMIT_NPROC, &processes);
  }
  if (limits.cpu_seconds > 0) {
    rlimit cpu{rlim_t(limits.cpu_seconds), rlim_t(limits.cpu_seconds) + 1};
    setrlimit(RLIMIT_CPU, &cpu);
  }
  for (const std::string& group : limits.groups) {
    const std::string why = join_group(group);
    if (!why.empty()) {
      dprintf(2, "labkit: %s\n", why.c_str());
      return false;  // its limits were promised: never run without them
    }
  }
  if (limits.uid >= 0) {
    const gid_t gid = gid_t(limits.gid >= 0 ? limits.gid : limits.uid);
    if (setgroups(0, nullptr) != 0 || setresgid(gid, gid, gid) != 0 ||
        setresuid(uid_t(limits.uid), uid_t(limits.uid), uid_t(limits.uid)) != 0) {
      dprintf(2, "labkit: cannot switch to uid %d: %s\n", limits.uid, strerror(errno));
      return false;
    }
  }
  if (limits.no_network) {
    const std::string why = no_network::restrict_self();
    if (!why.empty()) {
      dprintf(2, "labkit: cannot shut the network: %s\n", why.c_str());
      return false;
    }
  }
  return true;
}

namespace {

// A child's time limit: SIGTERM to its group at the deadline (the harness then names the
// case it was running), SIGKILL two seconds later.
struct Deadline {
  pid_t pid;
  Clock::time_point at, kill_at{};
  bool timed_out = false;

  void enforce(Clock::time_point now) {
    if (!timed_out && now >= at) {
      timed_out = true;
      kill(-pid, SIGTERM);
      kill_at = now + std::chrono::seconds(2);
    }
    if (kill_at != Clock::time_point{} && now >= kill_at) kill(-pid, SIGKILL);
  }
  Clock::time_point next() const { return kill_at != Clock::time_point{} ? kill_at : at; }
};

// Reads the child's output until its pipe closes (or, once the child is gone, a second
// more: a process it started outside its group may hold the pipe), within its limits.
// Whether it was reaped meanwhile, with `status`.
bool read_output(pid_t pid, int fd, const Limits& limits, const Observer& observe, Deadline& deadline, Capture& capture,
                 Run& result, int& status) {
  bool open = true, exited = false;
  Clock::time_point drained_at{};
  char buffer[1 << 16];
  while (open) {
    const auto now = Clock::now();
    if (!exited && waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      drained_at = now + std::chrono::seconds(1);
    }
    if (exited && now >= drained_at) break;
    deadline.enforce(now);
    const int wait_ms = int(
        std::max<long long>(10, std::chrono::duration_cast<std::chrono::milliseconds>(deadline.next() - now).count()));
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, std::min(wait_ms, 1000));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n <= 0) {
      open = n < 0 && (errno == EINTR || errno == EAGAIN);
      continue;
    }
    capture.add(buffer, std::size_t(n));
    if (observe) observe(buffer, std::size_t(n));
    if (!result.flooded && capture.total() > limits.flood_bytes) {
      result.flooded = true;
      kill(-pid, SIGKILL);
    }
  }
  return exited;
}

}  // namespace

Run run(const std::vector<std::string>& argv, const Environment& env, const Limits& limits,
        const std::string& directory, const Observer& observe) {
  Run result;
  int pipe_fds[2];
  if (argv.empty() || pipe2(pipe_fds, O_CLOEXEC) != 0) {
    result.started = false;
    return result;
  }
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid < 0) {
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    result.started = false;
    result.output = std::string("fork failed: ") + strerror(errno);
    return result;
  }
  if (pid == 0) {
    close(pipe_fds[0]);
    exec_child(argv, env, limits, directory, pipe_fds[1]);
  }
  close(pipe_fds[1]);

  Capture capture(limits.kept_bytes);
  // At most 1e7 s (four months): a Clock::duration holds that without overflow.
  const auto limit = std::chrono::duration<double>(std::min(limits.seconds, 1e7));
  Deadline deadline{pid, start + std::chrono::duration_cast<Clock::duration>(limit)};
  int status = 0;
  bool exited = read_output(pid, pipe_fds[0], limits, observe, deadline, capture, result, status);
  close(pipe_fds[0]);
  // The pipe closed: the child is gone or closed its output. Wait, still within limits.
  while (!exited) {
    if (waitpid(pid, &status, WNOHANG) == pid) break;
    deadline.enforce(Clock::now());
    usleep(10000);
  }
  kill(-pid, SIGKILL);  // anything it left behind in its group
  result.timed_out = deadline.timed_out;
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  result.output_size = capture.total();
  result.output = capture.text();
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  if (result.exit_code == 127 && result.output.find("labkit: cannot run") != std::string::npos) result.started = false;
  return result;
}

std::string signal_name(int signal) {
  switch (signal) {
    case SIGSEGV: return "segmentation fault (SIGSEGV)";
    case SIGBUS: return "bus error (SIGBUS)";
    case SIGFPE: return "arithmetic exception (SIGFPE)";
    case SIGILL: return "illegal instruction (SIGILL)";
    case SIGABRT: return "aborted (SIGABRT)";
    case SIGKILL: return "killed (SIGKILL)";
    case SIGTERM: return "terminated (SIGTERM)";
    case SIGXCPU: return "CPU time limit (SIGXCPU)";
    default: return std::string("signal ") + std::to_string(signal) + " (" + strsignal(signal) + ")";
  }
}

}  // namespace runner
