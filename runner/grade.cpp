#include "grade.h"
#include "lab_build.h"
#include "results.h"
#include "sandbox.h"
#include "submission.h"
#include "terminal.h"
#include "untrusted.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
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
  const Paths& paths;
  const GradeOptions& options;
  std::vector<const Lab*> labs;
  std::map<const Lab*, LabRecipe> recipes;
  Sandbox sandbox;
  GradingRun run;
  std::string work;  // scratch root, removed at the end
};

// The secret never appears in what is written, even if the code under test found it.
std::string redact(std::string text, const std::string& secret) {
  if (secret.size() < 6) return text;
  for (std::size_t at; (at = text.find(secret)) != std::string::npos;) text.replace(at, secret.size(), "[secret]");
  return text;
}

// Everything a student controls in a grade, as it may be written and shown: never the
// secret (even if the code under test found it), and safe text (untrusted.h). The one
// place this happens: every result file and the terminal get a grade through it.
void make_presentable(SubmissionGrade& g, const std::string& secret) {
  const auto presentable = [&](std::string& text) { text = safe_text(redact(text, secret)); };
  presentable(g.name);
  presentable(g.source);
  presentable(g.error);
  for (std::string& note : g.notes) presentable(note);
  for (LabGrade& l : g.labs) {
    presentable(l.build_output);
    for (StepGrade& s : l.steps) presentable(s.feedback);
  }
}

// The last `n` bytes of `text`, from the start of a character: a tail cut in the middle
// of one would begin with a broken character.
std::string tail(const std::string& text, std::size_t n) {
  if (text.size() <= n) return text;
  std::size_t from = text.size() - n;
  for (int k = 0; k < 3 && from < text.size() && (static_cast<unsigned char>(text[from]) & 0xC0) == 0x80; ++k) ++from;
  return "..." + text.substr(from);
}

// The command that replays a case, or why there is none: a token the harness never
// writes (the code under test printed or wrote it) never becomes a command.
std::string replay_line(const Lab& lab, const std::string& token) {
  const std::string command = replay_command("check", lab.id, token);
  return "replay    " + (command.empty() ? "none (the case it reported is not a replay token the kit writes)" : command) + "\n";
}

StepOptions graded_step_options(const std::string& folder, const Context& c) {
  StepOptions options;
  options.seed = c.options.seed;
  options.cases = c.options.cases;
  options.hide_seed = true;
  options.count_all = true;
  options.limits.seconds = c.options.timeout;
  options.limits.memory_bytes = c.options.memory_mb << 20;
  options.limits.file_bytes = std::size_t(64) << 20;
  options.limits.flood_bytes = std::size_t(16) << 20;
  // One call's limit: a tenth of the step's, at most 5 s, so that a loop costs its case
  // and the step still ends within its own limit.
  options.call_seconds = std::clamp(c.options.timeout / 10, 0.5, 5.0);
  options.sandbox = &c.sandbox;
  options.scratch_parent = folder;
  return options;
}

