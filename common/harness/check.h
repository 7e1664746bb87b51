// The verdict harness every lab's tests use (handouts/checking.md says how a step is checked).
//
//   check::example(query::find_segment_triangle, "through the middle", input, judge);
//   check::random_cases(query::find_segment_triangle, gen::segment_triangle(), judge);
//
// The queries come from the lab's table (tests/NN_name/queries.h, common/harness/query.h),
// which also fixes the input each one takes: the compiler refuses another.
//
// A judge takes an input, runs the code under test on it, and returns an Outcome: pass,
// fail (with the expected answer, the answer it got and why they differ), or ambiguous
// (the exact answer flips under a tiny perturbation of the input, so any answer is
// accepted and the case is counted apart). The harness counts, shrinks a failing random
// case to the smallest one RapidCheck finds, writes a machine-readable report for
// `./labkit check`, and turns a stub's NotImplemented into "not implemented yet".
#pragma once

#include "common/harness/codec.h"
#include "common/harness/outcome.h"
#include "common/harness/query.h"
#include "common/harness/rapidcheck_adaptor.h"
#include "common/harness/titles.h"
#include "common/not_implemented.h"
#include "common/oracle/not_finite.h"
#include "common/protocol/answerer.h"
#include "common/protocol/report.h"

#include <rapidcheck.h>
#include "common/harness/catch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace labkit::check {

// Everything a run can be told, read once from the environment (the runner sets them):
//   LABKIT_SEED    seed of the random cases (default: the public seed 1); any text
//   LABKIT_SEED_FILE  graded runs: a file holding the seed, deleted once read
//   LABKIT_CASES   random cases per query (default 1000)
//   LABKIT_REPLAY  a replay token: run that one case and nothing else
//   LABKIT_REPORT  where to write the JSON report
//   LABKIT_HIDE_SEED=1  graded runs: reports never show the seed, and the seed is wiped
//                       from the environment before any code under test runs
//   LABKIT_DESCRIBE=1   with LABKIT_REPLAY: only describe the case's input
//   LABKIT_COUNT_ALL=1  graded runs: random_cases judges all its cases even after a
//                       failure, so the report counts how many passed (partial credit);
//                       the first failure is still shrunk and reported
struct Settings {
  std::uint64_t seed = 1;
  int cases = 1000;
  std::string replay;
  std::string report;
  bool hide_seed = false;
  bool describe_only = false;  // LABKIT_DESCRIBE=1: with a replay, describe its input, run nothing
  bool count_all = false;
  bool domain_audit = false;  // LABKIT_DOMAIN_AUDIT=1: a case drawn outside the header's domain is a kit error
};
const Settings& settings();

// A yes/no answer against the exact one. `doubt` (ignored under the exact rules): the
// input is ambiguous, so either answer passes. `yes` and `no` say the two answers.
Outcome verdict(bool got, bool expected, bool doubt, Rules rules, const std::string& yes, const std::string& no);

// Collects the differences between an answer and the expected one, field by field,
// for hand-worked examples and judges. Its rule, in the lab's words, leads every why line
// a comparison writes, before the field and its numbers; where the two numbers show the
// likely cause (a sign, a factor, a swap, a turn), the line ends with it:
//   Expect e("the crossing is a + t (b - a), with t the fraction d_a / (d_a - d_b)");
//   e.equal("crosses", got.crosses, true);
//   e.near("t", got.t, 0.25, 1e-12);
//   return e.outcome();
// why: "the crossing is a + t (b - a), ...: t is off by 0.5 (tolerance 1e-12); yours has
// the opposite sign".
// A field that counts (tests, steps, pieces...), where one too many or too few is an
// off-by-one; an index (a triangle's, an axis's) is not.
bool counts_something(const std::string& field);

