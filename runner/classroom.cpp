#include "classroom.h"

#include "results.h"

#include <nlohmann/json.hpp>

#include <sstream>

namespace runner {

namespace {

// A YAML scalar: JSON's double-quoted string is one.
std::string quoted(const std::string& text) { return nlohmann::json(text).dump(); }

}  // namespace

std::string classroom_workflow(const Manifest& chosen, const std::string& name) {
  std::ostringstream y;
  y << "# GitHub Classroom feedback for " << quoted(name) << ", written by ./labkit release --classroom.\n"
    << "# On each push it builds and checks the labs on the public seed, shows the step table in\n"
    << "# the run's summary, and awards each step's points when `./labkit check NN --step K`\n"
    << "# passes. This repository holds the workflow and the public seed, so these points are\n"
    << "# feedback: a grade that counts comes from ./labkit grade or the Gradescope package,\n"
    << "# with the instructor's secret seed.\n"
    << "name: labkit check\n"
    << "\"on\":\n  push:\n  workflow_dispatch:\n"
    << "permissions:\n  checks: write\n  actions: read\n  contents: read\n"
    << "jobs:\n  check:\n"
    << "    if: github.actor != 'github-classroom[bot]'\n"
    << "    runs-on: ubuntu-latest\n"
    << "    # The kit's platform: Debian 12 and its packages (the runner's Ubuntu has other\n"
    << "    # versions, e.g. Catch2 3). In the container the job runs as root.\n"
    << "    container: debian:12\n"
    << "    timeout-minutes: 90\n"
    << "    steps:\n"
    << "      - uses: actions/checkout@v4\n"
    << "      - name: Install the kit's Debian packages\n"
    << "        run: if [ \"$(id -u)\" = 0 ]; then ./labkit install; else sudo ./labkit install; fi\n";
  std::string runners, env;
  for (const Lab& lab : chosen.labs) {
    y << "      - name: " << quoted("Build and check lab " + lab.id) << "\n"
      << "        run: |\n"
      << "          ./labkit check " << lab.id << " > check-" << lab.id << ".txt || true\n"
      << "          cat check-" << lab.id << ".txt\n"
      << "          { echo '### Lab " << lab.id << "'; echo '```'; cat check-" << lab.id
      << ".txt; echo '```'; } >> \"$GITHUB_STEP_SUMMARY\"\n";
    for (const Step& s : lab.steps) {
      const std::string id = "lab" + lab.id + "-step" + std::to_string(s.number);
      y << "      - name: "
        << quoted("Lab " + lab.id + " step " + std::to_string(s.number) + " (" + (s.core ? "core" : "extension") + ")")
        << "\n"
        << "        id: " << id << "\n"
        << "        uses: classroom-resources/autograding-command-grader@v1\n"
        << "        with:\n"
        << "          test-name: " << quoted("Lab " + lab.id + " step " + std::to_string(s.number) + ": " + s.title)
        << "\n"
        << "          command: ./labkit check " << lab.id << " --step " << s.number << "\n"
        << "          timeout: 10\n"
        << "          max-score: " << points(s.points) << "\n";
      runners += (runners.empty() ? "" : ",") + id;
      std::string upper = id;
      for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
      env += "          " + upper + "_RESULTS: \"${{steps." + id + ".outputs.result}}\"\n";
    }
  }
  y << "      - name: Autograding reporter\n"
    << "        uses: classroom-resources/autograding-grading-reporter@v1\n"
    << "        env:\n"
    << env << "        with:\n"
    << "          runners: " << runners << "\n";
  return y.str();
}

}  // namespace runner
