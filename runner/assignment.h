// An assignment: the labs and steps one grade covers, with their points (README,
// "Fitting a course"). A course publishes one per lab, week by week; the whole kit is
// the assignment when none is given.
//
// On the command line, one item per lab: LAB or LAB:WHICH, where WHICH is core,
// extension, all (the default) or step numbers, e.g. 03:core, 06, 05:1,4,5,8. In a
// file (a JSON object), with a name and points of its own where the manifest's do not
// suit:
//   {"name": "Week 3: separating axes",
//    "labs": [{"lab": "03", "steps": "core", "points": {"1": 20, "2": 30}}]}
#pragma once

#include "kit.h"
#include "manifest.h"

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace runner {

struct Assignment {
  struct Part {
    std::string lab;            // as given: "03", "3" or "separating_axes"
    std::string which = "all";  // core, extension, all, or "" when `steps` lists them
    std::vector<int> steps;
    std::map<int, double> points;  // step -> points, where the manifest's are not used
  };
  std::string name;  // "" until resolved: then "Lab 03, core steps" unless the file names it
  std::vector<Part> parts;

  bool whole_kit() const { return parts.empty(); }
  nlohmann::json to_json() const;
};

// From the command line's items, or from the file when there is one item and it names
// a file. Throws std::runtime_error naming what is wrong.
Assignment parse_assignment(const std::vector<std::string>& items);

// The manifest as the assignment sees it: its labs and steps only, with its points, and
// the assignment's name filled in. Throws std::runtime_error for a lab or a step the
// manifest does not have, or an assignment with no step.
Manifest restrict_to(const Manifest& manifest, Assignment& assignment);

// The assignment checked against the kit's manifest and written to `out` with its steps
// and points as they are now, and its GitHub Classroom workflow to `workflow` unless it
// is ""; says on stdout what it holds. 0, or 2 with the reason.
int freeze_assignment(const Paths& paths, const std::vector<std::string>& items, const std::string& out,
                      const std::string& workflow);

}  // namespace runner