class Expect {
 public:
  explicit Expect(std::string rule);
  template <class T> void equal(const std::string& field, const T& got, const T& expected) {
    const std::string g = describe(got), x = describe(expected);
    std::string mismatch = field + " is " + g + ", not " + x;
    if (g.size() + x.size() > 80) mismatch = field + " differs from the answer";
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>)
      if (counts_something(field) && (got - expected == 1 || expected - got == 1))
        mismatch += std::string(got > expected ? "; one more" : "; one fewer") + " than the answer (an off-by-one?)";
    add(field, g, x, got == expected, rule_ + ": " + mismatch);
  }
  void near(const std::string& field, double got, double expected, double tolerance);
  void near(const std::string& field, const Vec3& got, const Vec3& expected, double tolerance);
  // A condition with its own wording, for rules that are not a comparison (an empty why:
  // the Expect's rule and the field).
  void that(const std::string& field, bool ok, const std::string& got, const std::string& expected,
            const std::string& why);
  Outcome outcome() const;

 private:
  void add(const std::string& field, const std::string& got, const std::string& expected, bool ok,
           const std::string& why);
  std::string rule_, expected_, got_, why_;
  bool failed_ = false;
  // The near() fields that failed, to tell two swapped fields apart from two wrong ones.
  struct Miss {
    std::string field;
    Vec3 got, expected;
    double tolerance;
    bool scalar;
  };
  std::vector<Miss> misses_;
};

// What a wrong number most likely came from, read off the answer and yours alone: the
// opposite sign, a whole or square-root factor (a length left in or out), the right
// direction at another length, the right length in another direction, the components in
// another order. Empty when nothing simple explains the difference.
std::string likely_cause(double got, double expected, double tolerance);
std::string likely_cause(const Vec3& got, const Vec3& expected, double tolerance);

// A lab's input domain, as its header states it, over the lengths a case writes
// (codec::Kind::length): either the input's scale S, its largest |length|, is 0 or lies
// in [low, high] (Of::scale), or every non-zero length does (Of::each). Each lab's test
// file states its own once (check::domain); shrinking a failing case never leaves it,
// and a failing case shown outside it is the kit's error, never the student's.
struct Domain {
  enum class Of { scale, each } of = Of::scale;
  double low = 0, high = std::numeric_limits<double>::infinity();
  // The lab's inputs scale exactly: every length times a power of two is the same case at
  // another size (no plane's offset beside its normal, no mass beside a length). Its
  // families are drawn scale-free, and each case drawn is placed in [low, high] (fitted).
  bool fit = false;
};
void domain(const Domain& d);
const Domain& domain();
struct OutsideDomain : std::runtime_error {
  explicit OutsideDomain(const std::string& input)
      : std::runtime_error(
            "a shrunk failing case left the header's input domain, so it shows nothing about the answer (the "
            "kit's shrinking is at fault): " +
            input.substr(0, 300)) {}
};
bool in_domain(const codec::Values& v);
bool in_domain_scale(double s);  // S alone, for Of::scale: 0 or within [low, high]
namespace detail {
template <class T, class = void> struct HasHeaderScale : std::false_type {};
template <class T>
struct HasHeaderScale<T, std::void_t<decltype(header_scale(std::declval<const T&>()))>> : std::true_type {};
template <class T, class = void> struct HasHeaderDomain : std::false_type {};
template <class T>
struct HasHeaderDomain<T, std::void_t<decltype(header_in_domain(std::declval<const T&>()))>> : std::true_type {};
}  // namespace detail
// A lab whose header defines S otherwise than as the largest length (lab 05: a plane's
// distance |offset| / |n|, its direction left out) declares header_scale(input) for
// those inputs, beside them (found by argument-dependent lookup); one whose domain is not
// one range for every length (lab 01: offsets have no lower bound) header_in_domain(input).
// The case scaled by the power of two that brings its S into the domain, for a lab whose
// inputs scale exactly (Domain::fit); every relation of it (a touch, a coplanarity, a
// tie) stays exact. Any other case as it is.
template <class Input> Input fitted(const Input& input) {
  const Domain& d = domain();
  if (!d.fit || d.of != Domain::Of::scale) return input;
  codec::Values v = values_of(input);
  const double s = v.largest_length();
  if (s == 0 || !std::isfinite(s) || (s >= d.low && s <= d.high)) return input;
  const int k = s > d.high ? std::ilogb(d.high) - 1 - std::ilogb(s) : std::ilogb(d.low) + 1 - std::ilogb(s);
  for (std::size_t i = 0; i < v.numbers.size(); ++i)
    if (v.kinds[i] == codec::Kind::length) v.numbers[i] = std::ldexp(v.numbers[i], k);
  return from_numbers<Input>(std::move(v.numbers));
}

