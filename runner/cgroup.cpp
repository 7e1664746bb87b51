#include "cgroup.h"
#include "common/text.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

namespace runner {

namespace fs = std::filesystem;

namespace {

const char* const kControllers[] = {"memory", "pids", "cpu"};

// Where one controller's step groups go: below this process's own group, in the
// hierarchy that has the controller.
struct Place {
  std::string controller;
  int version = 0;      // 1 or 2
  std::string parent;   // the folder of this process's own group; "" when unusable
  std::string why_not;  // then, why
};

struct Mount {
  std::string root, point, type, options;  // options: the super block's (v1: its controllers)
  bool read_only = false;
};

// The reason behind an errno, in words an instructor can act on.
std::string because(int error) {
  if ((error == EACCES || error == EPERM) && geteuid() != 0) return "not root";
  if (error == EROFS) return "mounted read-only";
  return std::strerror(error);
}

// 0 when `text` went into the control file, else the errno.
int write_control(const std::string& file, const std::string& text) {
  const int fd = open(file.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const ssize_t n = write(fd, text.data(), text.size());
  const int error = n < 0 ? errno : EIO;
  close(fd);
  return n == ssize_t(text.size()) ? 0 : error;
}

// `word` among the words of `text` (separated by spaces, commas or new lines).
bool has_word(const std::string& text, const std::string& word) {
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  std::istringstream words(spaced);
  for (std::string w; words >> w;)
    if (w == word) return true;
  return false;
}

// The cgroup file systems mounted here (/proc/self/mountinfo: "ID PARENT DEVICE ROOT
// POINT OPTIONS [TAGS...] - TYPE SOURCE SUPER_OPTIONS").
std::vector<Mount> cgroup_mounts() {
  std::vector<Mount> mounts;
  std::ifstream in("/proc/self/mountinfo");
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string skip, options;
    Mount m;
    words >> skip >> skip >> skip >> m.root >> m.point >> options;
    while (words >> skip && skip != "-") {}
    words >> m.type >> skip >> m.options;
    m.read_only = has_word(options, "ro");
    if (m.type == "cgroup" || m.type == "cgroup2") mounts.push_back(m);
  }
  return mounts;
}

// This process's group in each hierarchy, by controller, "" standing for v2: from
// /proc/self/cgroup, "4:memory:/a/b" (v1, with its controllers) or "0::/a/b" (v2).
std::map<std::string, std::string> own_groups() {
  std::map<std::string, std::string> groups;
  std::ifstream in("/proc/self/cgroup");
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;  // not the kernel's format
    const std::string controllers = line.substr(first + 1, second - first - 1), path = line.substr(second + 1);
    if (controllers.empty()) groups[""] = path;
    std::istringstream names(controllers);
    for (std::string name; std::getline(names, name, ',');) groups[name] = path;
  }
  return groups;
}

// The folder of `group` (a path from its hierarchy's root) where `m` is mounted; "" when
// the mount shows only a part of the hierarchy that does not hold it.
std::string folder_of(const Mount& m, const std::string& group) {
  if (m.root == "/") return m.point + (group == "/" ? "" : group);
  if (group == m.root) return m.point;
  if (group.rfind(m.root + "/", 0) == 0) return m.point + group.substr(m.root.size());
  return "";
}

// A v1 hierarchy of its own when the controller has one; else the v2 hierarchy, when it
// offers the controller to this process's group.
Place find_place(const std::string& controller, const std::vector<Mount>& mounts,
                 const std::map<std::string, std::string>& groups) {
  Place p;
  p.controller = controller;
  const Mount* mount = nullptr;
  for (const Mount& m : mounts)
    if (m.type == "cgroup" && has_word(m.options, controller)) mount = &m;
  for (const Mount& m : mounts)
    if (!mount && m.type == "cgroup2") mount = &m;
  if (!mount) {
    p.why_not = "the " + controller + " controller is not mounted";
    return p;
  }
  p.version = mount->type == "cgroup" ? 1 : 2;
  const auto group = groups.find(p.version == 1 ? controller : "");
  const std::string folder = group == groups.end() ? "" : folder_of(*mount, group->second);
  if (folder.empty()) {
    // A container that mounts only a part of the hierarchy, without this process's group.
    p.why_not = "this process's group is not under " + mount->point;
  } else if (mount->read_only) {
    p.why_not = mount->point + " is mounted read-only";
  } else if (p.version == 2 && !has_word(labkit::read_file(folder + "/cgroup.controllers"), controller)) {
    // The group above this one keeps the controller to itself.
    p.why_not = "the " + controller + " controller is missing in " + folder;
  } else {
    p.parent = folder;
  }
  return p;
}

// v2 gives a controller to a group's children through the group's cgroup.subtree_control,
// and only while the group itself holds no process. When the grader is alone in its
// group, it moves into a leaf of its own (labkit-PID-grader) to empty it. "" when done.
std::string hand_down(const std::string& parent, const std::string& controller) {
  if (has_word(labkit::read_file(parent + "/cgroup.subtree_control"), controller)) return "";
  const std::string enable = "+" + controller, self = std::to_string(getpid());
  int error = write_control(parent + "/cgroup.subtree_control", enable);
  if (error == EBUSY && labkit::read_file(parent + "/cgroup.procs") == self + "\n") {
    const std::string leaf = parent + "/labkit-" + self + "-grader";
    if (mkdir(leaf.c_str(), 0755) == 0 || errno == EEXIST) error = write_control(leaf + "/cgroup.procs", self);
    if (error == 0) error = write_control(parent + "/cgroup.subtree_control", enable);
  }
  // Other processes share the grader's group: moving them is not the grader's to do.
  if (error == EBUSY)
    return parent +
           " holds other processes than the grader, so it cannot hand controllers to groups below it "
           "(run the grader alone in a group: systemd-run --scope -p Delegate=yes ./labkit grade ...)";
  return error ? "cannot enable it in " + parent + "/cgroup.subtree_control: " + because(error) : "";
}

// The pids a group's cgroup.procs lists.
std::vector<pid_t> members(const std::string& folder) {
  std::vector<pid_t> pids;
  std::ifstream in(folder + "/cgroup.procs");
  for (pid_t pid; in >> pid;) pids.push_back(pid);
  return pids;
}

// SIGKILL to each process the group lists, through a pidfd opened before the list is
// read again: a pid still listed then is the pidfd's own process, never one that took
// over the pid of a process gone meanwhile. (By syscall: glibc 2.36's <sys/pidfd.h> does
// not link from C++.)
void kill_members(const std::string& folder) {
  std::vector<std::pair<pid_t, int>> opened;
  for (const pid_t pid : members(folder)) {
    const int fd = int(syscall(SYS_pidfd_open, pid, 0));
    if (fd >= 0) opened.push_back({pid, fd});
    // Linux before 5.3 has no pidfd: the pid is as fresh as the list.
    if (fd < 0 && errno == ENOSYS) kill(pid, SIGKILL);
  }
  const std::vector<pid_t> still = members(folder);
  for (const auto& [pid, fd] : opened) {
    if (std::find(still.begin(), still.end(), pid) != still.end())
      syscall(SYS_pidfd_send_signal, fd, SIGKILL, nullptr, 0);
    close(fd);
  }
}

// Kills everything in the group and removes it: v2's cgroup.kill at once where the kernel
// has it (Linux 5.14), then SIGKILL to whatever is listed until the group is empty (its
// pids.max bounds what a fork bomb adds meanwhile). Gives up after 10 s: the group stays
// until the next grader finds it left over.
void end_group(const std::string& folder) {
  write_control(folder + "/cgroup.kill", "1");  // v1 and older kernels have no such file
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (rmdir(folder.c_str()) != 0 && errno == EBUSY && std::chrono::steady_clock::now() < until) {
    kill_members(folder);
    usleep(10000);
  }
}

// Groups a grader that died left behind (labkit-PID-..., that PID gone), with whatever
// still runs in them.
void remove_leftovers(const std::string& parent) {
  std::error_code e;
  for (const auto& entry : fs::directory_iterator(parent, e)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("labkit-", 0) != 0 || !entry.is_directory(e)) continue;  // not a step's group
    const pid_t grader = pid_t(std::atol(name.c_str() + 7));
    if (grader <= 0 || kill(grader, 0) == 0 || errno == EPERM) continue;  // its grader still runs
    end_group(entry.path().string());
  }
}

