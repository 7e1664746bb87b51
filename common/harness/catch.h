// Catch2 2 or 3, whichever the system has: Debian 12 and Ubuntu 22.04 ship Catch2 2 (one
// header; its implementation is compiled in catch_implementation.cpp), Ubuntu 24.04
// ships Catch2 3 (headers per part and a compiled library). Every file of the kit
// includes Catch through this header, which also holds the few names that differ.
#pragma once

#include <string>

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

}  // namespace labkit::check
