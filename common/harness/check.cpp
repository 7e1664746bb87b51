#include "common/harness/check.h"
#include "common/harness/report_writer.h"
#include "common/protocol/fiber.h"
#include "common/splitmix.h"
#include "common/text.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <random>

namespace labkit::check {

namespace {

namespace variable = labkit::report::variable;

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::uint64_t splitmix(std::uint64_t x) { return SplitMix64{x}.next(); }  // one step: a well-mixed hash of x

// A seed may be a number or any text (an instructor's secret phrase).
std::uint64_t parse_seed(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos && text.size() < 20)
    return std::stoull(text);
  return fnv1a(text);
}

Settings read_settings() {
  Settings s;
  if (const char* v = std::getenv(variable::seed); v && *v) s.seed = parse_seed(v);
  if (const char* v = std::getenv(variable::cases); v && *v) {
    const long n = std::strtol(v, nullptr, 10);
    s.cases = n >= 1 ? int(std::min(n, 100000000L)) : 1;
  }
  if (const char* v = std::getenv(variable::replay)) s.replay = v;
  if (const char* v = std::getenv(variable::report)) s.report = v;
  if (const char* v = std::getenv(variable::hide_seed)) s.hide_seed = std::string(v) == "1";
  if (const char* v = std::getenv(variable::describe)) s.describe_only = std::string(v) == "1";
  if (const char* v = std::getenv(variable::count_all)) s.count_all = std::string(v) == "1";
  if (const char* v = std::getenv(variable::domain_audit)) s.domain_audit = std::string(v) == "1";
  // A graded run's seed is a secret: it comes in a file that is deleted once read, and
  // is wiped from the environment (getenv, and /proc/self/environ, which shows the
  // original bytes in place), before any code under test runs (see read_early below).
  if (const char* v = std::getenv(variable::seed_file); v && *v) {
    const std::string text = read_file(v);
    if (!text.empty()) s.seed = parse_seed(text);
    std::remove(v);
  }
  if (char* v = std::getenv(variable::seed); v && s.hide_seed) {
    std::memset(v, 0, std::strlen(v));
    unsetenv(variable::seed);
  }
  return s;
}

// std::deque: entries keep their address while more are added.
std::deque<detail::QueryReport>& queries() {
  static std::deque<detail::QueryReport> all;
  return all;
}

std::deque<report::TestCase>& test_cases() {
  static std::deque<report::TestCase> all;
  return all;
}

bool run_finished = false;  // the test session returned: the process did not end early

// The test case running now, as the listener of catch_main.cpp reported it ("" outside one).
std::string current_test_name() {
  if (test_cases().empty() || test_cases().back().ended) return {};
  return test_cases().back().name;
}

// The in-flight case, kept in static storage so that a signal handler can print it.
char inflight[1 << 18];
volatile std::size_t inflight_length = 0;

}  // namespace

namespace {
std::map<std::string, std::string>& rules() {
  static std::map<std::string, std::string> r;
  return r;
}
}  // namespace

void rule(const std::string& query, const std::string& text) { rules()[query] = text; }

void note(const std::string& query, const std::string& text) { detail::entry(query, "examples").notes.push_back(text); }

const std::string& rule_of(const std::string& query) {
  static const std::string none;
  const auto it = rules().find(query);
  return it == rules().end() ? none : it->second;
}

const Settings& settings() {
  static const Settings s = read_settings();
  return s;
}

// Before any other static initializer (a student file's included): the seed file is gone
// and the environment wiped by the time code under test could look.
__attribute__((constructor(101))) static void read_early() { settings(); }