// The way a step's group limits `controller`: the files to write, in order.
struct Setting {
  std::string file, value;
  const char* if_absent;  // what it means when the kernel has no such file; null: it must
};

std::vector<Setting> settings(const Place& p, const GroupLimits& limits) {
  const std::string memory = std::to_string(limits.memory_bytes);
  if (p.controller == "memory" && limits.memory_bytes == 0) return {};
  // Memory and swap together, so that swapping is no way around the limit (v1: set after
  // the memory limit, which it may not be below).
  if (p.controller == "memory" && p.version == 1)
    return {{"memory.limit_in_bytes", memory, nullptr},
            {"memory.memsw.limit_in_bytes", memory, "swap not limited (swap accounting is off)"}};
  if (p.controller == "memory")
    return {{"memory.max", memory, nullptr}, {"memory.swap.max", "0", "swap not limited (no memory.swap.max)"}};
  if (p.controller == "pids") return {{"pids.max", std::to_string(limits.processes), nullptr}};
  // One core: 100 ms of CPU time in every 100 ms, at the default weight.
  if (p.version == 1)
    return {{"cpu.cfs_period_us", "100000", nullptr},
            {"cpu.cfs_quota_us", "100000", nullptr},
            {"cpu.shares", "1024", nullptr}};
  return {{"cpu.max", "100000 100000", nullptr}, {"cpu.weight", "100", nullptr}};
}

