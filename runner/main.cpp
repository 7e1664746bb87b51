// labkit-runner: the commands behind ./labkit. Run it through ./labkit, which installs
// what is missing, configures and builds first.
#include "assignment.h"
#include "case_counts.h"
#include "check.h"
#include "fake.h"
#include "grade.h"
#include "includes.h"
#include "mutant.h"
#include "plan.h"
#include "sandbox.h"
#include "untrusted.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

// `check`: the student's command. The student release holds no references and no
// mutants: there it checks the student's files only, and does not offer the choice.
CLI::App* add_check(CLI::App& app, runner::CheckOptions& check, bool release) {
  CLI::App* command = app.add_subcommand("check", "Build the labs as they stand and check every step");
  command->add_option("labs", check.labs, "Which labs (default: all), e.g. 02");
  command->add_option("--step", check.step, "Only this step")->check(CLI::PositiveNumber);
  command->add_option("--case", check.replay, "Replay exactly one case, as a failure report prints it");
  command->add_flag("--debug", check.debug, "With --case: run your code under gdb and show where it crashes");
  command->add_option("--cases", check.cases, "Random cases per query")->check(CLI::Range(1, 100000000));
  command->add_option("--seed", check.seed, "Seed of the random cases (default: the public one)");
  command->add_option("--jobs", check.jobs, "Steps run at once (default: one per core)")->check(CLI::PositiveNumber);
  command->add_option("--timeout", check.timeout, "Seconds allowed per step")->check(CLI::PositiveNumber);
  const auto valid = [release](std::string& s) {
    if (release && s != "student")
      return std::string("this is the student release: it holds your files only, no reference or mutant to check");
    return s == "student" || s == "reference" || s.rfind("mutant_", 0) == 0
               ? std::string()
               : std::string("must be student, reference or mutant_NAME");
  };
  CLI::Option* implementation =
      command
          ->add_option("--implementation", check.implementation,
                       "Which code to check: student (your files), reference, or mutant_NAME (a classic mistake)")
          ->check(CLI::Validator(valid, "IMPLEMENTATION"));
  if (release) implementation->group("");  // hidden from --help
  return command;
}

// `grade`: the instructor's command.
CLI::App* add_grade(CLI::App& app, runner::GradeOptions& grade) {
  CLI::App* command =
      app.add_subcommand("grade", "Grade submissions (folders, .zip or .tar.gz files) on a secret seed");
  command->add_option("submissions", grade.submissions, "The submissions")->required();
  command->add_option("--out", grade.out, "Where the results go (default: ./grades)");
  command->add_option("--seed", grade.seed, "The secret seed (default: $LABKIT_GRADING_SEED)");
  command
      ->add_option("--jobs", grade.jobs,
                   "Processes at once (default: the CPUs this process may use, its control group's quota included)")
      ->check(CLI::PositiveNumber);
  command->add_option("--labs", grade.labs, "Only these labs, e.g. --labs 01 02");
  command
      ->add_option("--assignment", grade.assignment,
                   "Only this assignment's labs and steps, with its points: an item such as 03:core, 06 or "
                   "05:1,4,5,8 (repeat the option for more labs), or a JSON file (README, \"Fitting a course\")")
      ->expected(1)
      ->take_all();
  command->add_option("--roster", grade.roster,
                      "A CSV of the students: a \"submission\" column and the columns your gradebook matches "
                      "on; gradebook.csv then has a row per student (README, \"Gradebooks\")");
  command
      ->add_option("--cases", grade.cases,
                   "Random cases per query (default " + std::to_string(runner::kGradingCases) + ")")
      ->check(CLI::Range(1, 100000000));
  command->add_option("--timeout", grade.timeout, "Seconds allowed per step (default 60)")->check(CLI::PositiveNumber);
  command
      ->add_option(
          "--budget", grade.budget,
          "Seconds of wall time for all of a submission's compiles and steps together (default " +
              std::to_string(int(runner::kGradingBudget)) +
              ": seven labs within Gradescope's 10 minutes at half a CPU); each step gets at most what is left")
      ->check(CLI::PositiveNumber);
  command
      ->add_option(
          "--memory", grade.memory_mb,
          "Megabytes of memory per step (default 2048; less when the grader's control group has less for its workers)")
      ->check(CLI::Range(64, 1 << 20));
  command->add_option("--sandbox", grade.sandbox, "auto (bubblewrap, else Landlock), bubblewrap, landlock or none")
      ->check(CLI::IsMember({"auto", "bubblewrap", "landlock", "none"}));
  return command;
}

struct ReportOptions {
  std::string directory;
  double max_ambiguous = 100;
};

CLI::App* add_report(CLI::App& app, ReportOptions& report) {
  CLI::App* command = app.add_subcommand("report", "Sum up the case counts a suite run left behind");
  command->add_option("directory", report.directory, "Where the reports are (default: build/reports)");
  command
      ->add_option("--max-ambiguous", report.max_ambiguous,
                   "Fail when a random family outside a robustness step has more ambiguous cases than this, in %")
      ->check(CLI::Range(0.0, 100.0));
  return command;
}

// `plan`: the core paths and extensions, from the manifest; the instructor's planning view.
CLI::App* add_plan(CLI::App& app, runner::PlanOptions& plan) {
  CLI::App* command = app.add_subcommand("plan", "The labs' core paths and extensions, with minutes and points");
  command->add_option("labs", plan.labs, "Labs to show step by step, e.g. 03");
  command->add_option("--assignment", plan.assignment, "An assignment (03:core, or a JSON file) to show");
  return command;
}

