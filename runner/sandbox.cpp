#include "sandbox.h"
#include "cgroup.h"
#include "landlock.h"
#include "no_network.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <bitset>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace runner {

namespace fs = std::filesystem;

namespace {

constexpr int kFirstUid = 61000;
constexpr int kUids = 1024;
constexpr long kProcesses = 256;  // per confined run (its own uid)
// The private /tmp under bubblewrap is RAM (a tmpfs): files there are bounded in all, not
// only one by one (RLIMIT_FSIZE).
constexpr std::size_t kTmpBytes = std::size_t(256) << 20;

std::mutex uid_mutex;
std::bitset<kUids> uids_in_use;

// Ends every process left under `uid` (a daemon that escaped its process group): a
// process of that uid signals all the others with kill(-1).
void kill_all_of(int uid) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (setresgid(uid, uid, uid) == 0 && setresuid(uid, uid, uid) == 0) kill(-1, SIGKILL);
    _exit(0);
  }
  if (pid > 0) waitpid(pid, nullptr, 0);
}

// A uid is leased machine-wide, not only in this process: two graders at once (a class
// and a resubmission) must never share one, or the end of one run's lease would kill
// the other's processes and each could write the other's scratch folder. The lease is
// an flock on /run/lock/labkit-uids/UID (or under /tmp), which the kernel drops when
// this process dies, however it dies.
int lock_uid_file(int uid) {
  static const std::string folder = [] {
    for (const char* parent : {"/run/lock", "/tmp"}) {
      std::error_code e;
      const fs::path f = fs::path(parent) / "labkit-uids";
      fs::create_directories(f, e);
      if (!e && access(f.c_str(), W_OK) == 0) {
        chmod(f.c_str(), 0755);
        return f.string();
      }
    }
    throw std::runtime_error("cannot make a folder for uid leases in /run/lock or /tmp");
  }();
  const std::string path = folder + "/" + std::to_string(uid);
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) return -1;
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

std::shared_ptr<void> lease_uid(int* uid) {
  std::lock_guard<std::mutex> lock(uid_mutex);
  for (int i = 0; i < kUids; ++i) {
    if (uids_in_use[i]) continue;
    const int fd = lock_uid_file(kFirstUid + i);
    if (fd < 0) continue;  // another grader holds it
    uids_in_use[i] = true;
    *uid = kFirstUid + i;
    kill_all_of(*uid);  // whatever a crashed grader left running under it
    return std::shared_ptr<void>(nullptr, [i, fd](void*) {
      kill_all_of(kFirstUid + i);
      std::lock_guard<std::mutex> lock(uid_mutex);
      uids_in_use[i] = false;
      close(fd);  // the lease ends after its processes do
    });
  }
  throw std::runtime_error("no free uid among " + std::to_string(kUids) + " for a confined run");
}

void chown_all(const fs::path& root, int uid) {
  std::error_code ignored;
  if (chown(root.c_str(), uid, uid) != 0) return;
  for (auto it = fs::recursive_directory_iterator(root, ignored); it != fs::recursive_directory_iterator();
       it.increment(ignored))
    if (lchown(it->path().c_str(), uid, uid) != 0) continue;
}

// The system a compiler and an answer program need, read-only: /usr and /etc, and the
// top-level links or folders of a merged-/usr layout.
void add_system(std::vector<std::string>& args) {
  for (const char* path : {"/usr", "/etc", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
    std::error_code e;
    const fs::file_status s = fs::symlink_status(path, e);
    if (e || !fs::exists(s)) continue;
    if (fs::is_symlink(s))
      args.insert(args.end(), {"--symlink", fs::read_symlink(path).string(), path});
    else
      args.insert(args.end(), {"--ro-bind", path, path});
  }
}

// bubblewrap 0.5 and later can bound a tmpfs (--size); older ones refuse the option.
bool bubblewrap_sizes_tmpfs() {
  Limits limits;
  limits.seconds = 10;
  return run({"bwrap", "--help"}, {}, limits).output.find("--size") != std::string::npos;
}

// `tmp_bytes`: the size of its /tmp, 0 for the tmpfs default (half the RAM).
std::vector<std::string> bubblewrap(const std::vector<std::string>& argv, const std::string& writable,
                                    const std::vector<std::string>& readable, std::size_t tmp_bytes) {
  std::vector<std::string> args = {"bwrap", "--unshare-all", "--die-with-parent"};
  add_system(args);
  args.insert(args.end(), {"--dev", "/dev", "--proc", "/proc"});
  if (tmp_bytes > 0) args.insert(args.end(), {"--size", std::to_string(tmp_bytes)});
  args.insert(args.end(), {"--tmpfs", "/tmp"});
  for (const std::string& path : readable)
    if (fs::exists(path) && path.rfind("/usr/", 0) != 0) args.insert(args.end(), {"--ro-bind", path, path});
  if (!writable.empty()) args.insert(args.end(), {"--bind", writable, writable, "--chdir", writable});
  args.insert(args.end(),
              {"--setenv", "HOME", writable.empty() ? "/tmp" : writable, "--setenv", "TMPDIR", "/tmp", "--"});
  args.insert(args.end(), argv.begin(), argv.end());
  return args;
}

}  // namespace