// Where each controller's step groups go, found once per process. The first time also
// hands v2's controllers down and removes what dead graders left.
const std::vector<Place>& places() {
  static const std::vector<Place> found = [] {
    const std::vector<Mount> mounts = cgroup_mounts();
    const std::map<std::string, std::string> groups = own_groups();
    std::vector<Place> list;
    std::set<std::string> cleaned;
    for (const char* controller : kControllers) {
      Place p = find_place(controller, mounts, groups);
      if (p.version == 2 && !p.parent.empty()) p.why_not = hand_down(p.parent, controller);
      if (!p.why_not.empty()) p.parent.clear();
      if (!p.parent.empty() && cleaned.insert(p.parent).second) remove_leftovers(p.parent);
      list.push_back(p);
    }
    return list;
  }();
  return found;
}

// Makes the group's folder in `p`'s hierarchy (v2's one folder serves every controller)
// and writes its limits. True when they hold; otherwise `missing` says why not.
bool set_up(const Place& p, const std::string& name, const GroupLimits& limits, std::vector<std::string>& folders,
            std::vector<std::string>& missing) {
  const auto lacks = [&](const std::string& why) {
    missing.push_back("no " + p.controller + " limit: " + why);
    return false;
  };
  if (p.parent.empty()) return lacks(p.why_not);
  const std::string folder = p.parent + "/" + name;
  if (std::find(folders.begin(), folders.end(), folder) == folders.end()) {
    if (mkdir(folder.c_str(), 0755) != 0) return lacks("cannot make " + folder + ": " + because(errno));
    folders.push_back(folder);
  }
  for (const Setting& s : settings(p, limits)) {
    const int error = write_control(folder + "/" + s.file, s.value);
    if (error == ENOENT && s.if_absent)
      missing.push_back(s.if_absent);  // the limit holds without it
    else if (error)
      return lacks("cannot write " + s.file + ": " + because(error));
  }
  return true;
}

}  // namespace