template <class Input> bool in_domain(const Input& input) {
  if constexpr (detail::HasHeaderDomain<Input>::value)
    return header_in_domain(input);
  else if constexpr (detail::HasHeaderScale<Input>::value)
    return in_domain_scale(header_scale(input));
  else
    return in_domain(values_of(input));
}

// The input's length scale S (codec::Values::largest_length), never below 1e-300.
template <class Input> double scale_of_input(const Input& input) {
  return std::max(values_of(input).largest_length(true), 1e-300);
}

// The relative size of the perturbation that decides ambiguity (handouts/checking.md, "ambiguous").
constexpr double kAmbiguity = 1e-9;

// True when the exact answer changes for some input within kAmbiguity * S of this one,
// S being the input's largest absolute coordinate (unit-free numbers such as rotation
// entries move by kAmbiguity). It tries seeded perturbations, never of counts or indices:
// each number alone, both ways, then `samples` moves of all of them together. Sampling
// can miss a flip that needs several numbers to move in step; a judge adds its query's
// own conservative test for those (see oracle::segment_triangle_in_doubt).
template <class Input, class ExactAnswer>
bool flips_under_perturbation(const Input& input, ExactAnswer&& exact, int samples = 16);

// The header's rule that keeps a query's calls finite and well defined, in the lab's words
// ("bisection halves [t0, t1] until it is shorter than tolerance: at most
// log2((t1 - t0) / tolerance) + 1 rounds"). A crash, a time-out or an exception on valid
// input in that query then says the rule before what happened. Set once per query, in
// the lab's test file, before its cases.
void rule(const std::string& query, const std::string& text);
// A measurement a passing example shows beside its step (./labkit check): the counts a
// step bounds, against their bounds.
void note(const std::string& query, const std::string& text);
const std::string& rule_of(const std::string& query);
template <class Input> void rule(const Query<Input>& query, const std::string& text) { rule(query.name, text); }
template <class Input> const std::string& rule_of(const Query<Input>& query) { return rule_of(query.name); }

// One hand-worked case from the handout.
template <class Input, class Judge>
void example(const Query<Input>& query, const std::string& title, const typename Query<Input>::InputType& input,
             Judge&& judge);

// `settings().cases` random cases from `gen`, shrunk on failure.
template <class Input, class Judge>
void random_cases(const Query<Input>& query, const rc::Gen<Input>& gen, Judge&& judge);

