// `./labkit grade SUBMISSION...`: the instructor's command.
//
// Each submission's labs are built on their own from the student's files alone (a
// compile error costs that lab), each step runs in its own confined process under
// limits (a crash, a time-out, running out of memory, a flood of output or an early
// exit() costs that step), on cases of its own drawn from a secret seed and its files
// (seed.h), within a time budget for all its compiles and steps. Points come from
// grading/manifest.json; a step marked "partial" earns its points in proportion to the
// cases it passes (ambiguous cases count as passed).
//
// Results: OUT/results.json (Gradescope), OUT/junit.xml, OUT/report.txt (the table) and
// OUT/steps.tsv for one submission; OUT/<name>/... for each of several, and OUT/class.csv,
// OUT/gradebook.csv (for Canvas and Moodle) and the class page. With an assignment
// (assignment.h) all of them hold its labs and steps only, and its total.
#pragma once

#include "kit.h"
#include "manifest.h"
#include "step.h"

#include <string>
#include <vector>

namespace runner {

// Random cases per query when grading. Students' checks run 1,000 per query on the
// public seed (enough to catch every classic mistake written in the references, and
// quick after each save); grading draws three times as many from the secret seed, so
// that every generator family comes up hundreds of times, and a submission still grades
// in about half a minute. A student rehearses it with ./labkit check --cases 3000 --seed anything.
constexpr int kGradingCases = 3000;

// A submission's time budget, in seconds of wall time of the processes the grader runs
// for it (compiles, links, steps): each step's limit is the least of its own and what is
// left. 480 s keeps all seven labs inside Gradescope's 10-minute time-out at half a CPU
// (a submission takes about 125 s there), with room for the grader's own work; a class
// run then takes at most students x budget / jobs.
constexpr double kGradingBudget = 480;
// A lab's compile and link, at most (less when the budget has less left).
constexpr double kBuildSeconds = 300;

struct GradeOptions {
  std::vector<std::string> submissions;
  std::string out = "grades";
  std::string seed;                     // the secret seed; "" grades with the public one (and says so)
  std::vector<std::string> labs;        // empty: every lab the kit has
  std::vector<std::string> assignment;  // its items or file (assignment.h); empty: the whole kit
  std::string roster;                   // a roster CSV for gradebook.csv (gradebook.h); "": none
  int jobs = 0;                         // processes at once (0: what the CPU and memory envelope allows)
  int cases = kGradingCases;            // random cases per query
  double timeout = 60;                  // seconds per step
  double budget = kGradingBudget;       // seconds of wall time for a submission's compiles and steps together
  std::size_t memory_mb = 2048;         // address space per step (less when the envelope is smaller)
  std::string sandbox = "auto";         // auto, bubblewrap, landlock or none (sandbox.h)
};

struct StepGrade {
  const Step* step = nullptr;
  bool graded = false;  // false until its run ends (results.json is written as steps end)
  Status status = Status::not_built;
  double score = 0;
  int cases = 0, ambiguous = 0;
  double seconds = 0;    // the step's process, wall clock
  std::string feedback;  // what the student reads: never the seed
  std::string why;       // a failing step's first failure: the rule it broke, then the numbers
};

struct LabGrade {
  const Lab* lab = nullptr;
  // out_of_time: the submission's time budget ran out before (or while) it was built.
  enum class State { pending, graded, missing, not_built, out_of_time } state = State::pending;
  std::string build_output;  // compiler errors, or why the file is missing
  double build_seconds = 0;  // compile, audit and link, wall clock
  std::vector<StepGrade> steps;
  double score = 0, max_score = 0;
};

struct SubmissionGrade {
  std::string name, source;
  std::string error;  // the submission could not be read at all
  std::vector<std::string> notes;
  std::vector<LabGrade> labs;
  double score = 0, max_score = 0, seconds = 0;
  double budget = 0, budget_used = 0;  // seconds: its time budget, and what its processes took of it
  std::string budget_note;             // when it ran out: what used it, the slowest first
};

int grade(const Paths& paths, const GradeOptions& options);

// Points for a step's result: all, none, or (partial steps) the fraction of cases
// passed, rounded down to a hundredth so that a near miss never shows as full marks.
double step_score(const Step& step, const StepResult& result);

}  // namespace runner