// What the student reads about one step: the verdict, the counts, the first failure and
// how to replay it with the public kit.
std::string feedback(const StepResult& r, const Lab& lab, const Programs& programs, const Context& c) {
  std::ostringstream out;
  int cases = 0, passed = 0;
  for (const QueryResult& q : r.queries) {
    cases += q.cases;
    passed += q.passed + q.ambiguous;
  }
  out << status_word(r.status);
  if (r.status == Status::passed || r.status == Status::failing)
    out << ": " << passed << " of " << cases << " cases pass" << (r.ambiguous ? " (" + std::to_string(r.ambiguous) + " of them ambiguous: any answer is accepted there)" : "");
  out << "\n";
  if (abnormal(r.status)) {
    out << "what      " << r.detail << "\n";
    if (!r.inflight.empty() && !is_replay_token(r.inflight)) {
      out << replay_line(lab, r.inflight);  // its output faked the marker: no input to describe
    } else if (!r.inflight.empty()) {
      // Describing runs no code under test; it keeps the graded limits all the same.
      StepOptions describe = graded_step_options(fs::path(programs.answerer).parent_path().string(), c);
      describe.replay = r.inflight;
      describe.describe_only = true;
      describe.count_all = false;
      describe.limits.seconds = 30;
      std::string input = r.inflight;
      const StepResult d = run_step(programs, lab, *r.step, describe);
      for (const QueryResult& q : d.queries)
        if (q.failure && !q.failure->input.empty()) input = q.failure->input;
      out << "on input  " << term::indent(input, "          ") << "\n";
      out << replay_line(lab, r.inflight);
    }
    if (r.status == Status::crashed || r.status == Status::exited_early || r.status == Status::out_of_memory) {
      const std::string last = tail(r.run.output, 800);
      if (!last.empty()) out << "its last output:\n" << last << "\n";
    }
    return out.str();
  }
  for (const QueryResult& q : r.queries) {
    if (!q.error.empty()) {
      out << q.query << ": " << q.error << "\n";
      break;
    }
    if (q.failure && q.not_implemented.empty()) {
      const Failure& f = *q.failure;
      out << labkit::report::format(f, q.query, "");
      if (!f.replay.empty()) out << replay_line(lab, f.replay);
      break;
    }
  }
  return out.str();
}

// Calls work(0) ... work(count - 1), `jobs` at a time.
template <class Work>
void parallel_for(std::size_t count, int jobs, Work&& work) {
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i; (i = next++) < count;) work(i);
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < std::max(1, std::min<int>(jobs, int(count))); ++k) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
}

// The lab's files found and built; `binary` is its answer program when it built.
LabGrade build_one_lab(const Lab& lab, const Submission& sub, const std::string& folder, const Context& c,
                       std::string* binary) {
  LabGrade g;
  g.lab = &lab;
  for (const Step& s : lab.steps) {
    g.max_score += s.points;
    StepGrade sg;
    sg.step = &s;
    g.steps.push_back(sg);
  }
  std::map<std::string, std::string> files;
  std::string missing;
  for (const std::string& f : lab.student_files) {
    const auto found = sub.files.find(f);
    if (found == sub.files.end()) missing += (missing.empty() ? "" : ", ") + f;
    else files[f] = found->second;
  }
  if (!missing.empty()) {
    g.state = LabGrade::State::missing;
    g.build_output = "The submission has no " + missing + ".";
    for (StepGrade& s : g.steps) s.feedback = "not graded: " + g.build_output;
    return g;
  }
  const auto start = std::chrono::steady_clock::now();
  const LabBuild build = build_lab(c.paths, lab, c.recipes.at(&lab), files, folder, c.sandbox);
  g.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!build.ok) {
    g.state = LabGrade::State::not_built;
    g.build_output = build.errors;
    for (StepGrade& s : g.steps) s.feedback = "does not compile: every step of this lab scores 0 until it does.";
    return g;
  }
  *binary = build.binary;
  return g;
}


