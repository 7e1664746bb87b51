// One step of one lab: the judge's process `test_NN_name "[labNN][stepK]"` (the kit's
// tests, judges and oracle), which runs the code under test in a process of its own,
// the answerer (common/protocol/answerer.h), and writes its JSON report to a scratch
// file. The code under test only answers calls: a crash or a time-out costs the case it
// happened on. The result says what happened, in the runner's words.
#pragma once

#include "manifest.h"
#include "process.h"
#include "sandbox.h"

#include "common/protocol/report.h"

#include <optional>
#include <string>
#include <vector>

namespace runner {

enum class Status {
  passed,
  failing,
  not_implemented,
  crashed,
  timed_out,
  flooded,
  out_of_memory,
  exited_early,  // exit() or _exit() inside a test: the session never finished
  no_tests,      // the binary has no test for this step: a kit bug, never the student's
  kit_error,     // the kit's own judge failed (protocol/report.h's "kit error: ..."): never the student's
  not_built,     // the lab did not compile
  out_of_time,   // graded runs: the submission's time budget ran out before or during the step
};

std::string status_word(Status s);

// The judge's report, as common/protocol/report.h defines it.
using Failure = labkit::report::Failure;
using QueryResult = labkit::report::Query;
using TestCaseResult = labkit::report::TestCase;

struct StepResult {
  Status status = Status::not_built;
  const Step* step = nullptr;
  std::vector<QueryResult> queries;
  std::vector<TestCaseResult> test_cases;
  std::string detail;    // why it crashed, timed out, ...
  std::string inflight;  // the replay token of the case a crash or time-out died on
  Run run;
  bool finished = false;  // the harness's report says the test session returned
  int examples = 0, random_cases = 0, ambiguous = 0;
  int cases_per_query = 0;  // the run's random cases per query (protocol/report.h)
  // For partial credit (step.cpp, fraction_passed): the share of the step's points its
  // cases earn; 1 when the step passes, 0 when it did not run to its end.
  double fraction_passed = 0;
};

// True for the ways a step can end without a verdict on its cases.
bool abnormal(Status s);

struct StepOptions {
  std::string seed;    // "" = the harness's public default
  int cases = 0;       // 0 = the harness's default
  std::string replay;  // one case only
  bool hide_seed = false;
  bool count_all = false;            // judge every random case (partial credit), LABKIT_COUNT_ALL
  bool describe_only = false;        // with `replay`: describe the input, run no code under test
  Limits limits;                     // the judge's process; its answerer gets the same memory and file limits (graded:
                                     // for its processes together too, in a control group, runner/cgroup.h)
  double call_seconds = 0;           // the time limit of one call of the code under test (0: the harness's 5 s)
  bool debugger = false;             // the answerer runs under gdb, which prints where it crashed
  const Sandbox* sandbox = nullptr;  // graded runs: the answerer runs confined to a scratch folder of its own
  std::string scratch_parent = "/tmp";  // where each step's scratch folder is made
  std::string record_examples;          // the kit's scoring test: where the judge hashes the examples' requests
};

// The two programs of a step (see Lab::judge_binary).
struct Programs {
  std::string judge;     // the kit's test program
  std::string answerer;  // the program that runs the code under test
};

StepResult run_step(const Programs& programs, const Lab& lab, const Step& step, const StepOptions& options);

}  // namespace runner
