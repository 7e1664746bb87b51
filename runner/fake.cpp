#include "fake.h"

#include "grade.h"
#include "manifest.h"
#include "step.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace runner {

namespace {

constexpr double kRandomMostPoints = 1.0;
constexpr double kExamplesMostPoints = 5.0;

// The statuses in which a step's cases were all judged by the kit's own judge.
bool judged(Status s) { return s == Status::passed || s == Status::failing || s == Status::not_implemented; }

std::string first_why(const StepResult& r) {
  if (!r.detail.empty()) return r.detail;
  for (const QueryResult& q : r.queries) {
    if (!q.error.empty()) return q.error;
    if (q.failure) return q.query + ": " + q.failure->why;
  }
  return "";
}

}  // namespace

int fake(const Paths& paths, const FakeOptions& options) {
  const Manifest manifest = load_manifest(paths.source + "/grading/manifest.json");
  const Lab* lab = manifest.find(options.lab);
  if (!lab) throw std::runtime_error("there is no lab '" + options.lab + "'");
  const std::string mode = options.answers;
  if (mode != "nothing" && mode != "random" && mode != "garbage" && mode != "examples")
    throw std::runtime_error("--answers must be nothing, random, garbage or examples, not '" + mode + "'");

  StepOptions step_options;
  step_options.limits.seconds = 300;
  step_options.limits.memory_bytes = std::size_t(4) << 30;
  const std::string judge = paths.build + "/" + lab->judge_binary();
  std::vector<std::string> answerer = {paths.build + "/" + lab->answerer("fake"), mode};

  if (mode == "examples") {
    // The worked examples' requests, recorded by the judge while the reference answers
    // them (common/protocol/answerer.h, RecordingExample).
    const std::string file = paths.build + "/fake/" + lab->stem() + ".examples";
    std::filesystem::create_directories(paths.build + "/fake");
    std::remove(file.c_str());
    StepOptions record = step_options;
    record.cases = 1;
    record.record_examples = file;
    for (const Step& step : lab->steps)
      run_step({judge, paths.build + "/" + lab->answerer("reference")}, *lab, step, record);
    answerer.push_back(file);
  }

  step_options.seed = "the kit's own scoring test";
  step_options.cases = options.cases;
  step_options.count_all = true;
  const Programs programs{judge, nlohmann::json(answerer).dump()};
  double total = 0, most = 0;
  int queries = 0, broken = 0;
  std::ostringstream table;
  for (const Step& step : lab->steps) {
    const StepResult r = run_step(programs, *lab, step, step_options);
    const double points = step_score(step, r);
    total += points;
    most += step.points;
    queries += int(r.queries.size());
    table << "  step " << step.number << "  " << std::left << std::setw(22) << status_word(r.status) << std::right
          << std::setw(6) << std::fixed << std::setprecision(2) << points << " / " << step.points << "   "
          << first_why(r).substr(0, 160) << "\n";
    if (mode == "nothing" && points > 0) {
      table << "    a file that does nothing earned points on this step\n";
      ++broken;
    }
    if (!judged(r.status)) {
      table << "    the kit's judge did not survive these answers: it must judge any answer\n";
      ++broken;
    }
  }
  std::cout << "lab " << lab->id << ", answers: " << mode << "\n" << table.str();
  std::cout << "  total " << std::fixed << std::setprecision(2) << total << " / " << most << " (" << queries
            << " query reports)\n";
  if (mode == "random" && total > kRandomMostPoints) {
    std::cout << "  a file that answers at random earned more than " << kRandomMostPoints << " point\n";
    ++broken;
  }
  if (mode == "examples" && total > kExamplesMostPoints) {
    std::cout << "  a file that answers only the worked examples earned more than " << kExamplesMostPoints
              << " points\n";
    ++broken;
  }
  return broken == 0 ? 0 : 1;
}

}  // namespace runner
