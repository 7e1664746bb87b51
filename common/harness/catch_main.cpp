// The test binaries' main(): our signal handlers, a listener that feeds the JSON report,
// then Catch's session. Catch's implementation itself is in catch_implementation.cpp;
// EXTERNAL_INTERFACES declares the listener types outside it.
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include "common/harness/catch.h"
#if LABKIT_CATCH2_MAJOR == 3
#include <catch2/catch_test_case_info.hpp>
#include <catch2/catch_translate_exception.hpp>
#include <catch2/reporters/catch_reporter_event_listener.hpp>
#include <catch2/reporters/catch_reporter_registrars.hpp>
#endif

#include "common/harness/report_writer.h"
#include "common/not_implemented.h"
#include "common/oracle/not_finite.h"
#include "common/protocol/answerer.h"

namespace {

constexpr const char* kYourCode = "your code ";

// Feeds report_writer.h with what Catch knows: test cases, and failed assertions in words.
#if LABKIT_CATCH2_MAJOR == 3
using ListenerBase = Catch::EventListenerBase;
using AssertionEnded = void;
#else
using ListenerBase = Catch::TestEventListenerBase;
using AssertionEnded = bool;  // Catch2 2 asks whether to keep the assertion's messages
#endif

class ReportListener : public ListenerBase {
 public:
  using ListenerBase::ListenerBase;

  void testCaseStarting(const Catch::TestCaseInfo& info) override {
    std::vector<std::string> tags;
    for (const auto& tag : info.tags) {
#if LABKIT_CATCH2_MAJOR == 3
      tags.emplace_back(tag.original.data(), tag.original.size());
#else
      tags.push_back(tag);
#endif
    }
    labkit::check::report::test_case_started(info.name, tags);
  }

  AssertionEnded assertionEnded(const Catch::AssertionStats& stats) override {
    const Catch::AssertionResult& result = stats.assertionResult;
    if (result.isOk()) return AssertionEnded(true);
    // An exception that ended the test case and came from neither the code under test
    // (the translators below mark those) nor a stub is the kit's own failure: the step
    // is not graded, and says whose failure it was.
    if (result.getResultType() == Catch::ResultWas::ThrewException) {
      const std::string what(result.getMessage());
      if (what.rfind(kYourCode, 0) != 0 && what.find("not implemented yet (") == std::string::npos)
        labkit::check::report::kit_error("an exception ended the test case early: " + what);
    }
    std::string message;
    for (const Catch::MessageInfo& info : stats.infoMessages) message += info.message + "\n";
    if (result.hasExpression())
      message += result.getExpressionInMacro() + " with expansion " + result.getExpandedExpression() + "\n";
    if (result.hasMessage()) message += std::string(result.getMessage());
    message +=
        "\n(" + std::string(result.getSourceInfo().file) + ":" + std::to_string(result.getSourceInfo().line) + ")";
    labkit::check::report::assertion_failed(message);
    return AssertionEnded(true);
  }

  void testCaseEnded(const Catch::TestCaseStats& stats) override {
    labkit::check::report::test_case_ended(stats.totals.assertions.failed == 0);
  }
};

}  // namespace

CATCH_REGISTER_LISTENER(ReportListener)

// A stub reached outside the harness (a test calling student code directly) still reads
// "not implemented yet", which is how the runner recognises it.
CATCH_TRANSLATE_EXCEPTION(const labkit::NotImplemented& e) { return e.what(); }
// What the code under test did, reached outside the harness: marked as its own.
CATCH_TRANSLATE_EXCEPTION(const labkit::remote::Failed& e) { return kYourCode + std::string(e.what()); }
CATCH_TRANSLATE_EXCEPTION(const labkit::remote::Threw& e) {
  return kYourCode + std::string("threw an exception: ") + e.what();
}
CATCH_TRANSLATE_EXCEPTION(const labkit::remote::Rejected& e) {
  return kYourCode + std::string("rejected a valid input: ") + e.what();
}
CATCH_TRANSLATE_EXCEPTION(const oracle::NotFinite& e) {
  return kYourCode + std::string("answered a number that is not finite: ") + e.what();
}

int main(int argc, char* argv[]) {
  // The LABKIT_* settings were read (and a graded run's seed wiped from the environment)
  // by a constructor that runs before any other, a student file's included (check.cpp).
  labkit::check::report::install_signal_handlers();
  const int status = labkit::check::report::run_catch_session(argc, argv);
  labkit::check::report::session_finished();
  return status;
}
