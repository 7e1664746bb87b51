// Confinement for the code a submission brings: its compile, its link, and the answerer
// that runs it during each step (common/protocol/answerer.h).
//
// bubblewrap (the default when it works here): each run gets a new mount, pid, network,
// IPC and UTS namespace. It sees the system (/usr, /etc), a private empty /tmp (a tmpfs
// of 256 MB at most, where bubblewrap is 0.5 or later), and only the paths it is given
// read-only (the kit's headers and prebuilt pieces, never solutions/ nor .git, nor the
// kit's build tree as a whole, nor other submissions); its one writable folder is its
// own scratch folder. It cannot reach the network, see or signal other processes, or
// leave anything running behind it.
//
// landlock: where bubblewrap cannot run (a container that forbids namespaces), the run
// takes away its own access to the file system (runner/landlock.h): it reads the system
// and the paths it is given, writes its own folder, and nothing else; no signals outside
// itself where the kernel can refuse them. The same files as under bubblewrap. With no
// network namespace, a seccomp filter (runner/no_network.h) refuses every socket but a
// Unix one: no TCP, no UDP, nothing else.
//
// none: no file confinement. `auto` never falls back to it for a kit that holds
// solutions/ (the graded code could read the reference): it stops and says why. Asked
// for (--sandbox none), or for the Gradescope package (no reference in it), only the
// limits, the uid below and the seccomp filter that refuses sockets protect the machine.
//
// Every mode: a confined run starts with its standard streams (and an answerer with its
// protocol's pipes) and no other descriptor, whatever the grader inherited.
//
// Either way, when the grader runs as root, each confined run also runs under an
// unprivileged uid of its own (one per concurrent run, 61000 and up, leased machine-wide
// so that two graders never share one), which owns its scratch folder and nothing else,
// with a cap on its processes: it can write nowhere else, and a fork bomb starves only
// itself.
//
// A graded step's answerer also runs in a control group of the step's own
// (runner/cgroup.h), where the machine has them: its processes together get the step's
// memory, 64 processes and one core. Where it has none, the memory and file limits hold
// per process only, and the answerer may run only kProcessesWithoutGroup processes.
#pragma once

#include "process.h"

#include <memory>
#include <string>
#include <vector>

namespace runner {

// The cap on a graded answerer's processes (its uid's) where no control group holds
// them together: each may take the step's memory, so the cap bounds their sum.
constexpr long kProcessesWithoutGroup = 8;

// A command ready to run confined. Keep it until the run ends: it holds the run's uid.
struct Confined {
  std::vector<std::string> argv;
  Limits limits;
  std::shared_ptr<void> lease;
};

class Sandbox {
 public:
  enum class Kind { bubblewrap, landlock, none };

  // mode: "auto" (bubblewrap when it works, else landlock, else none where the kit holds
  // no solutions/: otherwise it throws, saying why), "bubblewrap" or "landlock" (throws
  // when it cannot run here), "none". `needed`: folders confined runs must be able to
  // see. `kit`: the kit's root.
  static Sandbox make(const std::string& mode, const std::vector<std::string>& needed, const std::string& kit);

  Kind kind() const { return kind_; }
  // One line for the instructor: what this run is protected by.
  std::string description() const;
  // Whether graded steps get a control group (runner/cgroup.h); description() says
  // which of its limits hold.
  bool step_groups() const { return step_groups_; }

  // `argv` confined to `writable` (made the working folder, and chowned to the run's uid),
  // also seeing `readable` (files or folders), under `limits`.
  Confined confine(const std::vector<std::string>& argv, const std::string& writable,
                   const std::vector<std::string>& readable, Limits limits) const;

  // bubblewrap reports a child killed by signal N as exit status 128 + N: turn it back.
  void interpret(Run& run) const;

 private:
  std::string probe(const std::vector<std::string>& needed) const;
  void probe_step_groups();
  void shut_network(const std::vector<std::string>& needed);
  Kind kind_ = Kind::none;
  bool drop_uid_ = false;
  std::size_t tmp_bytes_ = 0;  // the size of bubblewrap's /tmp; 0: its tmpfs cannot be sized
  std::string why_;            // why bubblewrap is not used
  bool step_groups_ = false;
  std::string groups_;       // what the step groups hold, for description()
  bool no_network_ = false;  // the seccomp filter on every run (runner/no_network.h)
  std::string network_;      // why not, for --sandbox none where it cannot be installed
};

// `labkit-runner confine [LIMITS] [--cgroup FOLDER]... [--descriptors N] [--network none]
// [--read PATH]... [--write PATH] -- PROGRAM [ARGS]`: closes every descriptor but 0 .. N-1
// (3 by default), takes the limits, joins the control groups (runner/cgroup.h) while it
// is still root, takes the uid, shuts the network (runner/no_network.h) when asked, then
// Landlock's restriction when paths are given, then runs PROGRAM: everything PROGRAM
// starts stays in the groups. The judge's process starts a graded answerer through it:
// the runner decides the confinement, the judge only starts the command line it is given.
std::vector<std::string> launcher(const Limits& limits, const std::vector<std::string>& argv,
                                  const std::vector<std::string>& readable = {}, const std::string& writable = "");
int confine_main(int argc, char** argv);

}  // namespace runner
