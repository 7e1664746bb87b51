// Confinement for the code a submission brings: its compile, its link, each of its steps.
//
// bubblewrap (the default when it works here): each run gets a new mount, pid, network,
// IPC and UTS namespace. It sees the system (/usr, /etc), a private empty /tmp, and only
// the paths it is given read-only (the kit's headers and prebuilt pieces, never
// solutions/ nor .git, nor the kit's build tree as a whole, nor other submissions); its
// one writable folder is its own scratch folder. It cannot reach the network, see or
// signal other processes, or leave anything running behind it.
//
// none: the fallback where bubblewrap cannot run (some containers). Then only the limits
// and, when the grader runs as root, the unprivileged uid below protect the machine.
//
// Either way, when the grader runs as root, each confined run also runs under an
// unprivileged uid of its own (one per concurrent run, 61000 and up, leased machine-wide so that two graders never share one), which owns its
// scratch folder and nothing else, with a cap on its processes: it can write nowhere
// else, and a fork bomb starves only itself.
#pragma once

#include "process.h"

#include <memory>
#include <string>
#include <vector>

namespace runner {

// A command ready to run confined. Keep it until the run ends: it holds the run's uid.
struct Confined {
  std::vector<std::string> argv;
  Limits limits;
  std::shared_ptr<void> lease;
};

class Sandbox {
 public:
  enum class Kind { bubblewrap, none };

  // mode: "auto" (bubblewrap when it works, else none), "bubblewrap" (throws when it
  // cannot run here), "none". `needed`: folders confined runs must be able to see.
  static Sandbox make(const std::string& mode, const std::vector<std::string>& needed);

  Kind kind() const { return kind_; }
  // One line for the instructor: what this run is protected by.
  std::string description() const;

  // `argv` confined to `writable` (made the working folder, and chowned to the run's uid),
  // also seeing `readable` (files or folders), under `limits`.
  Confined confine(const std::vector<std::string>& argv, const std::string& writable,
                   const std::vector<std::string>& readable, Limits limits) const;

  // bubblewrap reports a child killed by signal N as exit status 128 + N: turn it back.
  void interpret(Run& run) const;

 private:
  Kind kind_ = Kind::none;
  bool drop_uid_ = false;
  std::string why_;  // why bubblewrap is not used
};

}  // namespace runner
