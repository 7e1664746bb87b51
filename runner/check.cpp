#include "check.h"
#include "kit.h"
#include "terminal.h"
#include "untrusted.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace runner {

namespace {

using term::bold;
using term::dim;
using term::green;
using term::red;
using term::yellow;

std::string coloured_status(Status s) {
  const std::string word = status_word(s);
  switch (s) {
    case Status::passed: return green(word);
    case Status::not_implemented: return yellow(word);
    default: return red(word);
  }
}

std::string counts(const StepResult& r) {
  if (r.status == Status::not_implemented || r.status == Status::not_built) return "";
  std::string s;
  if (r.examples) s += std::to_string(r.examples) + " examples";
  if (r.random_cases) s += std::string(s.empty() ? "" : ", ") + std::to_string(r.random_cases) + " random";
  if (r.ambiguous) s += " (" + std::to_string(r.ambiguous) + " ambiguous)";
  return dim(s);
}

// A report's text, as the terminal may show it (the code under test wrote it).
std::string shown(const std::string& text) { return term::indent(safe_text(text), "            "); }

// A token longer than a report line (a mesh of hundreds of triangles) is kept in a file
// under build/cases/ and named by a short handle, @query-hash, which ./labkit check and
// ./labkit view read back: the why line stays in sight. A short token is its own handle.
std::string handle_of(const std::string& build, const std::string& token) {
  constexpr std::size_t kLongest = 160;
  if (token.size() <= kLongest) return shell_quote(token);
  char hash[9];
  std::snprintf(hash, sizeof hash, "%08x", unsigned(std::hash<std::string>{}(token)&0xffffffffu));
  // The query names the file; a token the code under test printed (a crash's in-flight
  // marker) may hold other characters in its query than the kit's names: those become _.
  std::string name = token.substr(0, token.find(':')) + "-" + hash;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.' && c != '-') c = '_';
  std::error_code ignored;
  std::filesystem::create_directories(build + "/cases", ignored);
  std::ofstream(build + "/cases/" + name) << token;
  return "@" + name;
}

// The commands that replay a case; none for a token the harness never writes (the code
// under test printed or wrote it).
void print_replay(const Lab& lab, const std::string& token, const std::string& build) {
  if (!is_replay_token(token)) {
    std::cout << "  replay    none (the case reported is not a replay token the kit writes)\n";
    return;
  }
  const std::string handle = handle_of(build, token);
  std::cout << "  replay    " << bold("./labkit check " + lab.id + " --case " + handle) << "\n";
  std::cout << "  see it    ./labkit view " << lab.id << " --case " << handle << "\n";
}

void print_failure(const Failure& f, const std::string& query, const Lab& lab, const std::string& build) {
  std::cout << safe_text(labkit::report::format(f, query, "  "));
  if (!f.replay.empty()) print_replay(lab, f.replay, build);
}

// What gdb printed about the answerer (--debug), in short.
// What gdb prints when the code it runs is stopped by a signal.
constexpr const char* kGdbStopped = "Program received signal";

void print_debugger(const std::string& output) {
  const auto at = output.find(kGdbStopped);
  if (at == std::string::npos) {
    std::cout << "  debugger  the code did not crash under gdb\n";
    return;
  }
  // The signal, the line it stopped on, then the backtrace's frames in the lab's own
  // files (the kit's frames below them only say how the call arrived). The backtrace
  // ends at its first line that is not a frame: what follows is the tests' own output.
  std::istringstream in(output.substr(at));
  std::string line, lines;
  bool frames = false;
  for (int n = 0; std::getline(in, line) && n < 60; ++n) {
    const bool frame = line.rfind("#", 0) == 0;
    if (frames && !frame) break;
    frames = frames || frame;
    if (frame && line.find("/common/protocol/") != std::string::npos) break;
    if (!frame || line.find("/labs/") != std::string::npos || line.find("/src/") != std::string::npos)
      lines += line + "\n";
  }
  std::cout << "  debugger  " << shown(lines) << "\n";
}

void print_details(const StepResult& r, const Lab& lab, const Paths& paths) {
  const Step& step = *r.step;
  std::cout << "\n"
            << bold("Lab " + lab.id + ", step " + std::to_string(step.number) + " (" + step.tag + ", " + step.title +
                    "): ") +
                   coloured_status(r.status)
            << "\n";
  if (abnormal(r.status)) {
    std::cout << "  what      " << safe_text(r.detail) << "\n";
    if (!r.inflight.empty()) {
      const Programs programs{paths.build + "/" + lab.judge_binary(), paths.build + "/" + lab.answerer("student")};
      // Its output may have faked the in-flight marker: only a real token is described.
      if (is_replay_token(r.inflight))
        std::cout << "  on input  " << shown(describe_token(programs, lab, r.inflight)) << "\n";
      print_replay(lab, r.inflight, paths.build);
    }
    const std::string tail =
        r.run.output.size() > 1200 ? r.run.output.substr(r.run.output.size() - 1200) : r.run.output;
    if (!tail.empty()) std::cout << dim("  its last output:\n    " + term::indent(safe_text(tail), "    ")) << "\n";
    return;
  }
  for (const QueryResult& q : r.queries) {
    if (!q.error.empty()) {
      std::cout << "  " << safe_text(q.query) << ": " << safe_text(q.error) << "\n";
      return;
    }
    if (q.failure && q.not_implemented.empty()) {
      print_failure(*q.failure, q.query, lab, paths.build);
      return;
    }
  }
  for (const TestCaseResult& t : r.test_cases)
    if (!t.passed && !t.failures.empty()) {
      std::cout << "  test      " << safe_text(t.name) << "\n  failure   " << shown(t.failures.front()) << "\n";
      return;
    }
  if (r.status == Status::no_tests)
    std::cout << "  The kit's test program has no test tagged [lab" << lab.id << "][step" << step.number
              << "]: grading/manifest.json and the tests disagree.\n";
}

}  // namespace

