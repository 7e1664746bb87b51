// The GitHub Classroom workflow of an assignment (README, "GitHub Classroom"): on each
// push to a student's repository it builds and checks the assignment's labs on the
// public seed, puts the step table in the run's summary, and awards each step's points
// when `./labkit check NN --step K` passes. The student's repository holds the workflow
// and the public seed, so it is feedback, not a grade that counts.
#pragma once

#include "manifest.h"

#include <string>

namespace runner {

// .github/workflows/classroom.yml for the assignment's labs and steps (a restricted
// manifest, assignment.h) and its name.
std::string classroom_workflow(const Manifest& chosen, const std::string& name);

}  // namespace runner
