#include "step.h"
#include "cgroup.h"
#include "untrusted.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

namespace runner {

namespace fs = std::filesystem;
namespace variable = labkit::report::variable;

std::string status_word(Status s) {
  switch (s) {
    case Status::passed: return "passed";
    case Status::failing: return "failing";
    case Status::not_implemented: return "not implemented yet";
    case Status::crashed: return "crashed";
    case Status::timed_out: return "timed out";
    case Status::flooded: return "too much output";
    case Status::out_of_memory: return "out of memory";
    case Status::exited_early: return "exited early";
    case Status::no_tests: return "no tests (kit error)";
    case Status::kit_error: return "not graded (kit error)";
    case Status::not_built: return "does not compile";
    case Status::out_of_time: return "not graded: no time";
  }
  return "?";
}

bool abnormal(Status s) {
  return s == Status::crashed || s == Status::timed_out || s == Status::flooded || s == Status::out_of_memory ||
         s == Status::exited_early || s == Status::kit_error;
}

namespace {

// The judge's report, when the step left one: read strictly (common/protocol/report.h), and still as a
// file that could be anything (read_untrusted_file: no FIFO, no link, no flood).
void read_report(const fs::path& path, StepResult& r) try {
  constexpr std::uintmax_t kLargestReport = std::uintmax_t(64) << 20;
  const UntrustedRead file = read_untrusted_file(path.string(), kLargestReport);
  if (!file.error.empty()) return;
  const labkit::report::Step step = labkit::report::step_from_json(nlohmann::json::parse(file.text));
  r.finished = step.finished;
  r.cases_per_query = step.cases_per_query;
  r.test_cases = step.test_cases;
  r.queries = step.queries;
} catch (const std::exception&) {
  // Cut short by the judge's death (it rewrites the report as it goes): what the run
  // printed says more.
  r.finished = false;
  r.test_cases.clear();
  r.queries.clear();
}

// The case in flight when the judge's process died: the file only that process writes.
std::string inflight_token(const fs::path& file) {
  const UntrustedRead read = read_untrusted_file(file.string(), 1 << 18);
  return read.error.empty() ? read.text : "";
}

// The judge's own process ran out of memory (the code under test running out costs its
// case: its answer says so).
bool out_of_memory(const StepResult& r) {
  return r.run.output.find("std::bad_alloc") != std::string::npos && !r.finished;
}

Status decide(const StepResult& r) {
  if (r.run.flooded) return Status::flooded;
  if (r.run.timed_out) return Status::timed_out;
  if (!r.run.started) return Status::crashed;
  if (out_of_memory(r)) return Status::out_of_memory;
  if (r.run.signal != 0) return Status::crashed;
  // A session that ran no test case for the filter (the report says so, not the
  // output, which the code under test shares).
  if (r.finished && r.test_cases.empty()) return Status::no_tests;
  // The session never returned: exit() in the code under test (even exit(0)), or a death
  // the harness never saw. Its counts stop where it stopped, so they are not a verdict.
  if (!r.finished) return Status::exited_early;
  // The kit's own judge failed on some case: the step cannot be graded, and says whose
  // failure it was (check.h's kit_error).
  for (const QueryResult& q : r.queries)
    if (q.error.rfind("kit error", 0) == 0) return Status::kit_error;
  bool failing = false, stub = false;
  for (const QueryResult& q : r.queries) {
    if (!q.not_implemented.empty()) stub = true;
    if ((q.failure && q.not_implemented.empty()) || !q.error.empty()) failing = true;
  }
  for (const TestCaseResult& t : r.test_cases) {
    if (!t.not_implemented.empty()) stub = true;
    if (!t.passed && !t.failures.empty()) failing = true;
  }
  if (failing) return Status::failing;
  if (stub) return Status::not_implemented;
  if (r.run.exit_code != 0) return Status::failing;  // Catch failed something the harness did not see
  return Status::passed;
}

// Partial credit (README, "Scoring"). A query's examples and random cases are pooled,
// each case counting once. Cases split by what an answer that does nothing gets on them:
// trivial (it passes them too) and decisive (it fails them). A query earns
//   decisive pass rate + trivial pass rate - 1 - 2 standard errors of that sum, at least 0
// (without the trivial terms when it has no trivial case): a constant answer earns 0, and
// so does one drawn at random, which passes either kind at the same rate (the standard
// errors take away what luck adds). The step earns the mean over its queries, each
// weighed by its cases, so that a handful of worked examples weighs a handful of cases. A
// query with no decisive case tells nothing and is left out; a stub query earns 0 and
// weighs a query's worth of random cases.
double query_credit(int decisive, int decisive_passed, int trivial, int trivial_passed) {
  const double d = double(decisive_passed) / decisive;
  double credit = d, variance = d * (1 - d) / decisive;
  if (trivial > 0) {
    const double t = double(trivial_passed) / trivial;
    credit += t - 1;
    variance += t * (1 - t) / trivial;
  }
  return std::max(0.0, credit - 2 * std::sqrt(variance));
}

double fraction_passed(const StepResult& r) {
  if (r.status == Status::passed) return 1.0;
  if (r.status != Status::failing && r.status != Status::not_implemented) return 0.0;
  struct Pool {
    int decisive = 0, decisive_passed = 0, trivial = 0, trivial_passed = 0;
    bool nothing = false;  // a stub or an error: the query earns 0
  };
  std::map<std::string, Pool> pools;
  for (const QueryResult& q : r.queries) {
    Pool& p = pools[q.query];
    if (!q.not_implemented.empty() || !q.error.empty()) p.nothing = true;
    p.decisive += q.decisive, p.decisive_passed += q.decisive_passed;
    p.trivial += q.trivial, p.trivial_passed += q.trivial_passed;
  }
  double earned = 0, weight = 0;
  for (const auto& [query, p] : pools) {
    if (p.nothing) {
      weight += std::max(1, r.cases_per_query);
    } else if (p.decisive > 0) {
      const double cases = p.decisive + p.trivial;
      earned += cases * query_credit(p.decisive, p.decisive_passed, p.trivial, p.trivial_passed);
      weight += cases;
    }
  }
  return weight > 0 ? earned / weight : 0.0;
}

}  // namespace

namespace {

// The control group of a graded step's answerer (runner/cgroup.h): all its processes
// together get the step's memory, 64 processes and one core. Null on a student's
// machine, and where the grader's machine has no cgroups to offer.
std::unique_ptr<StepGroup> answerer_group(const StepOptions& options) {
  if (!options.sandbox || !options.sandbox->step_groups()) return nullptr;
  return std::make_unique<StepGroup>(GroupLimits{options.limits.memory_bytes});
}

// The command line the judge's process starts the answerer with: the answerer itself
// on a student's machine; for a graded run, confined (its own scratch folder, uid,
// sandbox and control group) and under limits, through `labkit-runner confine`.
std::string answerer_command(const Programs& programs, const StepOptions& options, const std::string& scratch,
                             const StepGroup* group, std::shared_ptr<void>* lease) {
  if (options.debugger)
    return nlohmann::json({"gdb", "-q", "-batch", "-ex", "run", "-ex", "bt", "--args", programs.answerer}).dump();
  if (!options.sandbox) return programs.answerer;
  Limits limits;
  limits.memory_bytes = options.limits.memory_bytes;  // per process too: a second line of defence
  limits.file_bytes = options.limits.file_bytes;
  limits.cpu_seconds = long(options.limits.seconds) + 1;
  // Its standard streams and the protocol's two pipes, descriptors 3 and 4
  // (common/protocol/answerer.h); every other descriptor is closed before it starts.
  limits.descriptors = 5;
  const Confined confined = options.sandbox->confine({programs.answerer}, scratch,
                                                     {fs::path(programs.answerer).parent_path().string()}, limits);
  *lease = confined.lease;
  Limits answerer = confined.limits;
  if (group) answerer.groups = group->folders();
  // Without a group holding them together, each process may take the step's memory: only
  // a tight cap on how many there are bounds their sum (it needs a uid of the run's own).
  if ((!group || !group->whole()) && answerer.uid >= 0) answerer.processes = kProcessesWithoutGroup;
  return nlohmann::json(launcher(answerer, confined.argv)).dump();
}

// The judge's environment for one step: where it writes its report and the case in
// flight, how to start the answerer, and the cases to run. A secret seed never goes on a
// command line or in the environment (which other processes could show): a file the
// harness deletes, in the judge's folder.
Environment judge_environment(const StepOptions& options, const std::string& scratch, const std::string& answerer) {
  Environment env = {{variable::report, (fs::path(scratch) / "report.json").string()},
                     {variable::inflight, (fs::path(scratch) / "inflight").string()},
                     {variable::answerer, answerer}};
  if (options.call_seconds > 0) env.push_back({variable::call_seconds, std::to_string(options.call_seconds)});
  if (!options.seed.empty() && options.hide_seed) {
    const fs::path seed_file = fs::path(scratch) / ".seed";
    std::ofstream(seed_file) << options.seed;
    fs::permissions(seed_file, fs::perms::owner_read | fs::perms::owner_write);
    env.push_back({variable::seed_file, seed_file.string()});
  } else if (!options.seed.empty()) {
    env.push_back({variable::seed, options.seed});
  }
  if (options.cases > 0) env.push_back({variable::cases, std::to_string(options.cases)});
  if (!options.replay.empty()) env.push_back({variable::replay, options.replay});
  if (options.hide_seed) env.push_back({variable::hide_seed, "1"});
  if (options.count_all) env.push_back({variable::count_all, "1"});
  if (options.describe_only) env.push_back({variable::describe, "1"});
  if (!options.record_examples.empty()) env.push_back({"LABKIT_RECORD_EXAMPLES", options.record_examples});
  return env;
}

// What an abnormal end of the judge's process means, in the student's words.
std::string abnormal_detail(const StepResult& r, const StepOptions& options) {
  switch (r.status) {
    case Status::crashed:  // the judge's process is the kit's: its death is never the student's code crashing
      return r.run.signal ? "the kit's test process was killed by " + signal_name(r.run.signal)
                          : "the kit's test program could not be run: " + r.run.output.substr(0, 300);
    case Status::exited_early:
      return "the kit's test process ended before its tests did, with exit status " + std::to_string(r.run.exit_code) +
             ": a kit error, not yours (please report it)";
    case Status::out_of_memory:
      return "the kit's test process ran out of memory (std::bad_alloc" +
             (options.limits.memory_bytes
                  ? ", the limit is " + std::to_string(options.limits.memory_bytes >> 20) + " MB"
                  : std::string()) +
             ")";
    case Status::kit_error:
      for (const QueryResult& q : r.queries)
        if (q.error.rfind("kit error", 0) == 0) return q.query + ": " + q.error;
      return "";
    case Status::timed_out:
      return "the step did not finish within " + std::to_string(int(options.limits.seconds)) +
             " s: the code under test is too slow for its cases (each call has a time limit too)";
    case Status::flooded:
      return "it printed more than " + std::to_string(options.limits.flood_bytes >> 20) +
             " MB and was stopped (what the code under test prints counts: remove debug prints)";
    default: return "";
  }
}

}  // namespace

StepResult run_step(const Programs& programs, const Lab& lab, const Step& step, const StepOptions& options) {
  StepResult r;
  r.step = &step;
  const auto scratch_folder = [&] {
    std::string name = options.scratch_parent + "/labkit-step.XXXXXX";
    return mkdtemp(name.data()) ? name : std::string();
  };
  // The judge's folder (its report and the seed) and the answerer's are apart: the code
  // under test never sees the first.
  const std::string scratch = scratch_folder();
  const std::string answerer_scratch = options.sandbox ? scratch_folder() : scratch;
  if (scratch.empty() || answerer_scratch.empty()) {
    r.run.started = false;
    r.run.output = "cannot make a scratch folder in " + options.scratch_parent;
    r.status = Status::crashed;
    r.detail = r.run.output;
    return r;
  }
  // Held until the step ends: the answerer's uid, and its control group (everything left
  // in it is killed then, and the group removed).
  std::shared_ptr<void> answerer_lease;
  const std::unique_ptr<StepGroup> group = answerer_group(options);
  const Environment env = judge_environment(
      options, scratch, answerer_command(programs, options, answerer_scratch, group.get(), &answerer_lease));
  const std::string filter = "[lab" + lab.id + "][step" + std::to_string(step.number) + "]";
  r.run = run({programs.judge, filter}, env, options.limits, scratch);
  read_report(fs::path(scratch) / "report.json", r);
  r.inflight = inflight_token(fs::path(scratch) / "inflight");
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  if (answerer_scratch != scratch) fs::remove_all(answerer_scratch, ignored);

  r.status = decide(r);
  r.detail = abnormal_detail(r, options);
  for (const QueryResult& q : r.queries) {
    if (q.kind == "examples")
      r.examples += q.cases;
    else
      r.random_cases += q.cases;
    r.ambiguous += q.ambiguous;
  }
  r.fraction_passed = fraction_passed(r);
  return r;
}

}  // namespace runner
