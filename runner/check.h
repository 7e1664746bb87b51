// `./labkit check`: the student's command. Builds the labs as they stand, runs every
// step in its own process, prints a table, and for each step that does not pass, its
// first failure with a command that replays exactly that case.
#pragma once

#include "kit.h"
#include "manifest.h"
#include "step.h"

#include <string>
#include <vector>

namespace runner {

struct CheckOptions {
  std::vector<std::string> labs;  // empty: all
  int step = 0;                   // 0: all
  std::string replay;             // a replay token: that one case
  int cases = 0;                  // random cases per query (0: the default)
  std::string seed;
  int jobs = 0;          // parallel steps (0: one per core)
  double timeout = 120;  // seconds per step
  std::string implementation = "student";
  bool debug = false;  // with `replay`: run the code under test under gdb
};

int check(const Paths& paths, const CheckOptions& options);

// Builds the targets, showing its progress on stderr; on failure returns the first
// compiler errors, else "". keep_going: build all that can be built past a failure.
std::string build_targets(const Paths& paths, const std::vector<std::string>& targets, bool* ok,
                          bool keep_going = false);

// Runs the given steps of a lab, `jobs` at a time, in the order given.
std::vector<StepResult> run_steps(const Programs& programs, const Lab& lab, const std::vector<const Step*>& steps,
                                  const StepOptions& options, int jobs);

// The readable input behind a replay token (runs no code under test).
std::string describe_token(const Programs& programs, const Lab& lab, const std::string& token);

}  // namespace runner