// Everything below is the machinery behind these three.
namespace detail {

// The report's types (common/protocol/report.h): the runner reads exactly these.
using Failure = labkit::report::Failure;
using QueryReport = labkit::report::Query;

QueryReport& entry(const std::string& query, const std::string& kind);
QueryReport& entry(const std::string& test_case, const std::string& query, const std::string& kind);
// While a judge runs (check.cpp's SIGFPE handler turns GMP's NaN abort into NotFinite there).
extern int judging;
struct Judging {
  Judging();
  ~Judging();
};
// A failure of the kit itself (never the student's): the query's report says so, and the
// step is not graded (runner/step.cpp).
Outcome kit_error(QueryReport& report, const std::string& what);
void save_report();
void report_to_catch(const QueryReport& report, bool announce_not_implemented);
std::string current_lab();
std::uint64_t seed_for(const std::string& query);
// Remembered so that a crash or a time-out can still name the input it died on.
void set_inflight(const std::string& token);
void clear_inflight();

// "The rule: <the query's rule>. <what happened>", or what happened alone.
inline std::string with_rule(const std::string& query, const std::string& what) {
  const std::string& r = rule_of(query);
  return r.empty() ? what : "the rule: " + r + ". " + what;
}

// Whether every number of the input is finite: every lab's header asks it of valid input.
template <class Input> bool all_finite(const Input& input) {
  const codec::Values v = values_of(input);
  return std::all_of(v.numbers.begin(), v.numbers.end(), [](double x) { return std::isfinite(x); });
}

// Runs the judge, turning stubs, what the code under test threw and calls that got no
// answer (a crash or a time-out in the answerer's process) into outcomes. Anything else
// thrown is the kit's own failure, never the student's: the query's report says so
// (kit_error).
template <class Input, class Judge> Outcome run_judge(Judge& judge, const Input& input, QueryReport& report) {
  try {
    const Judging judging;
    return judge(input);
  } catch (const remote::Failed& e) {
    return fail("an answer", e.got, with_rule(report.query, e.what()));
  } catch (const NotImplemented& e) {
    report.not_implemented = e.what();
    return fail("an answer", "a stub", e.what());
  } catch (const remote::Rejected& e) {
    if (!all_finite(input))  // then the generator broke every header's first precondition
      return kit_error(report, "a case was drawn with a number that is not finite, which every header forbids (" +
                                   std::string(e.what()) + ")");
    return fail(
        "an answer", std::string("std::invalid_argument: ") + e.what(),
        with_rule(report.query, "your code rejected a valid input: this input meets every precondition of the header"));
  } catch (const remote::Threw& e) {
    return fail("an answer", std::string("an exception: ") + e.what(),
                with_rule(report.query, "your code threw an exception on a valid input"));
  } catch (const oracle::NotFinite&) {  // the inputs are finite: it came from the answer
    return fail("an answer", "an answer that cannot be checked",
                "every number computed from your answer must be finite, and one is not (NaN or an infinity): is "
                "some value huge, or divided by zero?");
  } catch (const std::exception& e) {
    return kit_error(report, e.what());
  }
}

// Graded runs: what a file that does nothing would get on this case (remote::DefaultAnswers).
template <class Input, class Judge>
Outcome default_outcome(Judge& judge, const Input& input, const std::string& query) {
  remote::DefaultAnswers nothing;
  QueryReport scratch;
  scratch.query = query;
  const Outcome o = run_judge(judge, input, scratch);
  return scratch.error.empty() ? o : fail("", "", "");  // a judge that cannot take the default: decisive
}

template <class Input>
Failure failure_of(const std::string& title, const std::string& query, const Input& input, const Outcome& o) {
  return {title, describe(input), o.expected, o.got, o.why, replay_token(query, input), 0};
}

inline void tally(QueryReport& report, const Outcome& o) {
  ++report.cases;
  if (o.verdict == Outcome::Verdict::pass) ++report.passed;
  if (o.verdict == Outcome::Verdict::ambiguous) ++report.ambiguous;
  if (o.verdict == Outcome::Verdict::fail) ++report.failed;
}

// Graded runs: files the case as trivial (the default answer passes it too) or decisive.
// An ambiguous case tells nothing either way and is left out.
inline void tally_against_default(QueryReport& report, const Outcome& got, const Outcome& nothing) {
  if (got.verdict == Outcome::Verdict::ambiguous || nothing.verdict == Outcome::Verdict::ambiguous) return;
  const bool passed = got.verdict == Outcome::Verdict::pass;
  if (nothing.verdict == Outcome::Verdict::pass) {
    ++report.trivial;
    report.trivial_passed += passed;
  } else {
    ++report.decisive;
    report.decisive_passed += passed;
  }
}

// One case to judge in a batch: its judge on its input, what the default answer gets,
// and its replay token (made only when needed).
struct Item {
  std::function<Outcome()> judge;
  std::function<Outcome()> judge_default;
  std::function<std::string()> token;
};

// Judges items[begin, end) into outcomes[begin, end), gathering the code under test's
// calls into batches (common/protocol/answerer.h): each case's judge runs as a fiber
// (common/protocol/fiber.h) that waits at its call; one flush answers every waiting call
// at once, and each fiber goes on from where it waited. A judge that makes several
// dependent calls waits once per call; none runs twice.
void judge_items(const std::vector<Item>& items, std::size_t begin, std::size_t end, std::vector<Outcome>& outcomes);

// Graded runs: a worked example waits for its query's random cases, and is judged in
// their batches at a shuffled place, so that the code under test cannot tell the one
// from the other by how or when it is asked. Examples whose query has no random cases in
// the step are judged together when the session ends.
struct PendingExample {
  std::string test_case;  // its report entry's
  std::string title;
  std::shared_ptr<void> input;  // keeps the input the item's functions read
  Item item;
  std::function<Failure(const Outcome&)> failure;
};
void defer_example(const std::string& query, PendingExample example);
std::vector<PendingExample> take_examples(const std::string& query);
// Tallies an example judged in a batch into its own report entry.
void record_example(const std::string& query, const PendingExample& example, const Outcome& o, const Outcome& nothing);

template <class Input, class Judge> void replay_one(const std::string& query, Judge& judge, QueryReport& report) {
  const ParsedToken token = parse_token(settings().replay);
  const Input input = input_from_token<Input>(token);
  if (settings().describe_only) {
    report.failure = failure_of("described", query, input, Outcome{});
    return;
  }
  set_inflight(settings().replay);
  const Outcome o = run_judge(judge, input, report);
  clear_inflight();
  tally(report, o);
  if (o.verdict == Outcome::Verdict::fail) report.failure = failure_of("the replayed case", query, input, o);
}

}  // namespace detail

