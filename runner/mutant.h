// `labkit-runner mutant`: the kit's own check that a classic mistake is caught where it
// belongs. A mutant (a `// mutant` line of solutions/NN_name/, cmake/Mutants.cmake) is the
// reference with one mistake of step k written in; its steps run in order, as a student's would, and
//   - every step before k passes (the mistake is not blamed on an earlier step),
//   - step k fails,
//   - the why of step k's first failure block, the one a student reads first, names the
//     concept: it holds every word the mutant SAYS (case-insensitive).
#pragma once

#include "kit.h"

#include <string>
#include <vector>

namespace runner {

struct MutantOptions {
  std::string lab;                // "02"
  std::string name;               // the mutant's NAME
  int step = 0;                   // the step its mistake belongs to
  std::vector<std::string> says;  // the concept words its first failure must show
};

// 0 when all three hold; else 1, with what broke and the failure block the student would read.
int mutant(const Paths& paths, const MutantOptions& options);

}  // namespace runner