// Every lab built at once, then every step of every lab, `jobs` processes at a time:
// a lab's build or step never waits for another lab's.
SubmissionGrade grade_one(const std::string& path, const std::string& name, const std::string& work, int jobs,
                          const Context& c) {
  const auto start = std::chrono::steady_clock::now();
  SubmissionGrade g;
  g.name = name;
  g.source = path;
  fs::create_directories(work);
  fs::permissions(work, fs::perms(0711));
  const Submission sub = read_submission(path, c.labs, work, c.sandbox);
  g.error = sub.error;
  g.notes = sub.notes;
  if (sub.files.empty() && sub.error.empty())
    g.notes.push_back(sub.notes.empty() ? "the submission holds none of the files a student edits"
                                        : "no file a student edits could be graded (the notes above say why)");

  const std::size_t n = c.labs.size();
  std::vector<std::string> folders(n), binaries(n);
  g.labs.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    folders[i] = work + "/lab" + c.labs[i]->id;
    fs::create_directories(folders[i]);
    fs::permissions(folders[i], fs::perms(0711));
  }
  parallel_for(n, jobs, [&](std::size_t i) {
    try {
      g.labs[i] = build_one_lab(*c.labs[i], sub, folders[i], c, &binaries[i]);
    } catch (const std::exception& e) {  // the grader's own trouble (a file system error): this lab only
      binaries[i].clear();
      g.labs[i] = build_one_lab(*c.labs[i], Submission{}, folders[i], c, &binaries[i]);
      g.labs[i].state = LabGrade::State::not_built;
      g.labs[i].build_output = std::string("the grader could not build it: ") + e.what();
    }
  });

  std::vector<std::pair<std::size_t, std::size_t>> tasks;  // (lab, step)
  for (std::size_t i = 0; i < n; ++i)
    if (!binaries[i].empty())
      for (std::size_t k = 0; k < g.labs[i].steps.size(); ++k) tasks.push_back({i, k});
  parallel_for(tasks.size(), jobs, [&](std::size_t t) {
    const auto [i, k] = tasks[t];
    const Lab& lab = *c.labs[i];
    StepGrade& s = g.labs[i].steps[k];
    StepResult r;
    const Programs programs{c.paths.build + "/" + lab.judge_binary(), binaries[i]};
    try {
      r = run_step(programs, lab, *s.step, graded_step_options(folders[i], c));
    } catch (const std::exception& e) {
      r.step = s.step;
      r.status = Status::crashed;
      r.detail = std::string("the grader could not run it: ") + e.what();
    }
    s.status = r.status;
    s.seconds = r.run.seconds;
    s.score = step_score(*s.step, r);
    s.ambiguous = r.ambiguous;
    for (const QueryResult& q : r.queries) s.cases += q.cases;
    s.feedback = feedback(r, lab, programs, c);
  });

  for (std::size_t i = 0; i < n; ++i) {
    for (const StepGrade& s : g.labs[i].steps) g.labs[i].score += s.score;
    g.score += g.labs[i].score;
    g.max_score += g.labs[i].max_score;
    std::error_code ignored;
    fs::remove_all(folders[i], ignored);  // its objects and answer program
  }
  g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return g;
}

// A grade of 0 for a submission the grader itself could not grade (a file system error),
// with the same labs as every other, so that class.csv keeps its columns.
SubmissionGrade ungraded(const std::string& path, const std::string& name, const std::string& why, const Context& c) {
  SubmissionGrade g;
  g.name = name;
  g.source = path;
  g.error = why;
  for (const Lab* lab : c.labs) {
    LabGrade l;
    l.lab = lab;
    l.state = LabGrade::State::not_built;
    l.build_output = why;
    for (const Step& step : lab->steps) {
      StepGrade s;
      s.step = &step;
      s.feedback = why;
      l.steps.push_back(s);
      l.max_score += step.points;
    }
    g.max_score += l.max_score;
    g.labs.push_back(l);
  }
  return g;
}

// The class's own files in OUT, beside a folder per submission.
const std::vector<std::string> kClassFiles = {"class.csv"};

// Removes the scratch root however grading ends.
struct RemovedAtEnd {
  std::string path;
  ~RemovedAtEnd() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_results(const SubmissionGrade& g, const fs::path& folder, const Context& c) {
  write_file(folder / "results.json", gradescope_results(g, c.run).dump(2) + "\n");
  write_file(folder / "junit.xml", junit_xml(g));
  write_file(folder / "report.txt", table(g, c.run));
  write_file(folder / "steps.tsv", steps_tsv(g));
}

}  // namespace

