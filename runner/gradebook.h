// gradebook.csv: a class's grades in the form Canvas and Moodle import (README,
// "Gradebooks"): a row per student, their identity columns, and one column of points
// headed by the assignment's name.
//
// Without a roster the Student column holds the submission's name. A roster is a CSV
// file whose header has a "submission" column (the names ./labkit grade gives the
// submissions: folder or archive names) and the columns the gradebook matches students
// on (Canvas: Student, ID, SIS User ID, SIS Login ID, Section; Moodle: an Email address
// or ID number column, chosen when importing); those columns are copied as they are.
#pragma once

#include "grade.h"

#include <string>
#include <vector>

namespace runner {

struct Roster {
  std::vector<std::string> columns;            // the identity columns, in the file's order
  std::vector<std::string> names;              // each student's submission name
  std::vector<std::vector<std::string>> rows;  // each student's identity cells
};

// Throws std::runtime_error naming the file and what is wrong with it.
Roster load_roster(const std::string& path);

struct Gradebook {
  std::string csv;
  std::vector<std::string> notes;  // submissions not on the roster, students with none
};

Gradebook gradebook_csv(const std::vector<SubmissionGrade>& all, const std::string& assignment, const Roster* roster);

}  // namespace runner
