// Catch2's implementation, compiled once for every program that uses the harness: the
// test binaries (whose main() is in catch_main.cpp) and the viewer (which has its own).
// Catch's own signal handlers are off: ours (report_writer.h) name the input a crash died on.
// (Catch2 3 is a library compiled with its own settings: there, its handler reports a
// crash first, then hands the signal on to ours.)
#define CATCH_CONFIG_RUNNER
#define CATCH_CONFIG_NO_POSIX_SIGNALS
// Wide enough that most replay tokens print on one line; `./labkit check` prints them
// whole, from the JSON report, whatever their length.
#define CATCH_CONFIG_CONSOLE_WIDTH 160
#include "common/harness/catch.h"
#if LABKIT_CATCH2_MAJOR == 3
#include <catch2/catch_session.hpp>
#endif

#include "common/harness/report_writer.h"

// Session is declared only here, with the implementation; main() calls through this.
int labkit::check::report::run_catch_session(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
