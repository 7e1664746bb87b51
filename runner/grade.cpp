#include "grade.h"
#include "assignment.h"
#include "budget.h"
#include "cgroup.h"
#include "class_report.h"
#include "common/text.h"
#include "feedback.h"
#include "gradebook.h"
#include "lab_build.h"
#include "results.h"
#include "sandbox.h"
#include "seed.h"
#include "submission.h"
#include "terminal.h"
#include "untrusted.h"
#include "work_queue.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

namespace runner {

namespace fs = std::filesystem;

double step_score(const Step& step, const StepResult& result) {
  if (result.status == Status::passed) return step.points;
  if (!step.partial || (result.status != Status::failing && result.status != Status::not_implemented)) return 0;
  return std::max(0.0, std::min(step.points - 0.01, std::floor(step.points * result.fraction_passed * 100) / 100));
}

namespace {

struct Context {
  Context(const Paths& p, const GradeOptions& o)
      : paths(p),
        options(o),
        sandbox(Sandbox::make(o.sandbox, {p.source + "/common", p.build}, p.source)),
        step_memory_mb(o.memory_mb) {}

  const Paths& paths;
  const GradeOptions& options;
  std::vector<const Lab*> labs;
  std::map<const Lab*, LabRecipe> recipes;
  Sandbox sandbox;
  GradingRun run;
  std::string work;            // scratch root, removed at the end
  int jobs = 1;                // workers: processes at once
  std::size_t step_memory_mb;  // each step's memory: --memory, or less to fit the envelope
};

// A graded step's options; `seed` is the submission's own for the lab (seed.h), "" for
// the public cases.
StepOptions graded_step_options(const std::string& folder, const Context& c, const std::string& seed) {
  StepOptions options;
  options.seed = seed;
  options.cases = c.options.cases;
  options.hide_seed = true;
  options.count_all = true;
  options.limits.seconds = c.options.timeout;
  options.limits.memory_bytes = c.step_memory_mb << 20;
  options.limits.file_bytes = std::size_t(64) << 20;
  options.limits.flood_bytes = std::size_t(16) << 20;
  // One call's limit: a tenth of the step's, at most 5 s, so that a loop costs its case
  // and the step still ends within its own limit.
  options.call_seconds = std::clamp(c.options.timeout / 10, 0.5, 5.0);
  options.sandbox = &c.sandbox;
  options.scratch_parent = folder;
  return options;
}

// What a step or lab the budget never reached says.
const char* const kNoTime =
    "not graded: the submission's time budget ran out before it (the report's time budget line says what used it)";

// A lab of a submission before anything is known of it: every step waiting.
LabGrade pending_lab(const Lab& lab) {
  LabGrade g;
  g.lab = &lab;
  for (const Step& s : lab.steps) {
    g.max_score += s.points;
    StepGrade sg;
    sg.step = &s;
    g.steps.push_back(sg);
  }
  return g;
}

// A lab that earns nothing, for the reason given: missing, not compiling, or the grader's
// own trouble.
void close_lab(LabGrade& g, LabGrade::State state, const std::string& why, const std::string& feedback) {
  g.state = state;
  g.build_output = why;
  for (StepGrade& s : g.steps) {
    s.feedback = feedback;
    s.graded = true;
  }
}

// Identical files are built once in a run: in a class, the labs that many students left
// as the stub (or handed in twice) compile once. The key is the files' whole contents,
// so that two different files can never share an entry.
struct BuildCache {
  struct Entry {
    bool done = false;
    LabBuild build;
    double seconds = 0;
    double limit = 0;  // what its compiles and link were given: less than kBuildSeconds when a budget was short
    std::vector<std::function<void(const Entry&)>> waiting;  // builds of the same files, meanwhile
  };
  std::mutex mutex;
  std::map<std::string, std::shared_ptr<Entry>> entries;
  int folders = 0;
};

// One submission while it is graded.
struct Graded {
  std::string path, name, work;  // work: its scratch folder
  Submission sub;
  SubmissionGrade grade;
  std::vector<std::string> folders;  // per lab: where its steps run
  std::vector<std::string> seeds;    // per lab: its cases' seed, from the secret and its files (seed.h)
  Budget budget;                     // its processes' wall clock
  std::mutex mutex;                  // grade, open
  std::mutex writing;                // its results.json, written as its tasks end
  int open = 0;                      // its tasks queued or running
  std::chrono::steady_clock::time_point start;
};

// The whole run: every submission's reading, builds and steps on one queue of `jobs`
// workers (work_queue.h), the earliest submission's first.
class Grader {
 public:
  Grader(Context& c, std::vector<std::unique_ptr<Graded>>& all, std::function<void(Graded&)> finished)
      : c_(c), all_(all), finished_(std::move(finished)) {}

