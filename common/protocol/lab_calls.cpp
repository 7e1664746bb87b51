// One lab's functions for the judge's process, labkit::labNN::answerer::*: each sends its
// call to the answerer and returns the answer (calls.h). Compiled once per lab, with
// LABKIT_LAB_QUERIES naming the lab's queries.h, LABKIT_LAB_NAMESPACE its namespace and
// LABKIT_LAB_CALLS its list (cmake/LabKit.cmake sets them).
#include LABKIT_LAB_QUERIES

#include "common/protocol/calls.h"

namespace labkit::LABKIT_LAB_NAMESPACE::answerer {
LABKIT_LAB_CALLS(LABKIT_DEFINE_CALL, LABKIT_DEFINE_METHOD)
}  // namespace labkit::LABKIT_LAB_NAMESPACE::answerer

#ifdef LABKIT_LAB_SERVED  // queries.h's: the judge serves this lab's given functions
namespace {
[[maybe_unused]] const bool given_served = (LABKIT_LAB_SERVED(), true);
}  // namespace
#endif