namespace detail {

QueryReport& entry(const std::string& query, const std::string& kind) {
  return entry(current_test_name(), query, kind);
}

QueryReport& entry(const std::string& test, const std::string& query, const std::string& kind) {
  for (QueryReport& q : queries())
    if (q.test_case == test && q.query == query && q.kind == kind) return q;
  queries().push_back({});
  QueryReport& q = queries().back();
  q.test_case = test;
  q.query = query;
  q.kind = kind;
  return q;
}

bool replayed_as_example(const std::string& query) {
  for (const QueryReport& q : queries())
    if (q.query == query && q.kind == "examples" && (q.cases > 0 || q.failure)) return true;
  return false;
}

int judging = 0;
Judging::Judging() { ++judging; }
Judging::~Judging() { --judging; }

Outcome kit_error(QueryReport& report, const std::string& what) {
  const std::string text = "kit error: the kit's own judge failed here, not your code (please report it): " + what;
  if (report.error.empty()) report.error = text;
  return fail("an answer", "(not judged)", text);
}

void judge_items(const std::vector<Item>& items, std::size_t begin, std::size_t end, std::vector<Outcome>& outcomes) {
  // Fibers alive at once: each holds a stack (fiber.h) until its judge returns.
  constexpr std::size_t kAlive = 64;
  remote::begin_batch();
  for (std::size_t first = begin; first < end; first += kAlive) {
    struct Case {
      std::string token;  // its replay token: a crash of the judge's process names its case
      std::unique_ptr<remote::Fiber> fiber;
    };
    std::vector<Case> waiting;
    const auto run = [&](Case& c) {
      set_inflight(c.token);
      const bool done = c.fiber->resume();
      clear_inflight();
      return done;
    };
    for (std::size_t i = first; i < std::min(end, first + kAlive); ++i) {
      Case c{items[i].token(),
             std::make_unique<remote::Fiber>([&items, &outcomes, i] { outcomes[i] = items[i].judge(); })};
      if (!run(c)) waiting.push_back(std::move(c));
    }
    while (!waiting.empty()) {
      try {
        remote::flush();
      } catch (...) {
        remote::end_batch();  // each waiting call now ends with a kit error, its judge's frames unwound
        for (Case& c : waiting) run(c);
        throw;
      }
      std::vector<Case> still;
      for (Case& c : waiting)
        if (!run(c)) still.push_back(std::move(c));
      waiting = std::move(still);
    }
  }
  remote::end_batch();
}

namespace {
std::map<std::string, std::vector<PendingExample>>& pending_examples() {
  static std::map<std::string, std::vector<PendingExample>> all;
  return all;
}
}  // namespace

void defer_example(const std::string& query, PendingExample example) {
  pending_examples()[query].push_back(std::move(example));
}

std::vector<PendingExample> take_examples(const std::string& query) {
  std::vector<PendingExample> taken;
  const auto it = pending_examples().find(query);
  if (it == pending_examples().end()) return taken;
  taken = std::move(it->second);
  pending_examples().erase(it);
  return taken;
}

void record_example(const std::string& query, const PendingExample& example, const Outcome& o, const Outcome& nothing) {
  QueryReport& report = entry(example.test_case, query, "examples");
  tally(report, o);
  tally_against_default(report, o, nothing);
  if (o.verdict == Outcome::Verdict::fail && !report.failure) report.failure = example.failure(o);
}

// The examples whose query had no random cases in this run, judged together, shuffled.
void judge_remaining_examples() {
  std::vector<std::pair<std::string, PendingExample>> all;
  for (auto& [query, examples] : pending_examples())
    for (PendingExample& e : examples) all.emplace_back(query, std::move(e));
  pending_examples().clear();
  if (all.empty()) return;
  std::shuffle(all.begin(), all.end(), std::mt19937_64(seed_for("examples")));
  std::vector<Item> items;
  for (const auto& [query, e] : all) items.push_back(e.item);
  std::vector<Outcome> outcomes(items.size());
  try {
    judge_items(items, 0, items.size(), outcomes);
    for (std::size_t i = 0; i < all.size(); ++i)
      record_example(all[i].first, all[i].second, outcomes[i], items[i].judge_default());
  } catch (const std::exception& e) {
    kit_error(entry(all.front().second.test_case, all.front().first, "examples"), e.what());
  }
}

std::uint64_t seed_for(const std::string& query) { return splitmix(settings().seed ^ fnv1a(query)); }

std::string current_lab() {
  if (!current_test_name().empty())
    for (const std::string& tag : test_cases().back().tags)
      if (tag.rfind("lab", 0) == 0 && tag.size() == 5) return tag.substr(3);
  return "NN";
}

void set_inflight(const std::string& token) {
  const std::size_t n = std::min(token.size(), sizeof inflight - 1);
  inflight_length = 0;
  std::memcpy(inflight, token.data(), n);
  inflight_length = n;
}

void clear_inflight() { inflight_length = 0; }

void save_report() {
  const std::string& path = settings().report;
  if (path.empty()) return;
  labkit::report::Step step;
  step.seed = settings().hide_seed ? "hidden" : std::to_string(settings().seed);
  step.cases_per_query = settings().cases;
  step.finished = run_finished;
  step.test_cases.assign(test_cases().begin(), test_cases().end());
  step.queries.assign(queries().begin(), queries().end());
  // Written beside and renamed: a crash mid-write leaves the previous report whole. What
  // the code under test threw is its own text: invalid UTF-8 in it is replaced, not fatal.
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial);
    out << labkit::report::to_json(step).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  }
  std::rename(partial.c_str(), path.c_str());
}

