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

// The name a submission's results are filed under.
std::string submission_name(const std::string& path);

// The submissions a folder holds when it is a class's folder (one sub-folder, .zip or
// .tar.gz per student), sorted; empty when `path` is one submission. A folder is one
// submission when a student file lies at its top or under its labs/; it is a class when
// it holds archives, or two or more sub-folders with a student file in them.
std::vector<std::string> class_members(const std::string& path, const std::vector<const Lab*>& labs);

// Finds the student files of `labs` in the submission at `path`; an archive is unpacked
// (only those files) into `work`, confined by `sandbox`.
Submission read_submission(const std::string& path, const std::vector<const Lab*>& labs, const std::string& work,
                           const Sandbox& sandbox);

}  // namespace runner