  void run() {
    for (std::size_t i = 0; i < all_.size(); ++i) {
      Graded& g = *all_[i];
      g.grade.name = g.name;
      g.grade.source = g.path;
      for (const Lab* lab : c_.labs) g.grade.labs.push_back(pending_lab(*lab));
      for (const LabGrade& l : g.grade.labs) g.grade.max_score += l.max_score;
      g.open = 1;
      queue_.add({i, 0, 0}, [this, i] { task(i, [&] { read(i); }); });
    }
    queue_.run(c_.jobs);
  }

  // The results so far of a submission not finished yet, as results.json shows them.
  static SubmissionGrade so_far(Graded& g) {
    std::lock_guard<std::mutex> lock(g.mutex);
    SubmissionGrade s = g.grade;
    for (const LabGrade& l : s.labs)
      for (const StepGrade& step : l.steps) s.score += step.score;
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - g.start).count();
    return s;
  }

  std::function<void(Graded&)> progress;  // after each of a submission's tasks

 private:
  // Runs one of submission i's tasks; the last one to end finishes the submission.
  template <class Work> void task(std::size_t i, Work&& work) {
    Graded& g = *all_[i];
    work();
    if (progress) progress(g);
    bool last;
    {
      std::lock_guard<std::mutex> lock(g.mutex);
      last = --g.open == 0;
    }
    if (last) finish(g);
  }

  void add(std::size_t i, WorkQueue::Key key, std::function<void()> work) {
    {
      std::lock_guard<std::mutex> lock(all_[i]->mutex);
      ++all_[i]->open;
    }
    queue_.add(key, [this, i, work = std::move(work)] { task(i, work); });
  }

  void read(std::size_t i) {
    Graded& g = *all_[i];
    g.start = std::chrono::steady_clock::now();
    try {
      fs::create_directories(g.work);
      fs::permissions(g.work, fs::perms(0711));
      g.sub = read_submission(g.path, c_.labs, g.work, c_.sandbox);
      g.seeds.assign(c_.labs.size(), "");
      g.budget.set(c_.options.budget);
      for (const Lab* lab : c_.labs) {
        g.folders.push_back(g.work + "/lab" + lab->id);
        fs::create_directories(g.folders.back());
        fs::permissions(g.folders.back(), fs::perms(0711));
      }
    } catch (const std::exception& e) {  // the grader's own trouble (a file system error)
      g.sub = Submission{};
      g.sub.error = std::string("the grader could not read it: ") + e.what();
      g.folders.clear();
    }
    {
      std::lock_guard<std::mutex> lock(g.mutex);
      g.grade.error = g.sub.error;
      g.grade.notes = g.sub.notes;
      if (g.sub.files.empty() && g.sub.error.empty())
        g.grade.notes.push_back(g.sub.notes.empty()
                                    ? "the submission holds none of the files a student edits"
                                    : "no file a student edits could be graded (the notes above say why)");
    }
    for (std::size_t l = 0; l < c_.labs.size(); ++l) {
      if (g.folders.empty()) {
        std::lock_guard<std::mutex> lock(g.mutex);
        close_lab(g.grade.labs[l], LabGrade::State::not_built, g.sub.error, g.sub.error);
        continue;
      }
      add(i, {i, l + 1, 0}, [this, i, l] { build(i, l); });
    }
  }

