// The judges the viewer shares with the tests are built on the verdict harness
// (common/harness/check.cpp), which reports to Catch2. The viewer never runs a Catch
// session, but the linker still needs Catch's implementation: here it is, without the
// test runner's main().
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
