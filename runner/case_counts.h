// `labkit-runner report DIR`: the per-query case counts of the reports a suite run left
// in DIR (build/reports after ./labkit test): the figures of how hard the suite tests.
#pragma once

#include "manifest.h"

#include <string>

namespace runner {

// With `max_ambiguous` (a share, 0 to 1) and the manifest, it also fails, naming them,
// when a random query of a step other than a lab's robustness step has a larger share of
// ambiguous cases: those cases accept any answer, so such a family could never fail.
int report(const std::string& directory, const Manifest* manifest = nullptr, double max_ambiguous = 1);

}  // namespace runner