namespace {

// A build's progress on stderr, from Ninja's "[12/135] Building CXX object ..." lines:
// how far it is, for how long, and what it is building. On a terminal one line is
// rewritten in place and cleared at the end; in a log, a line every 15 seconds
// (none for a build shorter than that).
class BuildProgress {
 public:
  BuildProgress() : terminal_(isatty(2) != 0), start_(std::chrono::steady_clock::now()) {}
  ~BuildProgress() {
    if (shown_ && terminal_) std::cerr << "\r\033[K" << std::flush;
  }
  void operator()(const char* data, std::size_t size) {
    pending_.append(data, size);
    for (std::size_t end; (end = pending_.find('\n')) != std::string::npos; pending_.erase(0, end + 1))
      line(pending_.substr(0, end));
  }

 private:
  void line(const std::string& text) {
    // "[N/M] Building CXX object common/CMakeFiles/labkit_oracle.dir/oracle/boxes.cpp.o"
    if (text.size() < 5 || text[0] != '[' || text.find("Re-checking globbed") != std::string::npos) return;
    const std::size_t close = text.find("] ");
    if (close == std::string::npos) return;
    std::string what = text.substr(close + 2);
    for (const char* verb : {"Building CXX object ", "Linking CXX executable ", "Linking CXX static library "})
      if (what.rfind(verb, 0) == 0) what = (verb[0] == 'L' ? "linking " : "") + what.substr(std::strlen(verb));
    // common/CMakeFiles/labkit_oracle.dir/oracle/boxes.cpp.o -> common/oracle/boxes.cpp
    const std::size_t dir = what.find("CMakeFiles/");
    const std::size_t inner = dir == std::string::npos ? dir : what.find(".dir/", dir);
    if (inner != std::string::npos) what = what.substr(0, dir) + what.substr(inner + 5);
    if (what.size() > 2 && what.compare(what.size() - 2, 2, ".o") == 0) what.resize(what.size() - 2);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (!terminal_ && seconds < last_ + 15) return;
    last_ = seconds;
    shown_ = true;
    std::ostringstream out;
    out << "labkit: building " << text.substr(0, close + 1) << " " << int(seconds) / 60 << "m"
        << (int(seconds) % 60 < 10 ? "0" : "") << int(seconds) % 60 << "s  " << what;
    std::string shown = out.str();
    if (terminal_ && shown.size() > 99) shown = shown.substr(0, 96) + "...";
    std::cerr << (terminal_ ? "\r\033[K" : "") << shown << (terminal_ ? "" : "\n") << std::flush;
  }

  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::string pending_;
  bool shown_ = false;
  double last_ = 0;
};

}  // namespace