StepGroup::StepGroup(const GroupLimits& limits) {
  static std::atomic<int> made{0};
  const std::string name = "labkit-" + std::to_string(getpid()) + "-" + std::to_string(made++);
  std::vector<std::string> missing;
  std::set<int> versions;
  whole_ = true;
  for (const Place& p : places()) {
    const bool holds = set_up(p, name, limits, folders_, missing);
    if (holds) versions.insert(p.version);
    // Memory and processes are what per-process limits cannot bound together; CPU time
    // has RLIMIT_CPU and the step's time limit.
    if (!holds && p.controller != "cpu") whole_ = false;
  }
  for (const int v : versions) version_ += (version_.empty() ? "v" : " and v") + std::to_string(v);
  for (const std::string& m : missing) missing_ += (missing_.empty() ? "" : "; ") + m;
}

StepGroup::~StepGroup() {
  for (const std::string& folder : folders_) end_group(folder);
}

Envelope own_envelope() {
  Envelope e;
  cpu_set_t set;
  CPU_ZERO(&set);
  const int cores = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
  e.cpus = cores > 0 ? cores : std::max(1u, std::thread::hardware_concurrency());
  const double machine_bytes = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
  double quota_cpus = 0, memory = 0;
  const auto number = [](const std::string& text) {  // "max" and "-1" are no limit: 0
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    return end == text.c_str() || x <= 0 ? 0.0 : x;
  };
  const auto tighter = [](double& limit, double x) {
    if (x > 0 && (limit == 0 || x < limit)) limit = x;
  };
  const std::vector<Mount> mounts = cgroup_mounts();
  const std::map<std::string, std::string> groups = own_groups();
  for (const char* controller : {"cpu", "memory"}) {
    const Mount* mount = nullptr;
    for (const Mount& m : mounts)
      if (m.type == "cgroup" && has_word(m.options, controller)) mount = &m;
    for (const Mount& m : mounts)
      if (!mount && m.type == "cgroup2") mount = &m;
    if (!mount) continue;
    const bool v1 = mount->type == "cgroup";
    const auto group = groups.find(v1 ? controller : "");
    if (group == groups.end()) continue;
    // A limit anywhere above holds too: from this process's group up to the mount's root.
    for (fs::path folder = folder_of(*mount, group->second); !folder.empty(); folder = folder.parent_path()) {
      const std::string f = folder.string();
      if (std::string(controller) == "cpu") {
        std::istringstream max(labkit::read_file(f + (v1 ? "/cpu.cfs_quota_us" : "/cpu.max")));
        std::string quota, period = v1 ? labkit::read_file(f + "/cpu.cfs_period_us") : "";
        max >> quota;
        if (!v1) max >> period;
        if (number(quota) > 0 && number(period) > 0) tighter(quota_cpus, number(quota) / number(period));
      } else {
        tighter(memory, number(labkit::read_file(f + (v1 ? "/memory.limit_in_bytes" : "/memory.max"))));
      }
      if (f == mount->point || f.size() <= mount->point.size()) break;
    }
  }
  std::ostringstream text;
  if (quota_cpus > 0 && quota_cpus < e.cpus) {
    e.cpus = quota_cpus;
    text << quota_cpus << " CPU (control group quota)";
  } else {
    text << e.cpus << (e.cpus == 1 ? " core" : " cores");
  }
  if (memory > 0 && memory < machine_bytes) {
    e.memory_bytes = std::size_t(memory);
    text << ", " << (e.memory_bytes >> 20) << " MB (control group limit)";
  }
  e.description = text.str();
  return e;
}

std::string join_group(const std::string& folder) {
  const int error = write_control(folder + "/cgroup.procs", std::to_string(getpid()));
  return error ? "cannot join the control group " + folder + ": " + because(error) : "";
}

}  // namespace runner