void report_to_catch(const QueryReport& q, bool announce_not_implemented) {
  if (!q.error.empty()) {
    FAIL_CHECK(q.query << ": " << q.error);
  } else if (q.failure) {
    std::string text = labkit::report::format(*q.failure, q.query, "  ");
    if (!settings().hide_seed) text += "  seed      " + std::to_string(settings().seed) + "\n";
    text += "  replay    ./labkit check " + current_lab() + " --case '" + q.failure->replay + "'";
    FAIL_CHECK(text);
  } else if (!q.not_implemented.empty()) {
    if (announce_not_implemented) FAIL_CHECK(q.query << ": " << q.not_implemented);
  } else {
    SUCCEED(q.query << ": " << q.cases << " cases, " << q.ambiguous << " ambiguous");
  }
}

}  // namespace detail

namespace report {

void test_case_started(const std::string& name, const std::vector<std::string>& tags) {
  test_cases().push_back({name, tags, false, false, {}, {}});
  detail::save_report();
}

void assertion_failed(const std::string& message) {
  if (test_cases().empty()) return;
  TestCase& t = test_cases().back();
  if (message.find("not implemented yet (") != std::string::npos) {
    if (t.not_implemented.empty()) t.not_implemented = message;
  } else if (t.failures.size() < 5) {
    t.failures.push_back(message);
  }
}

void test_case_ended(bool passed) {
  if (test_cases().empty()) return;
  test_cases().back().passed = passed;
  test_cases().back().ended = true;
  detail::save_report();
}

void kit_error(const std::string& what) {
  detail::QueryReport& entry = detail::entry("(the test case)", "examples");
  detail::kit_error(entry, what);
  detail::save_report();
}

void session_finished() {
  detail::judge_remaining_examples();
  run_finished = true;
  detail::save_report();
}

// Where a crash or the runner's time-out writes the case in flight: a file in the judge's
// own folder (LABKIT_INFLIGHT), opened before anything runs. Never the output, which the
// code under test shares and could fake.
int inflight_file = 2;

// Fatal signals and the runner's SIGTERM on a time-out: name the input, then die as asked.
extern "C" void on_fatal_signal(int signal) {
  if (inflight_length > 0) {
    ssize_t ignored = write(inflight_file, inflight, inflight_length);
    (void)ignored;
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// GMP meets a NaN or an infinity by raising SIGFPE and then aborting (its
// __gmp_invalid_operation). kernel.h's checks stop the numbers they see first; any other
// way a non-finite number reaches exact arithmetic (an implicit conversion in CGAL's lazy
// numbers) ends here. Raised by a call (si_code <= 0), it is synchronous, inside a judge
// (detail::Judging), so it is thrown back to run_judge as oracle::NotFinite: that case
// fails, and the judge's process lives. A fault of the processor (an integer division by
// zero) is the kit's own crash, reported as ever.
void on_floating_point_signal(int signal, siginfo_t* info, void*) {
  if (info->si_code <= 0 && detail::judging > 0) throw oracle::NotFinite();
  on_fatal_signal(signal);
}

void install_signal_handlers() {
  if (const char* path = std::getenv(variable::inflight); path && *path) {
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd >= 0) inflight_file = fd;
  }
  // Its own stack, so that a stack overflow can still be reported.
  static char alternate_stack[1 << 16];
  stack_t stack{};
  stack.ss_sp = alternate_stack;
  stack.ss_size = sizeof alternate_stack;
  sigaltstack(&stack, nullptr);
  for (int s : {SIGSEGV, SIGBUS, SIGILL, SIGABRT, SIGTERM, SIGXCPU}) {
    struct sigaction action {};
    action.sa_handler = on_fatal_signal;
    action.sa_flags = SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    sigaction(s, &action, nullptr);
  }
  // On the thread's own stack, and not blocked while it runs: it may leave by throwing.
  struct sigaction action {};
  action.sa_sigaction = on_floating_point_signal;
  action.sa_flags = SA_SIGINFO | SA_NODEFER;
  sigemptyset(&action.sa_mask);
  sigaction(SIGFPE, &action, nullptr);
}

}  // namespace report

}  // namespace labkit::check

