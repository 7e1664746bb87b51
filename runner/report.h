// `labkit-runner report DIR`: the per-query case counts of the reports a suite run left
// in DIR (build/reports after ./labkit test): the figures of how hard the suite tests.
#pragma once

#include <string>

namespace runner {

int report(const std::string& directory);

}  // namespace runner
