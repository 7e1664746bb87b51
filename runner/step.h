// One step of one lab, run in its own process: `test_NN_name_X "[labNN][stepK]"`, with
// the harness writing its JSON report to a scratch file. The result says what happened,
// in the runner's words, whatever the code under test did.
#pragma once

#include "manifest.h"
#include "process.h"

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
  no_tests,   // the binary has no test for this step: a kit bug, never the student's
  not_built,  // the lab did not compile
};

std::string status_word(Status s);

struct Failure {
  std::string title, input, expected, got, why, replay;
  int shrinks = 0;
};

struct QueryResult {
  std::string test_case, query, kind;
  int cases = 0, passed = 0, ambiguous = 0, failed = 0;
  std::string not_implemented, error;
  std::optional<Failure> failure;
};

struct TestCaseResult {
  std::string name;
  bool passed = false;
  std::vector<std::string> failures;
  std::string not_implemented;
};

struct StepResult {
  Status status = Status::not_built;
  const Step* step = nullptr;
  std::vector<QueryResult> queries;
  std::vector<TestCaseResult> test_cases;
  std::string detail;    // why it crashed, timed out, ...
  std::string inflight;  // the replay token of the case a crash or time-out died on
  Run run;
  int examples = 0, random_cases = 0, ambiguous = 0;
  double fraction_passed = 0;  // of cases, for partial credit
};

struct StepOptions {
  std::string seed;           // "" = the harness's public default
  int cases = 0;              // 0 = the harness's default
  std::string replay;         // one case only
  bool hide_seed = false;
  bool describe_only = false; // with `replay`: describe the input, run no code under test
  Limits limits;
};

StepResult run_step(const std::string& binary, const Lab& lab, const Step& step, const StepOptions& options);

}  // namespace runner