namespace labkit::check {

namespace {
Domain& the_domain() {
  static Domain d;
  return d;
}
}  // namespace

void domain(const Domain& d) { the_domain() = d; }
const Domain& domain() { return the_domain(); }

bool in_domain_scale(double s) {
  const Domain& d = the_domain();
  return std::isfinite(s) && (s == 0 || (s >= d.low && s <= d.high));
}

bool in_domain(const codec::Values& v) {
  const Domain& d = the_domain();
  if (d.of == Domain::Of::scale) return in_domain_scale(v.largest_length());
  const auto inside = [&d](double x) { return x == 0 || (std::abs(x) >= d.low && std::abs(x) <= d.high); };
  for (std::size_t i = 0; i < v.numbers.size(); ++i)
    if (v.kinds[i] == codec::Kind::length && (!std::isfinite(v.numbers[i]) || !inside(v.numbers[i]))) return false;
  return true;
}

bool counts_something(const std::string& field) {
  for (const char* word : {"count", "tests", "steps", "iterations", "size", "pieces", "nodes", "births", "survivors",
                           "bounces", "particles", "pairs", "halvings", "times asked"})
    if (field.find(word) != std::string::npos) return true;
  return false;
}

Expect::Expect(std::string rule) : rule_(std::move(rule)) {}

void Expect::add(const std::string& field, const std::string& got, const std::string& expected, bool ok,
                 const std::string& why) {
  expected_ += (expected_.empty() ? "" : ", ") + field + " = " + expected;
  got_ += (got_.empty() ? "" : ", ") + field + " = " + got;
  if (ok) return;
  if (!failed_) why_ = why.empty() ? rule_ + ": " + field + " differs from the answer" : why;
  failed_ = true;
}

namespace {

std::string with_cause(std::string line, const std::string& cause) {
  return cause.empty() ? line : line + "; " + cause;
}

bool whole(double x) { return x >= 2 && x <= 1e6 && std::abs(x - std::round(x)) <= 1e-9 * x; }

// "3 times", "1/3 of", "sqrt(2) times": a ratio a person recognises, or "".
std::string factor_words(double ratio) {
  if (whole(ratio)) return fmt(std::round(ratio)) + " times";
  if (ratio > 0 && whole(1 / ratio)) return "1/" + fmt(std::round(1 / ratio)) + " of";
  if (whole(ratio * ratio)) return "sqrt(" + fmt(std::round(ratio * ratio)) + ") times";
  if (ratio > 0 && whole(1 / (ratio * ratio))) return "1/sqrt(" + fmt(std::round(1 / (ratio * ratio))) + ") of";
  return "";
}

}  // namespace

std::string likely_cause(double got, double expected, double tolerance) {
  if (!std::isfinite(got)) return "yours is not a finite number";
  if (std::abs(got - expected) <= tolerance) return "";
  if (std::abs(expected) > tolerance && std::abs(got + expected) <= tolerance) return "yours has the opposite sign";
  if (std::abs(got) <= tolerance) return "yours is 0";
  if (std::abs(expected) <= tolerance) return "";
  const double ratio = got / expected;
  if (const std::string f = factor_words(std::abs(ratio)); !f.empty())
    return "yours is " + f + " the answer" + (ratio < 0 ? ", with the opposite sign" : "") +
           ": a factor left in or out (a length such as |n|, a 2, a mass)?";
  return "";
}

std::string likely_cause(const Vec3& got, const Vec3& expected, double tolerance) {
  if (!got.allFinite()) return "yours is not finite";
  if ((got - expected).norm() <= tolerance) return "";
  const double g = got.norm(), x = expected.norm();
  if (x > tolerance && (got + expected).norm() <= tolerance)
    return "yours points the opposite way: a sign, or a difference taken the other way round?";
  if (g <= tolerance) return "yours is the zero vector";
  if (x <= tolerance) return "";
  if (got.cross(expected).norm() <= tolerance * x && got.dot(expected) > 0) {
    if (std::abs(g - x) <= 1e-6 * x) return "";
    const std::string f = factor_words(g / x);
    return "yours has the right direction but " + (f.empty() ? fmt(g / x) + " times" : f) + " the length";
  }
  // The two causes below read a shape in the difference: not in one of rounding's size.
  if ((got - expected).norm() < 1e-3 * x) return "";
  Vec3 a = got.cwiseAbs(), b = expected.cwiseAbs();
  std::sort(a.data(), a.data() + 3);
  std::sort(b.data(), b.data() + 3);
  if ((a - b).norm() <= tolerance)
    return "yours has the answer's components in another order or with other signs: a swap, or a row taken "
           "for a column?";
  if (std::abs(g - x) <= tolerance)
    return "yours has the right length in another direction: a turn applied twice, the wrong way, or not undone "
           "(a frame)?";
  return "";
}

void Expect::near(const std::string& field, double got, double expected, double tolerance) {
  const double off = std::abs(got - expected);
  const bool ok = off <= tolerance;
  if (!ok) misses_.push_back({field, Vec3(got, 0, 0), Vec3(expected, 0, 0), tolerance, true});
  add(field, fmt(got), fmt(expected), ok,
      with_cause(rule_ + ": " + field + " is off by " + fmt(off) + " (tolerance " + fmt(tolerance) + ")",
                 likely_cause(got, expected, tolerance)));
}

void Expect::near(const std::string& field, const Vec3& got, const Vec3& expected, double tolerance) {
  const double off = (got - expected).norm();
  const bool ok = off <= tolerance;
  if (!ok) misses_.push_back({field, got, expected, tolerance, false});
  add(field, fmt(got), fmt(expected), ok,
      with_cause(rule_ + ": " + field + " is off by " + fmt(off) + " (tolerance " + fmt(tolerance) + ")",
                 likely_cause(got, expected, tolerance)));
}

void Expect::that(const std::string& field, bool ok, const std::string& got, const std::string& expected,
                  const std::string& why) {
  add(field, got, expected, ok, why);
}

// Two fields that each hold the other's answer were swapped, whatever else is wrong: that
// is said first.
Outcome Expect::outcome() const {
  if (!failed_) return pass();
  for (std::size_t i = 0; i < misses_.size(); ++i)
    for (std::size_t j = i + 1; j < misses_.size(); ++j) {
      const Miss &p = misses_[i], &q = misses_[j];
      const double tol = std::max(p.tolerance, q.tolerance);
      if (p.scalar == q.scalar && (p.got - q.expected).norm() <= tol && (q.got - p.expected).norm() <= tol)
        return fail(
            expected_, got_,
            rule_ + ": " + p.field + " and " + q.field + " are swapped: yours has each one's answer in the other");
    }
  return fail(expected_, got_, why_);
}

Outcome verdict(bool got, bool expected, bool doubt, Rules rules, const std::string& yes, const std::string& no) {
  if (rules == Rules::exact) doubt = false;
  if (got == expected) return doubt ? ambiguous() : pass();
  if (doubt) return ambiguous();
  return fail(expected ? yes : no, got ? yes : no,
              rules == Rules::exact ? "this degenerate input has an exact answer (see the header's rules)"
                                    : "the exact answer is stable here: no input within 1e-9 S answers otherwise");
}

}  // namespace labkit::check
