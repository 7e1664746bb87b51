// What the files of lab 03's judge share (tests/03_separating_axes.judge*.cpp): the
// header's tol.
#pragma once

#include "judging.h"

#include "common/generators/03_separating_axes.h"

#include <algorithm>

namespace labkit::lab03::judge {

// tol = 1e-9 S, S the input's largest position coordinate (the header's tolerances):
// scale_of, which counts the moving boxes' end positions and never an axis or a velocity,
// so not judging::tolerance_of, whose S is every length the input holds.
template <class Input> double position_tolerance(const Input& in) {
  return judging::kRelative * std::max(scale_of(in), 1e-300);
}

}  // namespace labkit::lab03::judge
