// What `./labkit grade` writes for each submission: a Gradescope results.json, JUnit
// XML, a readable table; and for a class, one CSV of students by labs.
#pragma once

#include "grade.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace runner {

struct GradingRun {
  std::string seed_kind;  // "secret" or "public": the seed itself is never written
  // With a secret: the command that grades a submission again on the same cases (each
  // submission's own, seed.h), with the secret left for the instructor to fill in.
  std::string regrade;
  int cases = 0;           // random cases per query (0: the harness's default)
  std::string sandbox;     // Sandbox::description()
  std::string limits;      // each step's time and memory, the workers and the envelope
  std::string assignment;  // its name (assignment.h), "" for the whole kit
};

// The readable table: a line per lab and per step, then each step's feedback.
std::string table(const SubmissionGrade& s, const GradingRun& run);

// Gradescope's results.json, as its autograder specification documents it
// (gradescope-autograders.readthedocs.io/en/latest/specs/, "Output format"; the schema
// is grading/gradescope-results.schema.json): top-level score, execution_time and
// output; one test per step (name, number, score, max_score, status, output,
// visibility) and one score-less test per lab saying whether it compiled.
nlohmann::json gradescope_results(const SubmissionGrade& s, const GradingRun& run);

// JUnit XML: <testsuites> of one <testsuite> per lab, one <testcase> per step, with
// <failure> for a step that failed and <error> for one that crashed, timed out, ...
std::string junit_xml(const SubmissionGrade& s);

// One line per step, tab-separated, for scripts: lab, step, tag, status, score, max.
std::string steps_tsv(const SubmissionGrade& s);

// The class: one row per submission, one column per lab, then the total and the maximum.
std::string class_csv(const std::vector<SubmissionGrade>& all);

// A CSV cell (RFC 4180) that no spreadsheet evaluates as a formula.
std::string csv_field(std::string text);

// Text as XML (and HTML) character data or an attribute value: & < > " ' escaped, and
// the control characters XML 1.0 forbids shown as "?".
std::string xml_escape(const std::string& text);

// "12.5", "100": at most two decimals.
std::string points(double x);

}  // namespace runner
