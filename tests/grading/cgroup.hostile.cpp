// A graded answerer that attacks its step's limits, and measures from inside how far it
// got (tests/grading/cgroup.test.sh). One line per attack on stdout:
//   memory N MB   N children each allocate and touch MB, and hold it: how many at once
//   fork N        N children that wait: how many started
//   spin N S      N children, each in a session (an autogroup) of its own, spin for S
//                 seconds: how many cores they got together
//   files N MB    N files of MB each in /tmp: how much was written
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

[[noreturn]] void allocate_and_hold(long mb, int held, int release) {
  char* p = static_cast<char*>(std::malloc(std::size_t(mb) << 20));
  if (!p) _exit(3);  // the address-space limit (RLIMIT_AS) refused it
  std::memset(p, 1, std::size_t(mb) << 20);
  const pid_t self = getpid();
  if (write(held, &self, sizeof self) != sizeof self) _exit(4);
  char c;
  while (read(release, &c, 1) > 0) {}
  _exit(p[12345] == 1 ? 0 : 5);
}

int memory(int n, long mb) {
  int held[2], release[2];
  if (pipe(held) != 0 || pipe(release) != 0) return 1;
  for (int i = 0; i < n; ++i)
    if (fork() == 0) {
      close(held[0]), close(release[1]);
      allocate_and_hold(mb, held[1], release[0]);
    }
  close(held[1]), close(release[0]);
  // Until every child holds its memory or has ended (the OOM killer, or malloc refused),
  // and a moment more: the OOM killer may pick one that held already.
  std::set<pid_t> holding;
  std::map<pid_t, int> ended;
  const auto start = Clock::now();
  auto settled = Clock::time_point::max();
  while (Clock::now() < settled && since(start) < 30) {
    pollfd p{held[0], POLLIN, 0};
    pid_t pid;
    if (poll(&p, 1, 100) > 0 && read(held[0], &pid, sizeof pid) == sizeof pid) holding.insert(pid);
    int status;
    for (pid_t k; (k = waitpid(-1, &status, WNOHANG)) > 0;) ended[k] = status, holding.erase(k);
    if (settled == Clock::time_point::max() && int(holding.size() + ended.size()) == n)
      settled = Clock::now() + std::chrono::milliseconds(500);
  }
  int killed = 0, refused = 0;
  for (const auto& [pid, status] : ended) {
    killed += WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
    refused += WIFEXITED(status) && WEXITSTATUS(status) == 3;
  }
  std::printf("memory: %zu of %d children held %ld MB at once (%d killed, %d refused memory)\n", holding.size(), n, mb,
              killed, refused);
  close(release[1]);
  while (wait(nullptr) > 0) {}
  return 0;
}

int forks(int n) {
  std::vector<pid_t> children;
  int first_error = 0;
  for (int i = 0; i < n; ++i) {
    const pid_t pid = fork();
    if (pid == 0) {
      pause();
      _exit(0);
    }
    if (pid > 0)
      children.push_back(pid);
    else if (!first_error)
      first_error = errno;
  }
  std::printf("fork: %zu of %d children started (%s)\n", children.size(), n,
              first_error ? std::strerror(first_error) : "no failure");
  for (const pid_t pid : children) kill(pid, SIGKILL);
  while (wait(nullptr) > 0) {}
  return 0;
}

int spin(int n, double seconds) {
  const auto start = Clock::now();
  for (int i = 0; i < n; ++i)
    if (fork() == 0) {
      setsid();  // an autogroup of its own, where the kernel has them: a fresh share
      for (volatile unsigned long x = 0; since(start) < seconds; ++x) {}
      _exit(0);
    }
  while (wait(nullptr) > 0) {}
  const double wall = since(start);
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  const double cpu =
      double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
  std::printf("spin: %d children, %.1f s, %.1f s of CPU: %.2f cores\n", n, wall, cpu, cpu / wall);
  return 0;
}

int files(int n, long mb) {
  signal(SIGXFSZ, SIG_IGN);  // a file-size limit shows as a short write
  const std::vector<char> block(1 << 20, 'x');
  long total = 0;
  int written = 0;
  std::string why = "no failure";
  for (; written < n && why == "no failure"; ++written) {
    const int fd = open(("/tmp/fill" + std::to_string(written)).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) why = std::strerror(errno);
    for (long m = 0; fd >= 0 && m < mb && why == "no failure"; ++m) {
      if (write(fd, block.data(), block.size()) == ssize_t(block.size()))
        ++total;
      else
        why = std::strerror(errno);
    }
    if (fd >= 0) close(fd);
  }
  std::printf("files: %ld MB written in /tmp (%s)\n", total, why.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string attack = argc > 1 ? argv[1] : "";
  const int n = argc > 2 ? std::atoi(argv[2]) : 0;
  const double x = argc > 3 ? std::atof(argv[3]) : 0;
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  if (attack == "memory") return memory(n, long(x));
  if (attack == "fork") return forks(n);
  if (attack == "spin") return spin(n, x);
  if (attack == "files") return files(n, long(x));
  std::fprintf(stderr, "usage: cgroup.hostile memory|fork|spin|files N [MB|SECONDS]\n");
  return 2;
}
