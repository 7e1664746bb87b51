// `./labkit plan`: the labs' core paths and extensions, step by step, with their minutes
// and points, read from grading/manifest.json (README, "Fitting a course"). A course
// plans its sessions and its assignments from it; nothing else keeps a copy.
#pragma once

#include "kit.h"

#include <string>
#include <vector>

namespace runner {

struct PlanOptions {
  std::vector<std::string> labs;        // "03", "3" or "separating_axes"; none: every lab
  std::vector<std::string> assignment;  // items such as 03:core, or a JSON file
};

// Prints the plan on stdout: 0, or 2 with the reason on stderr.
int plan(const Paths& paths, const PlanOptions& options);

}  // namespace runner