template <class Input, class ExactAnswer>
bool flips_under_perturbation(const Input& input, ExactAnswer&& exact, int samples) {
  const codec::Values base = values_of(input);
  std::vector<std::size_t> movable;
  std::uint64_t hash = 1469598103934665603ull;
  for (std::size_t i = 0; i < base.numbers.size(); ++i) {
    if (base.kinds[i] != codec::Kind::count) movable.push_back(i);
    std::uint64_t bits;
    std::memcpy(&bits, &base.numbers[i], sizeof bits);
    hash = (hash ^ bits) * 1099511628211ull;
  }
  const double length_step = kAmbiguity * scale_of_input(input);
  const auto step = [&](std::size_t i) { return base.kinds[i] == codec::Kind::unit ? kAmbiguity : length_step; };
  const auto answer = exact(input);
  const auto differs = [&](const std::vector<double>& numbers) {
    return !(exact(from_numbers<Input>(numbers)) == answer);
  };
  std::mt19937_64 random(hash);

  // Each number alone, both ways: this flips every exactly-zero predicate that depends
  // on it (an end exactly on a plane, a point exactly on an edge). Large inputs get a
  // seeded subset; their judges check ambiguity piece by piece instead.
  std::vector<std::size_t> single = movable;
  if (single.size() > 48) {
    std::shuffle(single.begin(), single.end(), random);
    single.resize(48);
  }
  for (std::size_t i : single)
    for (double direction : {1.0, -1.0}) {
      std::vector<double> numbers = base.numbers;
      numbers[i] += direction * step(i);
      if (differs(numbers)) return true;
    }
  // Then every number at once: corners of the box, and random points inside it, which
  // reach predicates that are near zero but need several numbers to move together.
  for (int k = 0; k < samples; ++k) {
    std::vector<double> numbers = base.numbers;
    for (std::size_t i : movable) {
      const double u = std::uniform_real_distribution<double>(-1.0, 1.0)(random);
      numbers[i] += step(i) * (k % 2 == 0 ? (u < 0 ? -1.0 : 1.0) : u);
    }
    if (differs(numbers)) return true;
  }
  return false;
}

namespace detail {

template <class Input, class Judge>
std::vector<Item> items_of(const std::vector<Input>& inputs, Judge& judge, QueryReport& report) {
  std::vector<Item> items;
  items.reserve(inputs.size());
  for (const Input& input : inputs)
    items.push_back({[&judge, &input, &report] { return run_judge(judge, input, report); },
                     [&judge, &input, &report] { return default_outcome(judge, input, report.query); },
                     [&input, &report] { return replay_token(report.query, input); }});
  return items;
}

// Graded runs: every case judged, the query's worked examples shuffled in among them (see
// PendingExample), each case filed as trivial or decisive. `outcomes` gets the random cases'.
template <class Input, class Judge>
void judge_graded(const std::vector<Input>& inputs, Judge& judge, QueryReport& report, std::vector<Outcome>& outcomes) {
  std::vector<Item> items = items_of(inputs, judge, report);
  std::vector<PendingExample> examples = take_examples(report.query);
  for (const PendingExample& e : examples) items.push_back(e.item);
  std::vector<std::size_t> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(seed_for(report.query) ^ 0x9e3779b97f4a7c15ull));
  std::vector<Item> shuffled;
  shuffled.reserve(order.size());
  for (std::size_t i : order) shuffled.push_back(items[i]);
  std::vector<Outcome> judged(shuffled.size());
  constexpr std::size_t kChunk = 1024;
  for (std::size_t begin = 0; begin < shuffled.size(); begin += kChunk)
    judge_items(shuffled, begin, std::min(shuffled.size(), begin + kChunk), judged);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Outcome nothing = shuffled[k].judge_default();
    if (order[k] < inputs.size()) {
      outcomes[order[k]] = judged[k];
    } else {
      record_example(report.query, examples[order[k] - inputs.size()], judged[k], nothing);
      continue;
    }
    tally_against_default(report, judged[k], nothing);
  }
  for (const Outcome& o : outcomes) tally(report, o);
}