namespace {

// The first folder on the way to one of `paths` (or the path itself) that a user who is
// neither its owner nor in its group cannot pass through or read; "" when there is none.
std::string closed_to_others(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    std::error_code e;
    fs::path p = fs::absolute(path, e);
    if (e || !fs::exists(p, e)) continue;
    for (fs::path at = p;; at = at.parent_path()) {
      struct stat st {};
      if (stat(at.c_str(), &st) == 0) {
        const bool folder = S_ISDIR(st.st_mode);
        const bool open = (!folder || (st.st_mode & S_IXOTH)) && (at != p || (st.st_mode & S_IROTH));
        if (!open) return at.string();
      }
      if (at == at.root_path() || at.parent_path() == at) break;
    }
  }
  return "";
}

}  // namespace

namespace {

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.substr(0, 300);
}

std::string self_path() {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  return n > 0 ? std::string(self, std::size_t(n)) : std::string("labkit-runner");
}

}  // namespace

// Runs a tiny confined command; "" when it wrote its file, else why not.
std::string Sandbox::probe(const std::vector<std::string>& needed) const {
  Limits limits;
  limits.seconds = 20;
  const fs::path folder = fs::temp_directory_path() / ("labkit-probe." + std::to_string(getpid()));
  fs::create_directories(folder);
  const Confined c = confine({"/bin/sh", "-c", "echo probe > written"}, folder.string(), needed, limits);
  const Run r = run(c.argv, {}, c.limits, folder.string());
  const bool works = r.ok() && fs::exists(folder / "written");
  fs::remove_all(folder);
  if (works) return "";
  if (kind_ == Kind::bubblewrap) {
    // The same without the kit's folders: tells a machine that forbids namespaces from
    // folders the graded uid cannot read.
    Sandbox bare = *this;
    const Confined plain = bare.confine({"bwrap", "--unshare-all", "--ro-bind", "/", "/", "true"}, "", {}, limits);
    const Run r2 = run(plain.argv, {}, plain.limits);
    if (!r2.ok())
      return "bubblewrap cannot make its namespaces here" + std::string(drop_uid_ ? " (as an unprivileged uid)" : "") +
             ": " + trimmed(r2.output.empty() ? "it failed" : r2.output);
    return "bubblewrap runs, but not with the kit's folders: " + trimmed(r.output) +
           (drop_uid_ ? " (are they readable by other users?)" : "");
  }
  return trimmed(r.output.empty() ? "the probe did not run" : r.output);
}

// With no sandbox, no namespace takes the network away: the seccomp filter does, where
// the kernel lets it (else the description says the network is open, and why).
void Sandbox::shut_network(const std::vector<std::string>& needed) {
  no_network_ = true;
  if (const std::string why = probe(needed); !why.empty()) {
    no_network_ = false;
    network_ = "; the network is open (" + why + ")";
  }
}

// Makes one group as a graded step does: whether steps get one here, and what it holds.
void Sandbox::probe_step_groups() {
  const StepGroup probe({std::size_t(64) << 20});
  step_groups_ = !probe.folders().empty();
  const std::string cap =
      drop_uid_ ? ", and the graded code may run " + std::to_string(kProcessesWithoutGroup) + " processes at once" : "";
  if (probe.whole())
    groups_ = "; per step, the graded code's processes together get the step's memory, " +
              std::to_string(GroupLimits{}.processes) + " processes and one core (cgroup " + probe.version() +
              (probe.missing().empty() ? ")" : "; but " + probe.missing() + ")");
  else if (step_groups_)
    groups_ = "; per-step cgroup limits in part only (cgroup " + probe.version() + "; " + probe.missing() + ")" + cap;
  else
    groups_ = "; no per-step cgroup limits (" + probe.missing() + "): memory and file limits hold per process" + cap;
}

