// The machine-readable side of a test run: the listener in catch_main.cpp tells it when
// test cases start and end, check.h adds each query's counts, and the JSON file named by
// LABKIT_REPORT is rewritten after each of them, so that `./labkit check` still knows
// how far a run got when the code under test crashes or hangs.
#pragma once

#include "common/protocol/report.h"

#include <string>
#include <vector>

namespace labkit::check::report {

using TestCase = labkit::report::TestCase;

void test_case_started(const std::string& name, const std::vector<std::string>& tags);
void assertion_failed(const std::string& message);
void test_case_ended(bool passed);
// An exception of the kit's own ended a test case early: its remaining queries never ran,
// so the report carries a kit error (check.h's kit_error) and the step is not graded.
void kit_error(const std::string& what);
// The whole session returned. A report without it comes from a process that ended early
// (exit() in the code under test, a crash), whatever its exit status.
void session_finished();

// Prints the in-flight case on a crash or a time-out (SIGTERM) before the process dies.
void install_signal_handlers();

// Catch's session (in catch_implementation.cpp, where Catch declares it).
int run_catch_session(int argc, char* argv[]);

}  // namespace labkit::check::report