std::string build_targets(const Paths& paths, const std::vector<std::string>& targets, bool* ok, bool keep_going) {
  Limits limits;
  limits.seconds = 3600;
  limits.kept_bytes = 1 << 20;
  std::vector<std::string> argv = {"cmake", "--build", paths.build, "--target"};
  argv.insert(argv.end(), targets.begin(), targets.end());
  if (keep_going) argv.insert(argv.end(), {"--", "-k", "0"});
  BuildProgress progress;
  const Run run = runner::run(argv, {}, limits, "", std::ref(progress));
  *ok = run.ok();
  return *ok ? "" : first_errors(run.output, paths.source);
}

std::vector<StepResult> run_steps(const Programs& programs, const Lab& lab, const std::vector<const Step*>& steps,
                                  const StepOptions& options, int jobs) {
  std::vector<StepResult> results(steps.size());
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i; (i = next++) < steps.size();) results[i] = run_step(programs, lab, *steps[i], options);
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < std::max(1, jobs); ++k) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  return results;
}

std::string describe_token(const Programs& programs, const Lab& lab, const std::string& token) {
  StepOptions options;
  options.replay = token;
  options.describe_only = true;
  options.limits.seconds = 30;
  for (const Step& step : lab.steps) {
    const StepResult r = run_step(programs, lab, step, options);
    for (const QueryResult& q : r.queries)
      if (q.failure && !q.failure->input.empty()) return q.failure->input;
  }
  return token;
}

namespace {

// "core path (steps 1, 2, 3, 6; about 160 min): 2 of 4 pass; extensions: steps 4, 5",
// or "done with the core ...": what finishing the lab's one-session path means.
std::string core_summary(const Lab& lab, const std::vector<StepResult>& results) {
  std::string core, extensions;
  int core_steps = 0, core_passing = 0;
  for (const Step& s : lab.steps) {
    std::string& list = s.core ? core : extensions;
    list += (list.empty() ? "" : ", ") + std::to_string(s.number);
  }
  for (const StepResult& r : results)
    if (r.step->core) ++core_steps, core_passing += r.status == Status::passed;
  const std::string path = "the core path (steps " + core + ", about " + std::to_string(lab.core_minutes()) + " min)";
  const std::string rest = extensions.empty() ? "" : "; the extensions: steps " + extensions;
  if (core_steps > 0 && core_passing == core_steps) return "done with " + path + ": every core step passes" + rest;
  return path + ": " + std::to_string(core_passing) + " of " + std::to_string(core_steps) + " pass" + rest;
}

}  // namespace

