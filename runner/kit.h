// The kit as every command meets it: where its tree and its build are, and what a build
// that failed says first. `./labkit check`, `grade` and the mutant checks all use these.
#pragma once

#include <string>

namespace runner {

struct Paths {
  std::string source;  // the kit's root
  std::string build;   // its CMake build tree
};

// The first compiler errors of a build log (24 lines), with `root/` taken out of paths.
std::string first_errors(const std::string& log, const std::string& root);

}  // namespace runner
