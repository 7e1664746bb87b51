// One lab's functions for the judge's process, labkit::labNN::answerer::*: each sends its
// call to the answerer and returns the answer (calls.h). Compiled once per lab, with
// LABKIT_LAB_WIRE naming the lab's wire header, LABKIT_LAB_NAMESPACE its namespace and
// LABKIT_LAB_CALLS its list (cmake/LabKit.cmake sets them).
#include LABKIT_LAB_WIRE

#include "common/protocol/calls.h"

namespace labkit::LABKIT_LAB_NAMESPACE::answerer {
LABKIT_LAB_CALLS(LABKIT_DEFINE_CALL, LABKIT_DEFINE_METHOD)
}  // namespace labkit::LABKIT_LAB_NAMESPACE::answerer

#ifdef LABKIT_LAB_SERVED  // the wire header's: the judge serves this lab's given functions
namespace {
[[maybe_unused]] const bool given_served = (LABKIT_LAB_SERVED(), true);
}  // namespace
#endif