  // A lab's files in a submission: where each is, its text, and the build cache's key
  // (the lab and the files' whole contents); `missing` names those it lacks.
  struct LabFiles {
    std::map<std::string, std::string> paths, contents;
    std::string key, missing;
  };
  static LabFiles lab_files(const Graded& g, const Lab& lab) {
    LabFiles files;
    files.key = lab.id;
    for (const std::string& f : lab.student_files) {
      const auto found = g.sub.files.find(f);
      if (found == g.sub.files.end()) {
        files.missing += (files.missing.empty() ? "" : ", ") + f;
        continue;
      }
      files.paths[f] = found->second;
      const std::string text = files.contents[f] = labkit::read_file(found->second);
      files.key += '\0' + f + '\0' + std::to_string(text.size()) + '\0' + text;
    }
    return files;
  }

  // Builds a cache entry's lab in `folder` within `limit` seconds, then runs what waited
  // for it (other submissions with the same files).
  void build_into(BuildCache::Entry& entry, const Lab& lab, const LabFiles& files, const std::string& folder,
                  double limit) {
    const auto start = std::chrono::steady_clock::now();
    try {
      fs::create_directories(folder);
      fs::permissions(folder, fs::perms(0711));
      entry.build = build_lab(c_.paths, lab, c_.recipes.at(&lab), files.paths, folder, c_.sandbox, limit);
    } catch (const std::exception& e) {
      entry.build = LabBuild{};
      entry.build.errors = std::string("the grader could not build it: ") + e.what();
    }
    entry.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    entry.limit = limit;
    std::vector<std::function<void(const BuildCache::Entry&)>> waiting;
    {
      std::lock_guard<std::mutex> lock(cache_.mutex);
      entry.done = true;
      waiting.swap(entry.waiting);
      // Cut short by this submission's budget, not by its files: the next submission
      // with the same files builds them again.
      if (entry.build.timed_out && limit < kBuildSeconds) cache_.entries.erase(files.key);
    }
    for (auto& then : waiting) then(entry);
  }

  void build(std::size_t i, std::size_t l) {
    Graded& g = *all_[i];
    const Lab& lab = *c_.labs[l];
    const LabFiles files = lab_files(g, lab);
    const std::string& missing = files.missing;
    if (!missing.empty()) {
      std::lock_guard<std::mutex> lock(g.mutex);
      const std::string why = "The submission has no " + missing + ".";
      close_lab(g.grade.labs[l], LabGrade::State::missing, why, "not graded: " + why);
      return;
    }
    // A build's time comes out of the budget: what is left, at most kBuildSeconds; a build
    // shared with another submission costs what it took, as if this one had run it.
    const double limit = g.budget.take(kBuildSeconds);
    if (limit <= 0) {
      std::lock_guard<std::mutex> lock(g.mutex);
      close_lab(g.grade.labs[l], LabGrade::State::out_of_time, kNoTime, kNoTime);
      for (StepGrade& s : g.grade.labs[l].steps) s.status = Status::out_of_time;
      return;
    }
    const std::string what = "lab " + lab.id + " build";
    // Its own cases: another file (a resubmission) draws others, the same files the same.
    if (!c_.options.seed.empty()) {
      const std::string seed = submission_seed(c_.options.seed, lab.id, files.contents);
      std::lock_guard<std::mutex> lock(g.mutex);
      g.seeds[l] = seed;
    }
    std::shared_ptr<BuildCache::Entry> entry;
    std::string folder;
    {
      std::lock_guard<std::mutex> lock(cache_.mutex);
      auto& found = cache_.entries[files.key];
      if (found && !found->done) {  // the same files are being built: their steps follow that build
        {
          std::lock_guard<std::mutex> held(g.mutex);
          ++g.open;
        }
        g.budget.spend(limit, 0, what);
        found->waiting.push_back([this, i, l, what](const BuildCache::Entry& e) {
          task(i, [&] {
            all_[i]->budget.spend(0, e.seconds, what);
            built(i, l, e);
          });
        });
        return;
      }
      if (!found) {
        found = std::make_shared<BuildCache::Entry>();
        folder = c_.work + "/builds/" + std::to_string(cache_.folders++);
      }
      entry = found;
    }
    if (!folder.empty()) build_into(*entry, lab, files, folder, limit);
    g.budget.spend(limit, entry->seconds, what);
    built(i, l, *entry);
  }

