// Catch2 2 or 3, whichever the system has: Debian 12 and Ubuntu 22.04 ship Catch2 2 (one
// header; its implementation is compiled in catch_implementation.cpp), Ubuntu 24.04
// ships Catch2 3 (headers per part and a compiled library). Every file of the kit
// includes Catch through this header, which also holds the few names that differ and the
// one precondition test every lab's tests share (rejects).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#if __has_include(<catch2/catch_all.hpp>)
#define LABKIT_CATCH2_MAJOR 3
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
using Catch::Approx;
#else
#define LABKIT_CATCH2_MAJOR 2
#include <catch2/catch.hpp>
#endif

namespace labkit::check {

// A matcher for text that holds `part` (Catch2 2's Contains, Catch2 3's ContainsSubstring).
inline auto contains_text(const std::string& part) {
#if LABKIT_CATCH2_MAJOR == 3
  return Catch::Matchers::ContainsSubstring(part);
#else
  return Catch::Matchers::Contains(part);
#endif
}

// A precondition's test: call() must throw std::invalid_argument whose message names
// `argument`, as every lab header's preconditions require of invalid input. `what`, when
// given, says which invalid input it is. Returns the message ("" when nothing was thrown).
template <class Call> std::string rejects(const std::string& argument, Call&& call) {
  INFO("invalid " << argument << ": the header's preconditions reject it with std::invalid_argument naming it");
  try {
    call();
  } catch (const std::invalid_argument& e) {
    INFO("message: " << e.what());
    CHECK_THAT(std::string(e.what()), contains_text(argument));
    return e.what();
  }
  FAIL_CHECK("accepted: it answered instead of throwing std::invalid_argument");
  return "";
}
template <class Call> std::string rejects(const std::string& what, const std::string& argument, Call&& call) {
  INFO(what);
  return rejects(argument, std::forward<Call>(call));
}

}  // namespace labkit::check
