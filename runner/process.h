// Runs one child process under limits, with its output captured. Whatever the child
// does (crash, loop, allocate without end, flood its output, exit early), the caller
// gets a Run back and goes on.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace runner {

struct Limits {
  double seconds = 120;                 // wall clock; then SIGTERM, and SIGKILL 2 s later
  std::size_t memory_bytes = 0;         // address space (RLIMIT_AS); 0: no limit
  std::size_t kept_bytes = 256 * 1024;  // output kept: the first half and the last half
  std::size_t flood_bytes = 64u << 20;  // output beyond this kills the process
  std::size_t file_bytes = 0;           // largest file it may write (RLIMIT_FSIZE); 0: no limit
  long processes = 0;                   // processes of its uid (RLIMIT_NPROC); 0: no limit
  long cpu_seconds = 0;                 // CPU time (RLIMIT_CPU); 0: no limit
  int uid = -1, gid = -1;               // run under this uid and gid (needs root); -1: as we are
  std::vector<std::string> groups;      // join these control groups first (runner/cgroup.h; needs root)
  // The child keeps descriptors 0 .. descriptors-1 (its standard streams, and a protocol's
  // pipes placed right above them) and nothing else: every descriptor this process
  // inherited or opened is closed before the program starts.
  int descriptors = 3;
  // No network: every socket but a Unix one refused (runner/no_network.h), for a run
  // that has no network namespace of its own.
  bool no_network = false;
};

struct Run {
  int exit_code = -1;  // when it exited normally
  int signal = 0;      // when a signal ended it
  bool timed_out = false;
  bool flooded = false;
  bool started = true;  // false when the program could not be run at all
  std::size_t output_size = 0;
  std::string output;  // stdout and stderr together, head and tail
  double seconds = 0;

  bool ok() const { return started && !timed_out && !flooded && signal == 0 && exit_code == 0; }
};

using Environment = std::vector<std::pair<std::string, std::string>>;

// The child runs in its own session (so its own process group, and no terminal).
// `observe`, when given, sees the output as it arrives (a build's progress line).
using Observer = std::function<void(const char* data, std::size_t size)>;
Run run(const std::vector<std::string>& argv, const Environment& extra_environment = {}, const Limits& limits = {},
        const std::string& directory = "", const Observer& observe = {});

// Applies the limits to this process (no core files; its control groups, while it may
// still join them; then the uid; then the network filter last). False, with the reason
// on stderr, when a group cannot be joined, the uid taken or the network shut.
bool apply_limits(const Limits& limits);

// Closes every descriptor from `first` up, open or not. Safe between fork and exec (no
// allocation): close_range where the kernel has it (Linux 5.9), else one close() each.
void close_descriptors_from(int first);

// "segmentation fault", "aborted", ...
std::string signal_name(int signal);

}  // namespace runner