int grade(const Paths& paths, const GradeOptions& options) {
  if (options.submissions.empty()) {
    std::cerr << "labkit grade: name at least one submission (a folder, a .zip or a .tar.gz)\n";
    return 2;
  }
  const Manifest manifest = load_manifest(paths.source + "/grading/manifest.json");
  Context c{paths, options, {}, {}, Sandbox::make(options.sandbox, {paths.source + "/common", paths.build}, paths.source), {}, {}};
  for (const Lab& lab : manifest.labs) {
    const bool wanted = options.labs.empty() ||
                        std::find_if(options.labs.begin(), options.labs.end(), [&](const std::string& id) {
                          return id == lab.id || "0" + id == lab.id || id == lab.stem();
                        }) != options.labs.end();
    if (!wanted || !fs::is_directory(paths.source + "/labs/" + lab.stem())) continue;  // a lab not written yet
    // A lab whose folder exists but which the kit does not build yet (its labkit_add_lab
    // line is still commented) cannot be graded: said once, and the others are.
    if (!fs::exists(recipe_record(paths, lab))) {
      std::cerr << "labkit grade: lab " << lab.id << " is in grading/manifest.json and labs/, but the kit's build has "
                << "no record of it (is its labkit_add_lab line in CMakeLists.txt?): not graded\n";
      continue;
    }
    c.labs.push_back(&lab);
  }
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
  c.run.seed_kind = options.seed.empty() ? "public" : "secret";
  c.run.cases = options.cases;
  c.run.sandbox = c.sandbox.description();
  if (options.seed.empty())
    std::cerr << "labkit grade: no secret seed (--seed or LABKIT_GRADING_SEED): grading on the public cases, "
                 "which students can see and hard-code\n";
  else if (options.seed.size() < 8)
    std::cerr << "labkit grade: a secret seed this short can be guessed; use a long phrase\n";

  char work_template[] = "/tmp/labkit-grade.XXXXXX";
  if (!mkdtemp(work_template)) throw std::runtime_error("cannot make a scratch folder in /tmp");
  c.work = work_template;
  const RemovedAtEnd scratch{c.work};
  fs::permissions(c.work, fs::perms(0711));

  const std::vector<std::string>& submissions = found.paths;
  std::vector<std::string> names;
  for (const std::string& path : submissions) names.push_back(submission_name(path));
  const bool single = !found.a_class;
  const int jobs = options.jobs > 0 ? options.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  // Several submissions share the processes out one each; one submission uses them all.
  const int outer = std::min<int>(jobs, int(submissions.size()));
  const int inner = std::max(1, jobs / outer);

  std::vector<SubmissionGrade> grades(submissions.size());
  std::mutex print;
  std::atomic<bool> trouble{false};  // the grader's own: a submission it could not grade, results it could not write
  const auto start = std::chrono::steady_clock::now();
  // One submission's trouble is its own: an exception here would end every grade at once.
  parallel_for(submissions.size(), outer, [&](std::size_t i) {
    try {
      grades[i] = grade_one(submissions[i], names[i], c.work + "/" + std::to_string(i), inner, c);
    } catch (const std::exception& e) {
      grades[i] = ungraded(submissions[i], names[i], std::string("the grader could not grade it: ") + e.what(), c);
      trouble = true;
    }
    make_presentable(grades[i], options.seed);
    const fs::path folder = single ? fs::path(options.out) : fs::path(options.out) / names[i];
    std::string unwritten;
    try {
      write_results(grades[i], folder, c);
    } catch (const std::exception& e) {
      unwritten = e.what();
      trouble = true;
    }
    std::lock_guard<std::mutex> lock(print);
    if (!unwritten.empty()) std::cerr << "labkit grade: " << safe_text(unwritten) << "\n";
    std::cout << (single ? "" : "\n") << table(grades[i], c.run) << std::flush;
  });

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!single) {
    write_file(fs::path(options.out) / "class.csv", class_csv(grades));
    std::cout << "\n" << term::bold("Class") << ": " << grades.size() << " submissions graded in " << points(seconds)
              << " s; " << (fs::path(options.out) / "class.csv").string() << "\n";
  } else {
    std::cout << "\nResults: " << (fs::path(options.out) / "results.json").string() << ", junit.xml, report.txt, steps.tsv\n";
  }
  if (trouble) std::cerr << "labkit grade: the grader had trouble of its own (above, or in a submission's results)\n";
  return trouble ? 1 : 0;
}

}  // namespace runner