Sandbox Sandbox::make(const std::string& mode, const std::vector<std::string>& needed, const std::string& kit) {
  Sandbox s;
  s.drop_uid_ = geteuid() == 0;
  s.probe_step_groups();
  // Run as root, the graded code runs under an unprivileged uid of its own: it must be
  // able to read the kit, or every lab would fail to build for a reason not the student's.
  if (const std::string closed = s.drop_uid_ ? closed_to_others(needed) : ""; !closed.empty())
    throw std::runtime_error("the graded code runs under an unprivileged uid, and " + closed +
                             " is closed to other users, so it could not read the kit. Make the kit's folder and "
                             "its parents readable (chmod o+rx " +
                             closed + ") or move the kit, then grade again");
  if (mode == "none") {
    s.why_ = "turned off (--sandbox none)";
    s.shut_network(needed);
    return s;
  }
  if (mode == "auto" || mode == "bubblewrap") {
    s.kind_ = Kind::bubblewrap;
    s.tmp_bytes_ = bubblewrap_sizes_tmpfs() ? kTmpBytes : 0;
    const std::string why = s.probe(needed);
    if (why.empty()) return s;
    s.why_ = "cannot run here: " + why;
    if (mode == "bubblewrap")
      throw std::runtime_error(why + " (install bubblewrap, or use --sandbox landlock or none)");
  }
  s.kind_ = Kind::landlock;
  s.no_network_ = true;  // no namespace of its own: the seccomp filter (runner/no_network.h)
  if (mode == "landlock") s.why_ = "not asked for: --sandbox landlock";
  const std::string why = landlock::version() == 0 ? "this kernel has no Landlock" : s.probe(needed);
  if (why.empty()) return s;
  s.kind_ = Kind::none;
  s.no_network_ = false;
  s.why_ += std::string(s.why_.empty() ? "" : "; ") + "Landlock: " + why;
  if (mode == "landlock") throw std::runtime_error("Landlock cannot confine the graded code here: " + why);
  if (fs::exists(fs::path(kit) / "solutions"))
    throw std::runtime_error("nothing can confine the graded code's files here (" + s.why_ +
                             "), and this kit holds solutions/: the graded code could read the reference. Grade with "
                             "the Gradescope package, which holds no reference (./labkit package gradescope; unzip it; "
                             "setup.sh, then run_autograder), or pass --sandbox none if you trust every submission");
  s.shut_network(needed);
  return s;
}

std::string Sandbox::description() const {
  const std::string also = (drop_uid_ ? ", each run under its own unprivileged uid" : "") + groups_;
  if (kind_ == Kind::bubblewrap)
    return "bubblewrap: no network, read-only system, only its own scratch folder writable, " +
           (tmp_bytes_ ? "a " + std::to_string(tmp_bytes_ >> 20) + " MB /tmp"
                       : "an unbounded /tmp (bubblewrap before 0.5)") +
           also;
  if (kind_ == Kind::landlock)
    return "Landlock (bubblewrap " + why_ +
           "): reads only the system and its own files, writes only its own scratch folder, no network (no "
           "socket but a Unix one)" +
           also;
  return "none (" + why_ + "): time, memory, output and file-size limits only" +
         (no_network_ ? ", and no network (no socket but a Unix one)" : network_) + also;
}

void Sandbox::interpret(Run& run) const {
  if (kind_ == Kind::bubblewrap && run.signal == 0 && run.exit_code > 128 && run.exit_code < 128 + 65) {
    run.signal = run.exit_code - 128;
    run.exit_code = -1;
  }
}

Confined Sandbox::confine(const std::vector<std::string>& argv, const std::string& writable,
                          const std::vector<std::string>& readable, Limits limits) const {
  Confined c;
  if (drop_uid_) {
    int uid = -1;
    c.lease = lease_uid(&uid);
    limits.uid = limits.gid = uid;
    limits.processes = kProcesses;
    if (!writable.empty()) chown_all(writable, uid);
  }
  // bubblewrap's own network namespace has nothing in it (and bubblewrap needs a netlink
  // socket to set it up); elsewhere the seccomp filter refuses sockets.
  limits.no_network = no_network_;
  c.limits = limits;
  Limits inner;
  inner.descriptors = limits.descriptors;  // a protocol's pipes, when the run has them
  switch (kind_) {
    case Kind::bubblewrap: c.argv = bubblewrap(argv, writable, readable, tmp_bytes_); break;
    case Kind::landlock: c.argv = launcher(inner, argv, readable, writable); break;
    case Kind::none: c.argv = argv; break;
  }
  return c;
}

