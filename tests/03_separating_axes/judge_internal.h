// What the files of lab 03's judge share (tests/03_separating_axes/judge*.cpp): the
// header's tol, the doubt margins and the short-axis bounds, and the axes' names.
#pragma once

#include "judging.h"

#include "03_separating_axes/judge.h"

#include <algorithm>
#include <string>

namespace labkit::lab03::judge {

// The verdicts every judge file of this lab gives.
using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;
using check::verdict;

// tol = 1e-9 S, S the input's largest position coordinate (the header's tolerances):
// scale_of, which counts the moving boxes' end positions and never an axis or a velocity,
// so not judging::tolerance_of, whose S is every length the input holds.
template <class Input> double position_tolerance(const Input& in) {
  return judging::kRelative * std::max(scale_of(in), 1e-300);
}

// Edge axes shorter than this are left out of the least-penetration search (the
// header's 1e-6), and between these two bounds either choice passes.
constexpr double kShortest = 0.5e-6, kSurelyIncluded = 2e-6;

// How far the exact answer can be from flipping, in units of tol (the header's
// perturbation: positions by tol, axis entries by 1e-9).
//  - A corner c + sum_k s_k h_k A_k moves by at most sqrt(3) tol (the center) plus, on
//    each axis, tol (h_k) and h_k sqrt(3) 1e-9 <= sqrt(3) tol (A_k): (4 sqrt(3) + 3) tol,
//    under 10 tol. Both boxes: the distance or the penetration depth moves by at most
//    20 tol; 24 leaves room for the margin's own rounding (about 1e-15 S).
constexpr double kBoxDoubt = 24;
//  - Moving boxes add the relative displacement duration (v_B - v_A): each box's end
//    position moves by tol per coordinate (velocity and start together: at most
//    2 sqrt(3) tol per box) and the duration by 1e-9 of itself (at most 2 sqrt(3) tol
//    of displacement per box): 20 + 4 sqrt(3) + 4 sqrt(3), under 34; 40 with room.
constexpr double kMovingDoubt = 40;

// "axis 7 (A_0 x B_1)": one of the 15 axes, named for reports.
std::string axis_name(int index);

}  // namespace labkit::lab03::judge
