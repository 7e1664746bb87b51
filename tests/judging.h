// What every lab's judge shares: the headers' relative tolerance and the tol it gives an
// input. A helper used by two judges or more belongs here, once.
#pragma once

#include "common/harness/check.h"

namespace labkit::judging {

// tol = 1e-9 S, the tolerance every lab header states (S: the input's scale, its largest
// coordinate magnitude, check::scale_of_input). It is the harness's ambiguity band too.
inline constexpr double kRelative = check::kAmbiguity;

template <class Input>
double tolerance_of(const Input& in) {
  return kRelative * check::scale_of_input(in);
}

}  // namespace labkit::judging