template <class Input, class Judge>
void example_now(const std::string& query, const std::string& title, const Input& input, Judge& judge) {
  QueryReport& report = entry(query, "examples");
  const bool stub_seen_before = !report.not_implemented.empty();
  set_inflight(replay_token(query, input));
  const Outcome o = [&] {
    remote::RecordingExample recording;
    return run_judge(judge, input, report);
  }();
  clear_inflight();
  tally(report, o);
  const bool first_failure = o.verdict == Outcome::Verdict::fail && !report.failure;
  if (first_failure) report.failure = failure_of("example \"" + title + "\"", query, input, o);
  save_report();
  if (first_failure || (!report.not_implemented.empty() && !stub_seen_before))
    report_to_catch(report, !stub_seen_before);
  else
    SUCCEED();
}

template <class Input, class Judge>
void example_later(const std::string& query, const std::string& title, const Input& input, Judge&& judge) {
  QueryReport& report = entry(query, "examples");  // std::deque: its address stays
  auto kept = std::make_shared<Input>(input);
  auto kept_judge = std::make_shared<std::decay_t<Judge>>(std::forward<Judge>(judge));
  QueryReport* r = &report;
  PendingExample e;
  e.test_case = report.test_case;
  e.title = title;
  e.input = kept;
  e.item.judge = [kept, kept_judge, r] { return run_judge(*kept_judge, *kept, *r); };
  e.item.judge_default = [kept, kept_judge, query] { return default_outcome(*kept_judge, *kept, query); };
  e.item.token = [kept, query] { return replay_token(query, *kept); };
  e.failure = [kept, query, title](const Outcome& o) {
    return failure_of("example \"" + title + "\"", query, *kept, o);
  };
  defer_example(query, std::move(e));
  save_report();
  SUCCEED();
}

// An example replayed by the token its failure printed: its own judge runs, which may
// know more than the input (a pose it captured, the handout's figure).
template <class Input, class Judge>
void replay_example(const std::string& query, const std::string& title, const Input& input, Judge& judge) {
  if (settings().describe_only) {
    QueryReport& report = entry(query, "examples");
    report.failure = failure_of("described", query, input, Outcome{});
    return save_report();
  }
  example_now(query, title, input, judge);
}
// Whether the replay token names this example: its query and its input's numbers.
template <class Input> bool replays(const std::string& query, const Input& input) {
  try {
    const ParsedToken token = parse_token(settings().replay);
    return token.query == query && token.numbers == values_of(input).numbers;
  } catch (const BadToken&) {
    return false;  // random_cases reports what is wrong with it
  }
}
// Whether an example already ran as the replayed case (random_cases then stays quiet).
bool replayed_as_example(const std::string& query);

template <class Input, class Judge>
void random_cases_unguarded(const Query<Input>& q, const rc::Gen<Input>& gen, Judge& judge, QueryReport& report);

}  // namespace detail

template <class Input, class Judge>
void example(const Query<Input>& q, const std::string& title, const typename Query<Input>::InputType& input,
             Judge&& judge) {
  // A replay runs the one case it names: this example, when the token is its own.
  if (!settings().replay.empty()) {
    if (detail::replays(q.name, input)) detail::replay_example(q.name, title, input, judge);
    return;
  }
  if (settings().count_all) return detail::example_later(q.name, title, input, std::forward<Judge>(judge));
  detail::example_now(q.name, title, input, judge);
}

