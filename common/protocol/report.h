// The report of one step: what the judge's process (common/harness) writes and the
// runner (runner/step.cpp) reads. Each struct's fields() lists its JSON keys once, for
// writing and for reading, so that a field is added or renamed in one place. The runner
// trusts the report because the code under test never writes it (answerer.h): it only
// answers.
//
// Reading is strict: a missing key, a misspelt one or another type is an error naming
// the field, never a silent default.
#pragma once

#include "common/fields.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace labkit::report {

// The first failing case of a query, as the student reads it.
struct Failure {
  std::string title;     // "random case 6 of 1000", "example \"through the middle\""
  std::string input;     // the input, described
  std::string expected;  // the exact answer
  std::string got;       // the answer under test
  std::string why;       // the rule it broke, then the numbers
  std::string replay;    // the replay token: query:numbers
  int shrinks = 0;       // how often RapidCheck shrank it
};
LABKIT_FIELDS(Failure, title, input, expected, got, why, replay, shrinks)

// One query of one test case: its examples, or its random cases.
struct Query {
  std::string test_case;
  std::string query;
  std::string kind;  // "examples" or "random"
  int cases = 0;
  int passed = 0;
  int ambiguous = 0;
  int failed = 0;
  // Graded runs (LABKIT_COUNT_ALL): each unambiguous case judged again as if the code
  // answered every call with its default (no hit, false, zeros). `trivial` cases are
  // those that answer would pass, `decisive` the others; partial credit is earned on
  // both at once, so that neither a constant nor a chance answer earns anything
  // (runner/step.cpp, README "Scoring").
  int trivial = 0, trivial_passed = 0;
  int decisive = 0, decisive_passed = 0;
  std::string not_implemented;     // the stub's message, when a stub was hit
  std::string error;               // a failure of the harness itself ("kit error: ...")
  std::optional<Failure> failure;  // null in JSON when every case passed
  // What a query measured that a student wants to see even when it passes (lab 06 step
  // 8's test counts against their bounds), measured in the judge's process.
  std::vector<std::string> notes;
};
LABKIT_FIELDS(Query, test_case, query, kind, cases, passed, ambiguous, failed, trivial, trivial_passed, decisive,
              decisive_passed, not_implemented, error, failure, notes)

// One Catch test case.
struct TestCase {
  std::string name;
  std::vector<std::string> tags;
  bool passed = false;
  bool ended = false;                 // false when the process died or exited inside it
  std::vector<std::string> failures;  // the first few failed assertions, as Catch words them
  std::string not_implemented;        // set when a stub was reached
};
LABKIT_FIELDS(TestCase, name, tags, passed, ended, failures, not_implemented)

struct Step {
  std::string seed;  // the seed's text, or "hidden"
  int cases_per_query = 0;
  bool finished = false;  // the test session returned (else: it died on the way)
  std::vector<TestCase> test_cases;
  std::vector<Query> queries;
};
LABKIT_FIELDS(Step, seed, cases_per_query, finished, test_cases, queries)

nlohmann::json to_json(const Step& step);
// Throws std::runtime_error naming the field when `json` is not a step's report.
Step step_from_json(const nlohmann::json& json);

// A failure as a person reads it, one field a line, each under a label column:
//   query     segment_plane, random case 6 of 1000 (shrunk 3 times)
//   input     ...
// `indent` starts each line; continuation lines line up under the values.
std::string format(const Failure& f, const std::string& query, const std::string& indent);

// The environment between the runner, the judge's process and the answerer.
namespace variable {
constexpr const char* report = "LABKIT_REPORT";      // where the judge writes this report
constexpr const char* inflight = "LABKIT_INFLIGHT";  // where a dying judge names its case
constexpr const char* answerer = "LABKIT_ANSWERER";  // the answerer's command line
constexpr const char* call_seconds = "LABKIT_CALL_SECONDS";
constexpr const char* seed = "LABKIT_SEED";
constexpr const char* seed_file = "LABKIT_SEED_FILE";
constexpr const char* hide_seed = "LABKIT_HIDE_SEED";
constexpr const char* cases = "LABKIT_CASES";
constexpr const char* replay = "LABKIT_REPLAY";
constexpr const char* describe = "LABKIT_DESCRIBE";
constexpr const char* count_all = "LABKIT_COUNT_ALL";
constexpr const char* domain_audit = "LABKIT_DOMAIN_AUDIT";  // the kit's own tests: every case drawn in the domain
}  // namespace variable

}  // namespace labkit::report
