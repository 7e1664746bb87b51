// The kit's one use of RapidCheck's internals (rc::detail), kept in this file so that an
// update of RapidCheck touches nothing else.
//
// Why not rc::check(), RapidCheck's public entry point: it reads its seed and its number
// of cases once per process, from the environment (RC_PARAMS), and prints its own report
// to the terminal. The kit needs a seed and a count per query (the same cases for every
// student, a count per grading run), silence (the kit's reports say how to replay), and
// the outcome back as data. Generators (rc::Gen, rc::gen::*) and RC_FAIL are public API
// and are used as they are everywhere else.
#pragma once

#include <rapidcheck.h>

#include <cstdint>
#include <string>
#include <utility>

namespace labkit::check::rapidcheck {

struct Result {
  enum class Kind { passed, failed, gave_up, error };
  Kind kind = Kind::passed;
  std::string description;  // RapidCheck's words for a failure, a give-up or an error
};

namespace detail {

// RapidCheck's own listener prints a banner and a hint about RC_PARAMS.
struct QuietListener : rc::detail::TestListener {
  void onTestCaseFinished(const rc::detail::CaseDescription&) override {}
  void onShrinkTried(const rc::detail::CaseDescription&, bool) override {}
  void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}
};

}  // namespace detail

// Runs `property` on up to `cases` inputs drawn from `seed` (sizes up to 100), shrinking
// its first failure as RapidCheck does (the property calls RC_FAIL to fail). The same
// seed draws the same cases in the same order.
template <class Property> Result run(const std::string& name, std::uint64_t seed, int cases, Property&& property) {
  rc::detail::TestParams params;
  params.seed = seed;
  params.maxSuccess = cases;
  params.maxSize = 100;
  rc::detail::TestMetadata metadata;
  metadata.id = metadata.description = name;
  detail::QuietListener listener;
  const auto result = rc::detail::checkProperty(rc::detail::toProperty(std::forward<Property>(property)), metadata,
                                                params, listener, {});
  if (result.template is<rc::detail::SuccessResult>()) return {};
  if (result.template is<rc::detail::FailureResult>())
    return {Result::Kind::failed, result.template get<rc::detail::FailureResult>().description};
  if (result.template is<rc::detail::GaveUpResult>())
    return {Result::Kind::gave_up, result.template get<rc::detail::GaveUpResult>().description};
  return {Result::Kind::error, result.template is<rc::detail::Error>()
                                   ? result.template get<rc::detail::Error>().description
                                   : std::string("an outcome this adaptor does not know")};
}

// The first input `gen` draws from `seed`, as run() would draw it.
template <class T> T first_case(const rc::Gen<T>& gen, std::uint64_t seed) { return gen(rc::Random(seed), 0).value(); }

}  // namespace labkit::check::rapidcheck
