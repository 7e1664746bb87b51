// What a lab file may include, and the audit that holds it to that: its lab's header,
// the geometry types (common/geometry.h and the kit headers it and the lab's header pull
// in), Eigen, and the C and C++ standard library with the system's C headers. Nothing
// else: not the oracle or any other kit source, not CGAL, Boost, GMP or MPFR (a lab file
// that includes the oracle's .cpp under another name, with CGAL's header-only arithmetic,
// would get the oracle's answers without a line of geometry of its own).
//
// The compiler says which headers it read (-H), and every one of them is checked against
// that list, so no spelling of a path (relative, absolute, through a macro or a link)
// gets past it. Both ways a lab file is compiled use it: `./labkit grade`
// (runner/lab_build.cpp) and the kit's own build of the student's library, the one
// `./labkit check` runs (`labkit-runner lab-compile`, its compiler launcher in
// cmake/LabKit.cmake).
#pragma once

#include <set>
#include <string>
#include <vector>

namespace runner::includes {

struct Rule {
  std::string kit;                   // the kit's root: nothing below it is allowed but...
  std::set<std::string> kit_files;   // ...the lab's headers and the kit headers they pull in
  std::vector<std::string> folders;  // allowed wholesale: the lab's folder, Eigen, the C++ library, the compiler's
  std::set<std::string> files;       // allowed one by one: the C library's headers, the precompiled header
  std::vector<std::string> system;   // the folders of the C library, where only `files` are allowed
  bool c_library_known = false;      // false: no package lists, so `system` allows all but kBlocked
  std::vector<std::string> search;   // every include folder, to name a header as it was written
};

// The rule for a file of the lab whose folder is `lab_folder` (the kit's labs/NN_name),
// compiled by `command` (the compiler first; its -I, -isystem and -include name Eigen's
// folder and the precompiled header).
Rule rule_for(const std::string& kit, const std::string& lab_folder, const std::vector<std::string>& command);

// The kit's files the compile needs to see: the lab's folder and the kit headers allowed
// (what a confined compile is shown of the kit's tree).
std::vector<std::string> kit_paths(const Rule& rule, const std::string& lab_folder);

// The compiler's output without the lines -H added (the headers it read, and its
// "Multiple include guards" list), and those headers with their depth (1: included by
// the file itself).
struct Header {
  int depth;
  std::string path;
};
std::vector<Header> split_output(const std::string& output, std::string* rest);

// "" when every header read is allowed; otherwise the rule, in plain words, then each
// include of `source` that broke it, as written and with its line. A compile that
// failed because a header was hidden from it (a confined compile cannot see the rest of
// the kit: "No such file or directory", "Permission denied") counts as reading it.
std::string audit(const Rule& rule, const std::vector<Header>& headers, const std::string& rest,
                  const std::string& source);

// `labkit-runner lab-compile --kit ROOT --lab FOLDER -- COMPILER ARGS...`: the compiler
// launcher of the student's library (cmake/LabKit.cmake): compiles with -H, prints the
// compiler's output without -H's lines, and fails (removing the object) when the audit
// does, with the rule as the first error.
int compile_main(int argc, char** argv);

}  // namespace runner::includes
