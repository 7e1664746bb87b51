// A judge's verdict on one answer, and the rules it judges by: all that a lab's table of
// queries (tests/NN_name/queries.h) needs to declare its verdicts. The harness that runs
// them is common/harness/check.h.
#pragma once

#include <string>
#include <utility>

namespace labkit::check {

struct Outcome {
  enum class Verdict { pass, fail, ambiguous };
  Verdict verdict = Verdict::pass;
  std::string expected;  // the exact answer, as a person reads it
  std::string got;       // the answer under test
  std::string why;       // the rule it broke, with the numbers
};

inline Outcome pass() { return {}; }
inline Outcome ambiguous() { return {Outcome::Verdict::ambiguous, {}, {}, {}}; }
inline Outcome fail(std::string expected, std::string got, std::string why) {
  return {Outcome::Verdict::fail, std::move(expected), std::move(got), std::move(why)};
}

// Which rules a query is judged by: random cases accept either answer on ambiguous input;
// a robustness step's exact degenerate input must follow the header's rules exactly.
enum class Rules { random, exact };

}  // namespace labkit::check
