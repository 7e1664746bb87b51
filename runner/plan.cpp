#include "plan.h"

#include "assignment.h"
#include "manifest.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace runner {
namespace {

// "1 (20), 2 (45)": the steps of one tier and their minutes; "none" when there are none.
std::string steps_of_tier(const Lab& lab, bool core) {
  std::string list;
  for (const Step& s : lab.steps)
    if (s.core == core)
      list += (list.empty() ? "" : ", ") + std::to_string(s.number) + " (" + std::to_string(s.minutes) + ")";
  return list.empty() ? "none" : list;
}

std::string points_text(double points) {
  std::ostringstream out;
  out << points << (points == 1 ? " point" : " points");
  return out.str();
}

// The lab's core path and extensions; with `each_step`, then each step of the lab as
// given (an assignment's steps only, with its points).
void print_lab(const Lab& lab, bool summary, bool each_step) {
  std::cout << lab.id << "  " << lab.title << "\n";
  if (summary) {
    int all_minutes = 0;
    for (const Step& s : lab.steps) all_minutes += s.minutes;
    std::cout << "    core path:  " << steps_of_tier(lab, true) << ": " << lab.core_minutes() << " min\n";
    std::cout << "    extensions: " << steps_of_tier(lab, false);
    if (all_minutes > lab.core_minutes()) std::cout << ": " << all_minutes - lab.core_minutes() << " min";
    std::cout << "\n";
  }
  if (!each_step) return;
  for (const Step& s : lab.steps) {
    char line[96];
    std::snprintf(line, sizeof line, "    step %-2d  %-9s  %3d min  %3g %-6s  ", s.number,
                  s.core ? "core" : "extension", s.minutes, s.points, s.points == 1 ? "point" : "points");
    std::cout << line << s.title << "\n";
  }
}

}  // namespace

int plan(const Paths& paths, const PlanOptions& options) {
  Manifest manifest;
  std::string heading = "Every lab";
  try {
    manifest = load_manifest(paths.source + "/grading/manifest.json");
    std::vector<std::string> items = options.assignment;
    for (const std::string& lab : options.labs) items.push_back(lab);
    if (!items.empty()) {
      Assignment assignment = parse_assignment(items);
      manifest = restrict_to(manifest, assignment);
      heading = options.assignment.empty() ? "" : "Assignment \"" + assignment.name + "\"";
    }
  } catch (const std::exception& e) {
    std::cerr << "labkit: " << e.what() << "\n";
    return 2;
  }
  const bool each_step = !options.labs.empty() || !options.assignment.empty();
  double points = 0;
  int minutes = 0, steps = 0;
  for (const Lab& lab : manifest.labs)
    for (const Step& s : lab.steps) points += s.points, minutes += s.minutes, ++steps;
  if (!heading.empty())
    std::cout << heading << ": " << steps << " steps, " << minutes << " min, " << points_text(points) << "\n\n";
  for (const Lab& lab : manifest.labs) {
    print_lab(lab, options.assignment.empty(), each_step);
    std::cout << "\n";
  }
  std::cout << "A lab's core path is one 3-hour session; its extensions are the deeper work. Minutes are\n"
               "estimates for a second-year student, from grading/manifest.json (`minutes`, `tier`).\n";
  if (!each_step) std::cout << "Each step, its minutes and its points: ./labkit plan NN, or --assignment 03:core.\n";
  return 0;
}

}  // namespace runner