  void built(std::size_t i, std::size_t l, const BuildCache::Entry& e) {
    Graded& g = *all_[i];
    {
      std::lock_guard<std::mutex> lock(g.mutex);
      LabGrade& lab = g.grade.labs[l];
      lab.build_seconds = e.seconds;
      if (!e.build.ok && e.build.timed_out && e.limit < kBuildSeconds) {
        const std::string why = "not graded: the submission's time budget ran out while this lab was built (it had " +
                                points(e.limit) + " s left)";
        close_lab(lab, LabGrade::State::out_of_time, why, why);
        for (StepGrade& s : lab.steps) s.status = Status::out_of_time;
        g.budget.ran_out();
        return;
      }
      if (!e.build.ok) {
        close_lab(lab, LabGrade::State::not_built, e.build.errors,
                  "does not compile: every step of this lab scores 0 until it does.");
        return;
      }
      lab.state = LabGrade::State::graded;
    }
    for (std::size_t k = 0; k < g.grade.labs[l].steps.size(); ++k)
      add(i, {i, l + 1, k + 1}, [this, i, l, k, binary = e.build.binary] { step(i, l, k, binary); });
  }

  void step(std::size_t i, std::size_t l, std::size_t k, const std::string& binary) {
    Graded& g = *all_[i];
    const Lab& lab = *c_.labs[l];
    const Step& step = lab.steps[k];
    const Programs programs{c_.paths.build + "/" + lab.judge_binary(), binary};
    const std::string what = "lab " + lab.id + " step " + std::to_string(step.number);
    // Its limit: its own, or what is left of the submission's budget when that is less.
    const double limit = g.budget.take(c_.options.timeout);
    if (limit <= 0) {
      StepGrade s;
      s.step = &step;
      s.graded = true;
      s.status = Status::out_of_time;
      s.feedback = kNoTime;
      std::lock_guard<std::mutex> lock(g.mutex);
      g.grade.labs[l].steps[k] = s;
      return;
    }
    StepResult r;
    try {
      StepOptions options = graded_step_options(g.folders[l], c_, g.seeds[l]);
      options.limits.seconds = limit;
      r = run_step(programs, lab, step, options);
    } catch (const std::exception& e) {
      r.step = &step;
      r.status = Status::crashed;
      r.detail = std::string("the grader could not run it: ") + e.what();
    }
    g.budget.spend(limit, r.run.seconds, what);
    StepGrade s;
    s.step = &step;
    s.graded = true;
    s.status = r.status;
    s.seconds = r.run.seconds;
    s.score = step_score(step, r);
    s.ambiguous = r.ambiguous;
    for (const QueryResult& q : r.queries) s.cases += q.cases;
    if (r.status == Status::timed_out && limit < c_.options.timeout) {  // the budget's limit, not the step's
      g.budget.ran_out();
      s.status = Status::out_of_time;
      s.feedback = "not graded: the submission's time budget ran out during this step (it had " + points(limit) +
                   " s left of its own " + points(c_.options.timeout) +
                   " s; the report's time budget line says what used it)";
    } else {
      const StepOptions describe =
          graded_step_options(fs::path(programs.answerer).parent_path().string(), c_, g.seeds[l]);
      s.feedback = feedback(r, lab, programs, describe, g.budget);
      s.why = first_why(r);
    }
    std::lock_guard<std::mutex> lock(g.mutex);
    g.grade.labs[l].steps[k] = s;
  }

