// What a graded submission shows: each step's feedback as the student reads it, and
// every text a student controls made presentable (no secret, safe text).
#pragma once

#include "budget.h"
#include "grade.h"
#include "step.h"

#include <string>
#include <vector>

namespace runner {

// Everything a student controls in a grade, as it may be written and shown: never the
// secret or a seed drawn from it (even if the code under test found them), and safe
// text (untrusted.h). The one place this happens: every result file and the terminal
// get a grade through it.
void make_presentable(SubmissionGrade& g, const std::vector<std::string>& secrets);

// What the student reads about one step: the verdict, the counts, the first failure and
// how to replay it with the public kit. A step that ended abnormally on a case has that
// case described by the judge, with `describe` (the step's graded options), in time
// taken from the submission's budget.
std::string feedback(const StepResult& r, const Lab& lab, const Programs& programs, const StepOptions& describe,
                     Budget& budget);

// The rule a failing step's first failure broke, as its judge worded it.
std::string first_why(const StepResult& r);

}  // namespace runner