template <class Input, class Judge> void random_cases(const Query<Input>& q, const rc::Gen<Input>& gen, Judge&& judge) {
  detail::QueryReport& report = detail::entry(q.name, "random");
  try {
    detail::random_cases_unguarded(q, gen, judge, report);
  } catch (const std::exception& e) {  // the harness's own failure: a kit error, not the student's
    detail::kit_error(report, e.what());
    detail::save_report();
    detail::report_to_catch(report, true);
  }
}

namespace detail {

// A stub is reported as "not implemented yet" from one probe, instead of being shrunk.
template <class Input, class Judge>
bool not_implemented_by_probe(const std::string& query, const rc::Gen<Input>& gen, Judge& judge, QueryReport& report) {
  const Input probe = fitted(rapidcheck::first_case(gen, seed_for(query)));
  QueryReport scratch;
  run_judge(judge, probe, scratch);
  if (scratch.not_implemented.empty()) return false;
  report.not_implemented = scratch.not_implemented;
  return true;
}

// The query's cases, drawn as RapidCheck draws them (the same seed, the same cases); none
// if they could not be drawn (report.error says why). The kit's own tests check the
// generators: every case lies in the header's domain (LABKIT_DOMAIN_AUDIT=1).
template <class Input>
std::optional<std::vector<Input>> draw_cases(const std::string& query, const rc::Gen<Input>& gen, QueryReport& report) {
  const Settings& s = settings();
  std::vector<Input> inputs;
  inputs.reserve(std::size_t(s.cases));
  const rapidcheck::Result drawn =
      rapidcheck::run(query, seed_for(query), s.cases, [&] { inputs.push_back(fitted(*gen)); });
  if (drawn.kind != rapidcheck::Result::Kind::passed) {
    report.error = "the random cases could not be drawn: " + (drawn.kind == rapidcheck::Result::Kind::failed
                                                                  ? drawn.description
                                                                  : std::string("RapidCheck gave up or failed"));
    return std::nullopt;
  }
  if (s.domain_audit) {
    const auto outside =
        std::find_if(inputs.begin(), inputs.end(), [](const Input& in) { return !in_domain(in) || !all_finite(in); });
    if (outside != inputs.end())
      throw std::runtime_error("case " + std::to_string(outside - inputs.begin() + 1) + " of " +
                               std::to_string(inputs.size()) +
                               " was drawn outside the header's input domain: " + describe(*outside).substr(0, 600));
  }
  return inputs;
}

// Judges the cases a chunk at a time, each chunk's calls in one batch; the 1-based index
// of the first failing case, 0 for none. The student's check stops at the chunk holding
// the first failure; a graded run judges every case (partial credit).
template <class Input, class Judge>
int judge_cases(const std::vector<Input>& inputs, Judge& judge, QueryReport& report, std::vector<Outcome>& outcomes) {
  constexpr std::size_t kChunk = 1024;
  outcomes.assign(inputs.size(), Outcome{});
  int first_failing_case = 0;
  if (settings().count_all) {
    judge_graded(inputs, judge, report, outcomes);
    for (std::size_t i = 0; i < outcomes.size() && first_failing_case == 0; ++i)
      if (outcomes[i].verdict == Outcome::Verdict::fail) first_failing_case = int(i) + 1;
    return first_failing_case;
  }
  const std::vector<Item> items = items_of(inputs, judge, report);
  for (std::size_t begin = 0; begin < inputs.size() && first_failing_case == 0; begin += kChunk) {
    const std::size_t end = std::min(inputs.size(), begin + kChunk);
    judge_items(items, begin, end, outcomes);
    for (std::size_t i = begin; i < end && first_failing_case == 0; ++i) {
      tally(report, outcomes[i]);
      if (outcomes[i].verdict == Outcome::Verdict::fail) first_failing_case = int(i) + 1;
    }
  }
  return first_failing_case;
}

// RapidCheck draws the same cases again to shrink the first failure (case `first`,
// 1-based): those before it passed already, so only the failing case and its shrinks are
// judged, one at a time. Shrinking has a budget: code that fails every input (a crash
// before main, say) makes every smaller input fail too, and a large input (two meshes)
// has a long way down; past it the smallest failure so far is the one shown. Sets
// report.failure, or report.error when the generator itself failed.
template <class Input, class Judge>
void shrink_failure(const std::string& query, const rc::Gen<Input>& gen, Judge& judge, QueryReport& report, int first,
                    Failure first_failure) {
  constexpr int kShrinkTries = 400;
  constexpr auto kShrinkTime = std::chrono::seconds(5);
  const std::string title = "random case " + std::to_string(first) + " of " + std::to_string(settings().cases);
  bool shrinking = false, start_in_domain = true;
  int seen = 0, shrinks = -1, tries = 0;
  std::chrono::steady_clock::time_point shrink_start;
  std::optional<Failure> smallest;
  std::optional<Input> smallest_input;
  const auto property = [&] {
    const Input input = fitted(*gen);
    if (!shrinking && ++seen < first) return;
    if (shrinking && (++tries > kShrinkTries || std::chrono::steady_clock::now() - shrink_start > kShrinkTime)) return;
    if (shrinking && start_in_domain && !in_domain(input)) return;  // a smaller case outside the domain shows nothing
    if (!shrinking) shrink_start = std::chrono::steady_clock::now();
    set_inflight(replay_token(query, input));
    const Outcome o = run_judge(judge, input, report);
    clear_inflight();
    if (o.verdict != Outcome::Verdict::fail) return;
    // Shrinking stays in the header's domain when the case it starts from is in it.
    if (!shrinking) start_in_domain = in_domain(input);
    shrinking = true;
    ++shrinks;
    smallest = failure_of("", query, input, o);
    smallest_input = input;
    RC_FAIL(o.why);
  };
  const rapidcheck::Result result = rapidcheck::run(query, seed_for(query), settings().cases, property);
  using Kind = rapidcheck::Result::Kind;
  if (result.kind == Kind::failed && smallest) {
    if (start_in_domain && !in_domain(*smallest_input)) throw OutsideDomain(smallest->input);
    smallest->shrinks = shrinks;
    smallest->title = title;
    report.failure = smallest;
  } else if (result.kind == Kind::failed) {  // no judge's verdict: the generator itself threw
    report.error = "a random case could not be generated: " + result.description;
  } else if (result.kind == Kind::gave_up) {
    report.error = "the generator gave up: " + result.description;
  } else if (result.kind == Kind::error) {
    report.error = "RapidCheck failed: " + result.description;
  } else {
    // It failed in the counting pass but not when run again: the code under test is not
    // deterministic. The case it failed on is still the one to show.
    first_failure.title = title + " (it passed when run again: is the code deterministic?)";
    report.failure = first_failure;
  }
}

}  // namespace detail

