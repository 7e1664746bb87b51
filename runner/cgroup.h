// A control group for one graded step (Linux cgroups): its limits hold for the graded
// code's processes together, where an rlimit holds for each process alone (four children
// under RLIMIT_AS each get the whole limit; sixty files under RLIMIT_FSIZE each get the
// whole file size).
//
//   memory   the step's memory, for all its processes, their tmpfs files included; no swap
//   pids     at most 64 processes and threads at once: a fork bomb stops there
//   cpu      at most one core, at normal weight; in a group of its own, a process that
//            calls setsid() no longer gets an autogroup (a fresh share of the machine)
//
// cgroup v2 (one unified hierarchy) or v1 (one hierarchy per controller): either way the
// step's group is made below the group this process was in when it started
// (/proc/self/cgroup), named labkit-PID-N. `labkit-runner confine --cgroup FOLDER` moves the answerer into it before
// it drops root, so everything the answerer starts is in it too. When the step ends,
// every process left in the group is killed and the group removed.
//
// Nothing here is fatal: where a limit cannot be set (not root, no such controller,
// cgroups mounted read-only), missing() says which and why, and grading goes on with the
// per-process limits.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace runner {

struct GroupLimits {
  std::size_t memory_bytes = 0;  // the processes together; 0: no memory limit
  long processes = 64;           // processes and threads at once
};

class StepGroup {
 public:
  explicit StepGroup(const GroupLimits& limits);
  ~StepGroup();  // kills every process left in the group, then removes it
  StepGroup(const StepGroup&) = delete;
  StepGroup& operator=(const StepGroup&) = delete;

  // What `labkit-runner confine --cgroup` joins: one folder per v1 hierarchy, or one v2
  // folder. Empty when no group could be made.
  const std::vector<std::string>& folders() const { return folders_; }
  // True when the memory and process limits asked for both hold for the group.
  bool whole() const { return whole_; }
  // What could not be done and why, in one line; "" when every limit is in force.
  const std::string& missing() const { return missing_; }
  // "v1", "v2", or "" when no group could be made.
  const std::string& version() const { return version_; }

 private:
  std::vector<std::string> folders_;
  bool whole_ = false;
  std::string missing_, version_;
};

// Moves this process into the control group `folder`. "" when done, else why not.
std::string join_group(const std::string& folder);

// What this process and everything it starts may use together: the CPUs it may run on,
// cut to its control groups' CPU quota, and their memory limit. Gradescope's default
// container is half a CPU and 768 MB; a plain machine has its cores and no limit.
struct Envelope {
  double cpus = 1;               // cores' worth of CPU time
  std::size_t memory_bytes = 0;  // 0: no limit below the machine's own memory
  std::string description;       // "2 cores", "0.5 CPU (control group quota), 768 MB"
};
Envelope own_envelope();

}  // namespace runner