  void finish(Graded& g) {
    SubmissionGrade& s = g.grade;
    s.score = 0;
    for (LabGrade& l : s.labs) {
      l.score = 0;
      for (const StepGrade& step : l.steps) l.score += step.score;
      s.score += l.score;
    }
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - g.start).count();
    s.budget = g.budget.total();
    s.budget_used = g.budget.used();
    s.budget_note = g.budget.note();
    std::error_code ignored;
    for (const std::string& folder : g.folders) fs::remove_all(folder, ignored);
    finished_(g);
  }

  Context& c_;
  std::vector<std::unique_ptr<Graded>>& all_;
  std::function<void(Graded&)> finished_;
  WorkQueue queue_;
  BuildCache cache_;
};

// What no output may show of a submission: the secret and the seeds drawn from it.
std::vector<std::string> secrets_of(Graded& g, const std::string& secret) {
  std::vector<std::string> all = {secret};
  std::lock_guard<std::mutex> lock(g.mutex);
  for (const std::string& seed : g.seeds)
    if (!seed.empty()) all.push_back(seed);
  return all;
}

// The class's own files in OUT, beside a folder per submission.
const std::vector<std::string> kClassFiles = class_files();

// Removes the scratch root however grading ends.
struct RemovedAtEnd {
  std::string path;
  ~RemovedAtEnd() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

// A whole file or nothing: written beside, then renamed over the old one, so that a
// reader (Gradescope after a time-out) never finds half of it.
void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  const fs::path part = path.string() + ".part";
  {
    std::ofstream out(part, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
  fs::rename(part, path);
}

void write_results(const SubmissionGrade& g, const fs::path& folder, const Context& c) {
  write_file(folder / "results.json", gradescope_results(g, c.run).dump(2) + "\n");
  write_file(folder / "junit.xml", junit_xml(g));
  write_file(folder / "report.txt", table(g, c.run));
  write_file(folder / "steps.tsv", steps_tsv(g));
}

// Workers and each step's memory within the envelope this process runs in. Each worker
// runs one compile or one step at a time (a compile of a lab's file takes about 300 MB,
// a step's program what the student's code allocates); the grader and the kit's judges
// keep the rest.
void fit_envelope(Context& c, const Envelope& envelope) {
  constexpr std::size_t kKeptMb = 256, kWorkerMb = 512;
  c.jobs = c.options.jobs > 0 ? c.options.jobs : std::max(1, int(std::lround(envelope.cpus)));
  c.step_memory_mb = c.options.memory_mb;
  if (envelope.memory_bytes > 0) {
    const std::size_t usable =
        (envelope.memory_bytes >> 20) > kKeptMb + 64 ? (envelope.memory_bytes >> 20) - kKeptMb : 64;
    if (c.options.jobs <= 0) c.jobs = std::max(1, std::min<int>(c.jobs, int(usable / kWorkerMb)));
    c.step_memory_mb = std::max<std::size_t>(64, std::min(c.step_memory_mb, usable / std::size_t(c.jobs)));
  }
  std::ostringstream limits;
  limits << points(c.options.timeout) << " s and " << c.step_memory_mb << " MB per step; " << points(c.options.budget)
         << " s for a submission's compiles and steps together; " << c.jobs << (c.jobs == 1 ? " worker" : " workers")
         << " in " << envelope.description;
  c.run.limits = limits.str();
  if (c.step_memory_mb < c.options.memory_mb)
    std::cerr << "labkit grade: each step may use " << c.step_memory_mb << " MB, not " << c.options.memory_mb
              << ": the grader runs in " << envelope.description << "\n";
}

// The labs asked for that the kit builds; a lab in the manifest and labs/ whose build the
// kit has no record of (its labkit_add_lab line still commented) is named, not graded.
std::vector<const Lab*> labs_to_grade(const Paths& paths, const Manifest& manifest, const GradeOptions& options) {
  std::vector<const Lab*> labs;
  for (const Lab& lab : manifest.labs) {
    const bool wanted =
        options.labs.empty() || std::find_if(options.labs.begin(), options.labs.end(), [&](const std::string& id) {
                                  return id == lab.id || "0" + id == lab.id || id == lab.stem();
                                }) != options.labs.end();
    if (!wanted || !fs::is_directory(paths.source + "/labs/" + lab.stem())) continue;  // a lab not written yet
    if (!fs::exists(recipe_record(paths, lab))) {
      std::cerr << "labkit grade: lab " << lab.id << " is in grading/manifest.json and labs/, but the kit's build has "
                << "no record of it (is its labkit_add_lab line in CMakeLists.txt?): not graded\n";
      continue;
    }
    labs.push_back(&lab);
  }
  return labs;
}

// What every report says of the run: its seed, cases, assignment, sandbox and limits, and
// how to grade one submission again; a missing or short secret is warned of.
void describe_run(Context& c, const Assignment& assignment) {
  const GradeOptions& options = c.options;
  c.run.seed_kind = options.seed.empty() ? "public" : "secret";
  if (!options.seed.empty()) {
    c.run.regrade = "./labkit grade <this submission> --seed <your secret>";
    if (options.cases != kGradingCases) c.run.regrade += " --cases " + std::to_string(options.cases);
    if (options.timeout != 60) c.run.regrade += " --timeout " + points(options.timeout);
    if (options.budget != kGradingBudget) c.run.regrade += " --budget " + points(options.budget);
  }
  c.run.cases = options.cases;
  c.run.assignment = assignment.name;
  c.run.sandbox = c.sandbox.description();
  fit_envelope(c, own_envelope());
  if (options.seed.empty())
    std::cerr << "labkit grade: no secret seed (--seed or LABKIT_GRADING_SEED): grading on the public cases, "
                 "which students can see and hard-code\n";
  else if (options.seed.size() < 8)
    std::cerr << "labkit grade: a secret seed this short can be guessed; use a long phrase\n";
}

// The scratch root: in $TMPDIR when it is set, as for any program, else in /tmp.
std::string make_scratch() {
  const char* tmp = std::getenv("TMPDIR");
  std::string work_template = std::string(tmp && *tmp == '/' ? tmp : "/tmp") + "/labkit-grade.XXXXXX";
  if (!mkdtemp(work_template.data())) throw std::runtime_error("cannot make a scratch folder in " + work_template);
  fs::permissions(work_template, fs::perms(0711));
  return work_template;
}

// A class's own files: class.csv, gradebook.csv and the class page.
void write_class_files(const std::vector<SubmissionGrade>& grades, const Context& c, const Assignment& assignment,
                       const std::optional<Roster>& roster, double seconds) {
  const fs::path out(c.options.out);
  write_file(out / "class.csv", class_csv(grades));
  const Gradebook book = gradebook_csv(grades, assignment.name, roster ? &*roster : nullptr);
  write_file(out / "gradebook.csv", book.csv);
  for (const std::string& note : book.notes) std::cerr << "labkit grade: gradebook.csv: " << note << "\n";
  const std::string page = write_class_page(grades, c.run, c.options.out, seconds, c.work + "/plots");
  std::cout << "\n"
            << term::bold("Class") << ": " << grades.size() << " submissions graded in " << points(seconds)
            << " s with " << c.jobs << (c.jobs == 1 ? " worker" : " workers") << "; " << (out / "class.csv").string()
            << ", gradebook.csv, " << page << "\n";
}

// Grades every submission found, writing each one's results as it ends; true when every
// result could be written. The grades in `grades`, in the order found.
bool grade_all(Context& c, const Submissions& found, std::vector<SubmissionGrade>& grades) {
  const bool single = !found.a_class;
  std::vector<std::unique_ptr<Graded>> all;
  for (std::size_t i = 0; i < found.paths.size(); ++i) {
    all.push_back(std::make_unique<Graded>());
    all.back()->path = found.paths[i];
    all.back()->name = submission_name(found.paths[i]);
    all.back()->work = c.work + "/" + std::to_string(i);
  }
  const auto folder_of = [&](const Graded& g) {
    return single ? fs::path(c.options.out) : fs::path(c.options.out) / g.name;
  };
  std::mutex print;
  std::atomic<bool> trouble{false};  // the grader's own: results it could not write
  Grader grader(c, all, [&](Graded& g) {
    make_presentable(g.grade, secrets_of(g, c.options.seed));
    std::string unwritten;
    try {
      write_results(g.grade, folder_of(g), c);
    } catch (const std::exception& e) {
      unwritten = e.what();
      trouble = true;
    }
    std::lock_guard<std::mutex> lock(print);
    if (!unwritten.empty()) std::cerr << "labkit grade: " << safe_line(unwritten) << "\n";
    std::cout << (single ? "" : "\n") << table(g.grade, c.run) << std::flush;
  });
  // results.json as each step ends: a time-out of the whole run keeps every finished step.
  grader.progress = [&](Graded& g) {
    std::lock_guard<std::mutex> lock(g.writing);
    SubmissionGrade now = Grader::so_far(g);
    make_presentable(now, secrets_of(g, c.options.seed));
    try {
      write_file(folder_of(g) / "results.json", gradescope_results(now, c.run).dump(2) + "\n");
    } catch (const std::exception&) {  // said once, when the final write fails too
    }
  };
  grader.run();
  grades.clear();
  for (const auto& g : all) grades.push_back(g->grade);
  return !trouble;
}

}  // namespace

int grade(const Paths& paths, const GradeOptions& options) {
  if (options.submissions.empty()) {
    std::cerr << "labkit grade: name at least one submission (a folder, a .zip or a .tar.gz)\n";
    return 2;
  }
  Assignment assignment = options.assignment.empty() ? Assignment{} : parse_assignment(options.assignment);
  const Manifest manifest = restrict_to(load_manifest(paths.source + "/grading/manifest.json"), assignment);
  const std::optional<Roster> roster =
      options.roster.empty() ? std::nullopt : std::optional<Roster>(load_roster(options.roster));
  Context c(paths, options);
  c.labs = labs_to_grade(paths, manifest, options);
  if (c.labs.empty()) {
    std::cerr << "labkit grade: no lab to grade (the kit has none of those asked for)\n";
    return 2;
  }
  // Before any work: a class whose names clash is not graded at all.
  const Submissions found = find_submissions(options.submissions, c.labs, kClassFiles);
  if (!found.error.empty()) {
    std::cerr << "labkit grade: " << found.error << "\n";
    return 2;
  }
  for (const std::string& line : found.classes) std::cerr << "labkit grade: " << line << "\n";
  for (const Lab* lab : c.labs) c.recipes[lab] = load_recipe(paths, *lab);
  describe_run(c, assignment);
  c.work = make_scratch();
  const RemovedAtEnd scratch{c.work};

  const auto start = std::chrono::steady_clock::now();
  std::vector<SubmissionGrade> grades;
  const bool written = grade_all(c, found, grades);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (found.a_class)
    write_class_files(grades, c, assignment, roster, seconds);
  else
    std::cout << "\nResults: " << (fs::path(options.out) / "results.json").string()
              << ", junit.xml, report.txt, steps.tsv\n";
  if (!written) std::cerr << "labkit grade: the grader had trouble of its own (above, or in a submission's results)\n";
  return written ? 0 : 1;
}

}  // namespace runner