template <class Input, class Judge>
void detail::random_cases_unguarded(const Query<Input>& q, const rc::Gen<Input>& gen, Judge& judge,
                                    QueryReport& report) {
  const std::string query = q.name;
  const auto finish = [&report] {
    save_report();
    report_to_catch(report, true);
  };
  if (!settings().replay.empty()) {
    if (parse_token(settings().replay).query != query || replayed_as_example(query)) return;
    try {
      replay_one<Input>(query, judge, report);
    } catch (const BadToken& e) {
      report.error = e.what();
    }
    return finish();
  }
  if (not_implemented_by_probe(query, gen, judge, report)) return finish();
  remote::new_query();
  std::optional<std::vector<Input>> inputs = draw_cases(query, gen, report);
  if (!inputs) return finish();
  std::vector<Outcome> outcomes;
  const int first = judge_cases(*inputs, judge, report, outcomes);
  save_report();
  if (first == 0) return finish();
  Failure first_failure = failure_of("", query, (*inputs)[std::size_t(first) - 1], outcomes[std::size_t(first) - 1]);
  inputs.reset();
  outcomes = {};
  if (first_failure.got == remote::kNoAnswer) {
    // A call that never finished is not shrunk: each try would wait out the time limit.
    first_failure.title = "random case " + std::to_string(first) + " of " + std::to_string(settings().cases);
    report.failure = first_failure;
    return finish();
  }
  shrink_failure(query, gen, judge, report, first, first_failure);
  finish();
}

}  // namespace labkit::check
