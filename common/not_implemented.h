// What a student stub does until the student writes it: throw NotImplemented with the
// step's tag. The harness reports the step as "not implemented yet"; nothing crashes
// and nothing passes.
#pragma once

#include <stdexcept>
#include <string>

namespace labkit {

struct NotImplemented : std::logic_error {
  explicit NotImplemented(const std::string& tag) : std::logic_error("not implemented yet (" + tag + ")") {}
};

// A stub hands its parameters along, unused, so that it compiles without warnings:
//   not_implemented("L02S1", segment, triangle);
template <class... Unused> [[noreturn]] void not_implemented(const char* tag, const Unused&...) {
  throw NotImplemented(tag);
}

}  // namespace labkit
