// The class page: OUT/class.html, opened from the results folder in any browser (no
// server, no script). It shows where the class stands:
//
//   - the distribution of totals, and each step's pass rate (plots drawn by gnuplot,
//     Debian's gnuplot-nox, as SVG files beside the page; without gnuplot the page says
//     how to get it and keeps its tables);
//   - the concepts most often broken: each failing step's first failure names the rule
//     the answer broke (its judge's "why"); the same rule with other numbers is one concept;
//   - the submissions that could not be read, did not compile, crashed, timed out, ran
//     out of memory, flooded their output or exited early, each with what happened;
//   - every submission's row, linked to its report (NAME/report.txt).
//
// Everything a student controls on the page went through make_presentable (grade.cpp)
// and is HTML-escaped here.
#pragma once

#include "grade.h"
#include "results.h"

#include <string>
#include <vector>

namespace runner {

inline const char* const kClassPage = "class.html";

// Every file a class run writes in OUT beside the submissions' folders: no submission
// may be named after one of them.
std::vector<std::string> class_files();

// Writes the page and its plots into `out`; `scratch` is a folder of the grader's for
// gnuplot's inputs. Returns the page's path.
std::string write_class_page(const std::vector<SubmissionGrade>& all, const GradingRun& run, const std::string& out,
                             double seconds, const std::string& scratch);

// A failure's rule without its numbers, so that one mistake made on different inputs
// counts once: "input triangle 3: the crossing is at t = 0.5, not 0.7" becomes
// "the crossing is at t = #, not #".
std::string concept_of(const std::string& why);

}  // namespace runner
