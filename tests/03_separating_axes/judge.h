// Lab 03's verdicts: each judge compares one answer with the exact oracle, following
// the tolerances and degenerate rules of labs/03_separating_axes/separating_axes.h.
// The tests and the viewer both use them, so a red mark in the viewer and a failing
// case in `./labkit check` always agree.
#pragma once

#include "03_separating_axes/wire.h"

#include "03_separating_axes/generators.h"
#include "03_separating_axes/inputs.h"
#include "common/harness/check.h"

#include <algorithm>
#include <array>

namespace labkit::lab03 {

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

Outcome project_box(const BoxOnAxis& in, const Projection& got);
Outcome separated_on_axis(const BoxPairOnAxis& in, bool got, Rules rules = Rules::random);
// got[k] = box_axis(a, b, k) for k = 0..14.
Outcome box_axes(const BoxPair& in, const std::array<Vec3, 15>& got);
Outcome test_boxes(const BoxPair& in, bool got, Rules rules = Rules::random);
Outcome find_boxes(const BoxPair& in, const BoxContact& got, Rules rules = Rules::random);
// The interval method, on its domain (gen::in_interval_domain); outside it any answer passes.
Outcome triangles_by_intervals(const TrianglePair& in, const LineIntervals& got, Rules rules = Rules::random);
Outcome test_triangles(const TrianglePair& in, bool got, Rules rules = Rules::random);
Outcome test_moving_boxes(const MovingBoxes& in, bool got, Rules rules = Rules::random);
Outcome find_moving_boxes(const MovingBoxes& in, const ContactInterval& got, Rules rules = Rules::random);

}  // namespace judge
}  // namespace labkit::lab03
