#include "mutant.h"

#include "manifest.h"
#include "step.h"

#include "common/protocol/report.h"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace runner {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// The first thing `./labkit check` explains for a step that does not pass: the block a
// student reads, and the line in it that must name the concept.
struct FirstFailure {
  std::string block;
  std::string why;
  std::string expected;  // "field = value, ..." for a field-by-field check
};

// A why line that only names a field and a number ("normal is off by 2 (tolerance
// 1e-12)", "closest0 is 1 from the rectangle", "tests differs") teaches nothing: once the
// field names, the numbers and the words of a comparison are taken out, a why that states
// a rule has words left.
bool field_and_number_alone(const std::string& why, const std::string& expected) {
  static const std::set<std::string> comparison = {
      "is",        "are",   "off",  "by",    "differs", "differ", "from",     "the", "answer",
      "tolerance", "yours", "not",  "a",     "an",      "of",     "and",      "to",  "at",
      "than",      "times", "more", "fewer", "less",    "wrong",  "expected", "got", "value"};
  std::set<std::string> fields;
  const auto words = [](const std::string& text) {
    std::vector<std::string> w;
    std::string word;
    for (char c : text + " ") {
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.') {
        word += char(std::tolower(static_cast<unsigned char>(c)));
      } else if (!word.empty()) {
        w.push_back(word);
        word.clear();
      }
    }
    return w;
  };
  for (std::size_t start = 0; start < expected.size();) {
    const std::size_t end = std::min(expected.find(", ", start), expected.size());
    const std::string item = expected.substr(start, end - start);
    if (const std::size_t eq = item.find(" = "); eq != std::string::npos)
      for (const std::string& w : words(item.substr(0, eq))) fields.insert(w);
    start = end + 2;
  }
  int left = 0;
  for (const std::string& w : words(why)) {
    const bool number = std::isdigit(static_cast<unsigned char>(w[0])) ||
                        (w.size() > 1 && w[0] == '.' && std::isdigit(static_cast<unsigned char>(w[1])));
    if (!number && !comparison.count(w) && !fields.count(w)) ++left;
  }
  return left < 3;
}

FirstFailure first_failure(const StepResult& r) {
  if (abnormal(r.status)) return {status_word(r.status) + ": " + r.detail, r.detail, {}};
  for (const QueryResult& q : r.queries) {
    if (!q.error.empty()) return {q.query + ": " + q.error, q.error, {}};
    if (q.failure && q.not_implemented.empty())
      return {labkit::report::format(*q.failure, q.query, "    "), q.failure->why, q.failure->expected};
  }
  for (const TestCaseResult& t : r.test_cases)
    if (!t.passed && !t.failures.empty()) return {"test " + t.name + ": " + t.failures.front(), t.failures.front(), {}};
  return {status_word(r.status), status_word(r.status), {}};
}

}  // namespace

int mutant(const Paths& paths, const MutantOptions& options) {
  const Manifest manifest = load_manifest(paths.source + "/grading/manifest.json");
  const Lab* lab = manifest.find(options.lab);
  if (!lab) throw std::runtime_error("there is no lab '" + options.lab + "'");
  const std::string who =
      "mutant " + options.name + " of lab " + lab->id + " (a step " + std::to_string(options.step) + " mistake)";
  const Programs programs{paths.build + "/" + lab->judge_binary(),
                          paths.build + "/" + lab->answerer("mutant_" + options.name)};
  StepOptions step_options;
  step_options.limits.seconds = 300;
  step_options.limits.memory_bytes = std::size_t(4) << 30;

  for (const Step& step : lab->steps) {
    if (step.number > options.step) break;
    const StepResult r = run_step(programs, *lab, step, step_options);
    if (r.status == Status::passed) {
      if (step.number < options.step) continue;
      std::cout << who << ": step " << step.number << " passes; its tests do not catch this mistake\n";
      return 1;
    }
    const FirstFailure f = first_failure(r);
    if (step.number < options.step) {
      std::cout << who << ": step " << step.number << " (" << status_word(r.status)
                << ") fails first, so a student is sent to the wrong step. Its first failure:\n"
                << f.block << "\n";
      return 1;
    }
    std::vector<std::string> missing;
    for (const std::string& word : options.says)
      if (lower(f.why).find(lower(word)) == std::string::npos) missing.push_back("'" + word + "'");
    std::cout << who << ": step " << step.number << " " << status_word(r.status) << ". First failure:\n"
              << f.block << "\n";
    if (options.says.empty()) {
      std::cout << who << " names no concept words (the quoted words of its `// mutant` line in the reference)\n";
      return 1;
    }
    if (field_and_number_alone(f.why, f.expected)) {
      std::cout << who << ": the why of its first failure names a field and a number alone: it must state the "
                << "rule the answer broke (in the judge, or as the rule of its check::Expect)\n";
      return 1;
    }
    if (!missing.empty()) {
      std::string list;
      for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
      std::cout << who << ": the why of its first failure does not say " << list
                << ": it must name the concept the mistake breaks\n";
      return 1;
    }
    return 0;
  }
  std::cout << who << ": lab " << lab->id << " has no step " << options.step << "\n";
  return 1;
}

}  // namespace runner