std::vector<std::string> launcher(const Limits& limits, const std::vector<std::string>& argv,
                                  const std::vector<std::string>& readable, const std::string& writable) {
  std::vector<std::string> out = {self_path(), "confine"};
  const auto add = [&](const char* name, long long value) {
    if (value > 0) out.insert(out.end(), {name, std::to_string(value)});
  };
  add("--memory", (long long)limits.memory_bytes);
  add("--file-size", (long long)limits.file_bytes);
  add("--processes", limits.processes);
  add("--cpu", limits.cpu_seconds);
  if (limits.uid >= 0)
    out.insert(out.end(), {"--uid", std::to_string(limits.uid), "--gid", std::to_string(limits.gid)});
  if (limits.descriptors > 3) add("--descriptors", limits.descriptors);
  if (limits.no_network) out.insert(out.end(), {"--network", "none"});
  for (const std::string& group : limits.groups) out.insert(out.end(), {"--cgroup", group});
  for (const std::string& path : readable) out.insert(out.end(), {"--read", path});
  if (!writable.empty()) out.insert(out.end(), {"--write", writable});
  out.push_back("--");
  out.insert(out.end(), argv.begin(), argv.end());
  return out;
}

int confine_main(int argc, char** argv) {
  Limits limits;
  std::vector<std::string> readable;
  std::string writable;
  bool restrict_files = false;
  int at = 2;  // after "labkit-runner confine"
  for (; at + 1 < argc && std::string(argv[at]) != "--"; at += 2) {
    const std::string name = argv[at], value = argv[at + 1];
    const long long number = std::atoll(value.c_str());
    if (name == "--memory")
      limits.memory_bytes = std::size_t(number);
    else if (name == "--file-size")
      limits.file_bytes = std::size_t(number);
    else if (name == "--processes")
      limits.processes = long(number);
    else if (name == "--cpu")
      limits.cpu_seconds = long(number);
    else if (name == "--uid")
      limits.uid = int(number);
    else if (name == "--gid")
      limits.gid = int(number);
    else if (name == "--cgroup")
      limits.groups.push_back(value);
    else if (name == "--descriptors")
      limits.descriptors = int(number);
    else if (name == "--network" && value == "none")
      limits.no_network = true;
    else if (name == "--read")
      readable.push_back(value), restrict_files = true;
    else if (name == "--write")
      writable = value, restrict_files = true;
    else {
      std::fprintf(stderr, "labkit-runner confine: unknown option %s\n", name.c_str());
      return 126;
    }
  }
  if (at + 1 >= argc || std::string(argv[at]) != "--") {
    std::fprintf(stderr,
                 "usage: labkit-runner confine [--memory B] [--file-size B] [--processes N] [--cpu S] "
                 "[--uid U --gid G] [--cgroup FOLDER]... [--descriptors N] [--network none] [--read PATH]... "
                 "[--write PATH] -- PROGRAM [ARGS]\n");
    return 126;
  }
  // PROGRAM gets descriptors 0 .. N-1 (its standard streams and, for an answerer, its
  // protocol's pipes) and nothing else the judge's process or its parents left open.
  close_descriptors_from(std::max(3, limits.descriptors));
  if (!apply_limits(limits)) return 126;
  if (restrict_files) {
    if (!writable.empty()) {
      setenv("TMPDIR", writable.c_str(), 1);  // the compiler's temporary files: never /tmp
      setenv("HOME", writable.c_str(), 1);
    }
    const std::string why = landlock::restrict_self(
        readable, writable.empty() ? std::vector<std::string>{} : std::vector<std::string>{writable});
    if (!why.empty()) {
      std::fprintf(stderr, "labkit-runner confine: %s\n", why.c_str());
      return 126;
    }
  }
  // Taking a uid clears the parent-death signal: set it again, so that the code under
  // test ends when the judge's process does, however that ends.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  execvp(argv[at + 1], argv + at + 1);
  std::fprintf(stderr, "labkit-runner confine: cannot run %s: %s\n", argv[at + 1], std::strerror(errno));
  return 127;
}

}  // namespace runner