namespace {

// The labs asked for (all the kit has when none is named), or none after saying on stderr
// why the request cannot be run.
std::optional<std::vector<const Lab*>> labs_asked(const Manifest& manifest, const Paths& paths,
                                                  const CheckOptions& options) {
  std::vector<const Lab*> labs;
  for (const std::string& id : options.labs) {
    const Lab* lab = manifest.find(id.size() == 1 ? "0" + id : id);
    if (!lab) {
      std::string known;
      for (const Lab& l : manifest.labs) known += (known.empty() ? "" : ", ") + l.id;
      std::cerr << "labkit check: there is no lab '" << id << "'; the labs are " << known << "\n";
      return std::nullopt;
    }
    labs.push_back(lab);
  }
  // All labs: those the kit has (the manifest may list labs still being written).
  if (labs.empty())
    for (const Lab& l : manifest.labs)
      if (std::filesystem::is_directory(paths.source + "/labs/" + l.stem())) labs.push_back(&l);
  if (!options.replay.empty() && labs.size() != 1) {
    std::cerr << "labkit check: --case replays one lab's case; name the lab, e.g. ./labkit check 02 --case '...'\n";
    return std::nullopt;
  }
  if (!options.replay.empty() && !is_replay_token(options.replay)) {
    std::cerr << "labkit check: a case looks like 'query:1,2,3' (copy it from a failure report); got '"
              << safe_text(options.replay.substr(0, 60)) << "'\n";
    return std::nullopt;
  }
  if (options.debug && options.replay.empty()) {
    std::cerr << "labkit check: --debug replays one case under gdb; add the --case a failure report printed\n";
    return std::nullopt;
  }
  for (const Lab* lab : labs)
    if (options.step != 0 &&
        std::none_of(lab->steps.begin(), lab->steps.end(), [&](const Step& s) { return s.number == options.step; })) {
      std::cerr << "labkit check: lab " << lab->id << " has no step " << options.step << "\n";
      return std::nullopt;
    }
  return labs;
}

StepOptions step_options_for(const CheckOptions& options) {
  StepOptions o;
  o.seed = options.seed;
  o.cases = options.cases;
  o.replay = options.replay;
  o.debugger = options.debug;
  if (options.debug) o.call_seconds = 120;  // gdb reads the program's symbols first
  o.limits.seconds = options.timeout;
  o.limits.memory_bytes = std::size_t(4) << 30;
  return o;
}

// --case: the one replayed case's verdict, or why it could not be replayed. The exit code.
int report_replay(const std::vector<StepResult>& results, const Lab& lab, const Paths& paths,
                  const CheckOptions& options) {
  for (const StepResult& r : results)
    for (const QueryResult& q : r.queries) {
      if (!q.error.empty()) {
        std::cerr << "labkit check: " << safe_text(q.error) << "\n";
        return 2;
      }
      if (q.cases == 0) continue;
      std::cout << "  replayed " << safe_text(q.query) << " (step " << r.step->number << ", " << r.step->tag << "): ";
      if (!q.failure) {
        std::cout << green(q.ambiguous ? "passes (an ambiguous case: any answer is accepted)" : "passes") << "\n";
        return 0;
      }
      std::cout << red("fails") << "\n";
      Failure f = *q.failure;
      // Under gdb the judge sees gdb's exit, not the crash, and gdb's output as the
      // code's: the debugger's own lines below are the explanation.
      if (options.debug && r.run.output.find(kGdbStopped) != std::string::npos)
        f.why = "your code did not answer this call under the debugger: its report below says why and where";
      print_failure(f, q.query, lab, paths.build);
      if (options.debug) print_debugger(r.run.output);
      return 1;
    }
  for (const StepResult& r : results)
    if (r.status != Status::passed && r.status != Status::failing) {
      print_details(r, lab, paths);
      return 1;
    }
  std::cerr << "labkit check: no step of lab " << lab.id << " has the query '"
            << options.replay.substr(0, options.replay.find(':')) << "'\n";
  return 2;
}

// What the table adds up to: steps shown and passing, the failing ones to explain below
// it, and where to go next.
struct Tally {
  int total = 0, passing = 0;
  std::string next_step;
  std::vector<std::pair<const Lab*, StepResult>> to_explain;
  std::string not_begun;  // the labs shown without their checker ("01, 02")
};

// A lab's rows: each step with its tier, status and counts (a passing step's notes under
// it), then the core path's progress.
void print_rows(const Lab& lab, const std::vector<StepResult>& results, std::size_t title_width, const Paths& paths,
                Tally& tally) {
  const StepResult* next = nullptr;  // the first core step that does not pass, else extension
  for (const StepResult& r : results) {
    ++tally.total;
    const Step& s = *r.step;
    std::cout << "  " << term::pad(std::to_string(s.number), 3) << term::pad(s.tag, 7)
              << term::pad(s.core ? "core" : "extension", 11) << term::pad(s.title, title_width)
              << term::pad(coloured_status(r.status), 22) << counts(r) << "\n";
    if (r.status == Status::passed) {
      ++tally.passing;
      for (const QueryResult& q : r.queries)
        for (const std::string& note : q.notes) std::cout << dim("       " + safe_text(note)) << "\n";
      continue;
    }
    if (r.status != Status::not_implemented) tally.to_explain.push_back({&lab, r});
    if (!next || (s.core && !next->step->core)) next = &r;
  }
  if (results.size() > 1) std::cout << dim("  " + core_summary(lab, results)) << "\n";
  if (!next || !tally.next_step.empty()) return;
  const Step& s = *next->step;
  tally.next_step = "lab " + lab.id + " step " + std::to_string(s.number) + " (" + s.tag + ", " +
                    (s.core ? "core" : "an extension") + "): " + lab.handout_of(s) + ", \"Step " +
                    std::to_string(s.number) + "\"";
  // A step begun but failing: its hints are one command away (handouts/hints/).
  if (next->status != Status::not_implemented && std::filesystem::exists(paths.source + "/" + lab.hints()))
    tally.next_step += "; stuck? ./labkit hint " + lab.id + " " + std::to_string(s.number);
}

// A lab is begun once its file answers anything: before that, ./labkit check shows its
// steps "not implemented yet" without building its checker (the judge, the generators,
// the tests: most of a first build), and builds it the first time the lab is checked
// after one of its functions answers. So a new student's first table comes after the
// runner and the seven files are built. True when the answerer's probe (calls.h) says
// that every function the lab lists threw NotImplemented.
bool not_begun(const std::string& answerer) {
  Limits limits;
  limits.seconds = 10;
  limits.memory_bytes = std::size_t(1) << 31;
  limits.kept_bytes = 16 * 1024;
  const Run run = runner::run({answerer, "--probe"}, {}, limits);
  const std::string marker = "labkit-probe: ";
  const std::size_t at = run.output.rfind(marker);
  return run.ok() && at != std::string::npos &&
         run.output.compare(at + marker.size(), std::string::npos, "not implemented\n") == 0;
}

// What the probe found of the labs whose checker is not built yet (LABKIT_PROBE_ONLY=1,
// kit.runner's test of this, treats every checker as not built yet): the labs not begun,
// and those whose file does not compile, with the compiler's errors (the checker of
// either is not built).
struct Probed {
  std::vector<const Lab*> not_begun;
  std::map<const Lab*, std::string> not_compiling;
  bool unbegun(const Lab* lab) const { return std::find(not_begun.begin(), not_begun.end(), lab) != not_begun.end(); }
  bool skips(const Lab* lab) const { return unbegun(lab) || not_compiling.count(lab); }
};

Probed probe_labs(const Paths& paths, const std::vector<const Lab*>& labs, const CheckOptions& options) {
  Probed probed;
  if (!options.replay.empty()) return probed;
  const char* probe_only = std::getenv("LABKIT_PROBE_ONLY");
  std::vector<const Lab*> unbuilt;
  std::vector<std::string> answerers;
  for (const Lab* lab : labs)
    if ((probe_only && std::string(probe_only) == "1") ||
        !std::filesystem::exists(paths.build + "/" + lab->judge_binary())) {
      unbuilt.push_back(lab);
      answerers.push_back(lab->answerer(options.implementation));
    }
  if (unbuilt.empty()) return probed;
  bool built = false;
  build_targets(paths, answerers, &built, true);
  for (const Lab* lab : unbuilt) {
    // Built above, or not: this says which, with the errors (a file that failed keeps its
    // last good program, which must not be probed).
    const std::string errors = build_targets(paths, {lab->answerer(options.implementation)}, &built);
    if (!built)
      probed.not_compiling[lab] = errors;
    else if (not_begun(paths.build + "/" + lab->answerer(options.implementation)))
      probed.not_begun.push_back(lab);
  }
  return probed;
}

// Says which labs' checkers are about to be built for the first time, and what it costs.
void announce_checkers(const Paths& paths, const std::vector<const Lab*>& labs) {
  std::string ids;
  int count = 0;
  for (const Lab* lab : labs)
    if (!std::filesystem::exists(paths.build + "/" + lab->judge_binary()))
      ids += std::string(count++ ? ", " : "") + lab->id;
  if (count > 0)
    std::cerr << "labkit: building " << (count == 1 ? "the checker of lab " : "the checkers of labs ") << ids
              << ", once (under a minute a lab on a quiet 2-core machine; the first also builds what all checkers "
                 "share: about a minute and a half)\n";
}

// Every begun lab's programs in one build first, so that all cores stay busy from the
// first file to the last; a lab that does not compile is built again later, alone, for
// its errors (and the other labs' programs are ready by then).
void build_begun(const Paths& paths, const std::vector<const Lab*>& labs, const Probed& probed,
                 const std::string& implementation) {
  std::vector<const Lab*> begun;
  std::vector<std::string> targets;
  for (const Lab* lab : labs)
    if (!probed.skips(lab)) {
      begun.push_back(lab);
      targets.insert(targets.end(), {lab->judge_binary(), lab->answerer(implementation)});
    }
  if (begun.size() < 2) return;
  announce_checkers(paths, begun);
  bool built = false;
  build_targets(paths, targets, &built, true);
}

// "Lab 02  Segment against triangle   handouts/02_segment_triangle.md", above its rows.
void print_lab_heading(const Lab& lab) {
  std::cout << "\n" << bold("Lab " + lab.id + "  " + lab.title) << dim("   " + lab.handout()) << "\n";
}

// A lab not begun: its steps, each "not implemented yet", with no checker run.
void print_not_begun(const Lab& lab, const std::vector<const Step*>& steps, std::size_t title_width, const Paths& paths,
                     Tally& tally) {
  print_lab_heading(lab);
  std::vector<StepResult> results(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    results[i].status = Status::not_implemented;
    results[i].step = steps[i];
  }
  print_rows(lab, results, title_width, paths, tally);
  tally.not_begun += (tally.not_begun.empty() ? "" : ", ") + lab.id;
}

// Below the table: the labs not begun, the count of passing steps, and the next step.
void print_summary(const Tally& tally, std::chrono::steady_clock::time_point start) {
  if (!tally.not_begun.empty())
    std::cout << "\n"
              << dim("Not begun: lab " + tally.not_begun +
                     " (each function still throws the stub's NotImplemented). A lab's checker is built, once, "
                     "the first time one of its functions answers.")
              << "\n";
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream took;
  took.precision(2);
  took << std::fixed << seconds;
  std::cout << "\n"
            << bold(std::to_string(tally.passing) + " of " + std::to_string(tally.total) + " steps pass")
            << dim(" (" + took.str() + " s)");
  if (!tally.next_step.empty()) std::cout << ". Next: " << tally.next_step;
  std::cout << "\n";
}

}  // namespace