struct AssignmentOptions {
  std::vector<std::string> items;
  std::string out, workflow;
};

// `./labkit package gradescope --assignment ...` and `./labkit release --classroom ...`:
// the assignment checked against the manifest and frozen (its steps and points as they
// are now) into a file the package carries.
CLI::App* add_assignment(CLI::App& app, AssignmentOptions& assignment) {
  CLI::App* command =
      app.add_subcommand("assignment", "Check an assignment against the manifest and write it out, frozen");
  command->group("");  // behind ./labkit package and release
  command->add_option("items", assignment.items, "Items such as 03:core, or a JSON file")->required();
  command->add_option("--out", assignment.out, "The JSON file to write")->required();
  command->add_option("--workflow", assignment.workflow, "Also write its GitHub Classroom workflow here");
  return command;
}

// The kit's own test of a classic mistake (ctest labNN.mutant.NAME); not for students.
CLI::App* add_mutant(CLI::App& app, runner::MutantOptions& mutant) {
  CLI::App* command =
      app.add_subcommand("mutant", "Check that a classic mistake fails first in its own step, naming its concept");
  command->group("");  // hidden from --help
  command->add_option("lab", mutant.lab, "The lab, e.g. 02")->required();
  command->add_option("--name", mutant.name, "The mutant's NAME")->required();
  command->add_option("--step", mutant.step, "The step its mistake belongs to")->required()->check(CLI::PositiveNumber);
  command->add_option("--says", mutant.says, "A word its first failure's why must contain");
  return command;
}

// The kit's own test of its scoring and judges (ctest kit.fake.labNN.MODE); not for students.
CLI::App* add_fake(CLI::App& app, runner::FakeOptions& fake) {
  CLI::App* command =
      app.add_subcommand("fake", "Grade a lab with answers that do no geometry: they must earn nothing");
  command->group("");  // hidden from --help
  command->add_option("lab", fake.lab, "The lab, e.g. 02")->required();
  command->add_option("--answers", fake.answers, "nothing, random, garbage or examples")->required();
  command->add_option("--cases", fake.cases, "Random cases per query")->check(CLI::PositiveNumber);
  return command;
}

// A seed given on the command line is wiped from it: /proc/PID/cmdline is world-readable.
void wipe_seeds(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--seed" && i + 1 < argc) std::memset(argv[i + 1], 'x', std::strlen(argv[i + 1]));
    if (arg.rfind("--seed=", 0) == 0) std::memset(argv[i] + 7, 'x', arg.size() - 7);
  }
}

}  // namespace

int main(int argc, char** argv) {
  // The judge's process starts a graded answerer through this (runner/step.h): first, and
  // without the rest of the command line's machinery.
  if (argc > 1 && std::string(argv[1]) == "confine") return runner::confine_main(argc, argv);
  // The compiler launcher of every lab's student library (cmake/LabKit.cmake): the
  // include audit of runner/includes.h, as ./labkit grade applies it.
  if (argc > 1 && std::string(argv[1]) == "lab-compile") return runner::includes::compile_main(argc, argv);
  CLI::App app{"The collision-detection lab kit"};
  app.require_subcommand(1);
  runner::Paths paths{LABKIT_SOURCE_DIR, LABKIT_BINARY_DIR};
  if (const char* b = std::getenv("LABKIT_BUILD_DIR"); b && *b) paths.build = b;
  runner::CheckOptions check;
  runner::GradeOptions grade;
  ReportOptions report;
  AssignmentOptions assignment;
  runner::PlanOptions plan;
  runner::MutantOptions mutant;
  runner::FakeOptions fake;
  CLI::App* check_command = add_check(app, check, !std::filesystem::exists(paths.source + "/solutions"));
  CLI::App* grade_command = add_grade(app, grade);
  CLI::App* report_command = add_report(app, report);
  CLI::App* assignment_command = add_assignment(app, assignment);
  CLI::App* plan_command = add_plan(app, plan);
  CLI::App* mutant_command = add_mutant(app, mutant);
  CLI::App* fake_command = add_fake(app, fake);
  CLI11_PARSE(app, argc, argv);
  wipe_seeds(argc, argv);
  try {
    if (check_command->parsed()) {
      if (const char* n = std::getenv("LABKIT_CASES"); n && check.cases == 0) check.cases = std::atoi(n);
      if (const char* s = std::getenv("LABKIT_SEED"); s && check.seed.empty()) check.seed = s;
      return runner::check(paths, check);
    }
    if (grade_command->parsed()) {
      // The secret stays in this process: nothing it starts inherits it.
      if (const char* s = std::getenv("LABKIT_GRADING_SEED"); s && grade.seed.empty()) grade.seed = s;
      unsetenv("LABKIT_GRADING_SEED");
      unsetenv("LABKIT_SEED");
      return runner::grade(paths, grade);
    }
    if (assignment_command->parsed())
      return runner::freeze_assignment(paths, assignment.items, assignment.out, assignment.workflow);
    if (plan_command->parsed()) return runner::plan(paths, plan);
    if (mutant_command->parsed()) return runner::mutant(paths, mutant);
    if (fake_command->parsed()) return runner::fake(paths, fake);
    if (report_command->parsed()) {
      const runner::Manifest manifest = runner::load_manifest(paths.source + "/grading/manifest.json");
      return runner::report(report.directory.empty() ? paths.build + "/reports" : report.directory, &manifest,
                            report.max_ambiguous / 100);
    }
  } catch (const std::exception& e) {
    std::cerr << "labkit: " << runner::safe_text(e.what()) << "\n";  // it may name a student's file
    return 2;
  }
  return 0;
}
