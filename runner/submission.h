// A submission: a folder, a .zip or a .tar.gz holding a student's files. Only the files
// the manifest lists as the student's (student_files) are ever taken from it, and only
// as regular files of a sane size: never a symlink, never a test, a header or a build
// file. Everything else in it is ignored, so a submission cannot change what it is
// graded by.
#pragma once

#include "manifest.h"
#include "sandbox.h"

#include <map>
#include <string>
#include <vector>

namespace runner {

struct Submission {
  std::string name;    // "alice" for alice.zip, alice.tar.gz or the folder alice/
  std::string source;  // the path given
  std::string error;   // why it could not be read at all ("" when it could)
  // student file (its manifest path) -> the file taken from the submission
  std::map<std::string, std::string> files;
  std::vector<std::string> notes;  // what the instructor should know (a file found by its name only, ...)
};

// The name a submission's results are filed under: its file or folder name without
// .zip, .tar.gz or .tar, with characters other than letters, digits, '-', '_' and '.'
// as '_'. Two submissions can have the same name (alice.zip, alice.tar.gz).
std::string submission_name(const std::string& path);

// The names that cannot be told apart: shared by two submissions or more, or the name of
// one of the class's own files (`reserved`: class.csv). One line per name, with the paths;
// "" when every submission has a name of its own.
std::string name_clashes(const std::vector<std::string>& submissions, const std::vector<std::string>& reserved);

struct ClassFolder {
  std::vector<std::string> members;  // sorted; empty when the folder is one submission
  std::string error;                 // it looks like both: nothing should be graded
};

// The submissions a folder holds when it is a class's folder (one sub-folder, .zip or
// .tar.gz per student). A folder is one submission when a student file lies at its top,
// or at its place in the kit (labs/NN_name/file); it is a class when it holds archives,
// or two or more sub-folders with a student file in them (a sub-folder named labs too,
// unless it holds a student file at its place). Both at once is an error.
ClassFolder class_members(const std::string& path, const std::vector<const Lab*>& labs);

struct Submissions {
  std::vector<std::string> paths;
  bool a_class = false;              // results in OUT/<name>/, and the class's own files in OUT
  std::string error;                 // why nothing should be graded
  std::vector<std::string> classes;  // "DIR holds N submissions", for each class folder
};

// The submissions named, a class folder standing for each submission in it; an error
// when a folder could be one submission or a class, or when two results folders would
// be one (alice.zip and alice.tar.gz: which counts is the instructor's call) or one
// would be a class file (`class_files`: class.csv.zip).
Submissions find_submissions(const std::vector<std::string>& named, const std::vector<const Lab*>& labs,
                             const std::vector<std::string>& class_files);

// Finds the student files of `labs` in the submission at `path`; an archive is unpacked
// (only those files) into `work`, confined by `sandbox`.
Submission read_submission(const std::string& path, const std::vector<const Lab*>& labs, const std::string& work,
                           const Sandbox& sandbox);

}  // namespace runner