int check(const Paths& paths, const CheckOptions& options) {
  const Manifest manifest = load_manifest(paths.source + "/grading/manifest.json");
  const std::optional<std::vector<const Lab*>> asked = labs_asked(manifest, paths, options);
  if (!asked) return 2;
  const std::vector<const Lab*>& labs = *asked;
  const StepOptions step_options = step_options_for(options);
  const int jobs = options.jobs > 0 ? options.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  const bool replaying = !options.replay.empty();
  const auto start = std::chrono::steady_clock::now();

  // The title column fits the longest title shown.
  std::size_t title_width = 40;
  for (const Lab* lab : labs)
    for (const Step& s : lab->steps)
      if (options.step == 0 || s.number == options.step) title_width = std::max(title_width, s.title.size() + 2);
  if (!replaying)
    std::cout << bold("labkit check")
              << dim(": " + std::string(options.cases ? std::to_string(options.cases) : "the default") +
                     " random cases per query, seed " + (options.seed.empty() ? "public" : options.seed))
              << "\n";

  const Probed probed = probe_labs(paths, labs, options);
  build_begun(paths, labs, probed, options.implementation);

  Tally tally;
  for (const Lab* lab : labs) {
    std::vector<const Step*> steps;
    for (const Step& s : lab->steps)
      if (options.step == 0 || s.number == options.step) steps.push_back(&s);
    if (probed.unbegun(lab)) {
      print_not_begun(*lab, steps, title_width, paths, tally);
      continue;
    }
    bool built = false;
    std::string errors;
    if (const auto broken = probed.not_compiling.find(lab); broken != probed.not_compiling.end()) {
      errors = broken->second;
    } else {
      announce_checkers(paths, {lab});
      errors = build_targets(paths, {lab->judge_binary(), lab->answerer(options.implementation)}, &built);
    }
    if (!replaying || !built) print_lab_heading(*lab);
    if (!built) {
      std::cout << "  " << red("does not compile") << ": every step of this lab fails until it does.\n\n    "
                << term::indent(safe_text(errors), "    ") << "\n";
      tally.total += int(steps.size());
      if (tally.next_step.empty()) tally.next_step = "make lab " + lab->id + " compile (the errors above)";
      continue;
    }
    const Programs programs{paths.build + "/" + lab->judge_binary(),
                            paths.build + "/" + lab->answerer(options.implementation)};
    const std::vector<StepResult> results = run_steps(programs, *lab, steps, step_options, jobs);
    if (replaying) return report_replay(results, *lab, paths, options);
    print_rows(*lab, results, title_width, paths, tally);
  }

  for (const auto& [lab, r] : tally.to_explain) print_details(r, *lab, paths);
  print_summary(tally, start);
  return tally.passing == tally.total ? 0 : 1;
}

}  // namespace runner
