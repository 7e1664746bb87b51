// Lab 04's verdicts: each judge checks one answer against the exact oracle, following
// the tolerances and degenerate rules of labs/04_bisection/bisection.h. The tests and the
// viewer both use them, so a red mark in the viewer and a failing case in
// `./labkit check` always agree.
//
// Times are certified, never compared with another floating-point root: the oracle poses
// the bodies with the motion's own numbers at the reported times and decides overlap
// exactly there. A configuration is in doubt when the bodies' signed gap is within what a
// perturbation of the input by a relative 1e-9 can move it (they touch, or nearly:
// grazing contact); a verdict that hangs on such a configuration is ambiguous.
#pragma once

#include "04_bisection/wire.h"

#include "04_bisection/generators.h"
#include "04_bisection/inputs.h"
#include "common/harness/check.h"

namespace labkit::lab04 {

// The lab's types from the kit's descriptions.
StandardMotion motion_of(const MotionParameters& m);
Shape shape_of(const MovingBody& b);
MovingPair pair_of(const MovingPairCase& c);

// The closing-speed bound of the pair's standard motions on [t0, t1]: max_speed of each
// body over its reach, added.
double closing_speed_of(const MovingPairCase& c);
// The lecture's "smallest object" of the pair: the smaller of the two smallest sizes.
double smallest_size_of(const MovingPairCase& c);

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

Outcome closest_point(const PointBox& in, const Vec3& got, Rules rules = Rules::random);
// Overlap at t0 and at t1 of the case's search.
Outcome overlap_at(const MovingPairCase& in, bool got_t0, bool got_t1, Rules rules = Rules::random);
Outcome bisect(const MovingPairCase& in, const TimeOfImpact& got, Rules rules = Rules::random);
Outcome substeps_for(const SubstepRule& in, int got, Rules rules = Rules::random);
Outcome sample_then_bisect(const SampledPair& in, const TimeOfImpact& got, Rules rules = Rules::random);
// closing_speed of the pair on [t0, t1]: max_speed of a plus max_speed of b.
Outcome closing_speed(const MovingPairCase& in, double got);
// The tunnelling demonstration: the pair's closing speed, the sub-step count for it and
// the pair's size, point sampling at the frame's ends only (which must miss) and with
// that many sub-steps (which must find the contact).
Outcome tunnelling(const MovingPairCase& in, double got_speed, int got_substeps, const TimeOfImpact& frame_only,
                   const TimeOfImpact& substepped);
// The distance at t0 and at t1 of the case's search.
Outcome distance_at(const MovingPairCase& in, double got_t0, double got_t1);
// The closing speed the advancement is given: speed_factor times closing_speed_of.
double closing_speed_of(const AdvancedPair& in);
Outcome advance(const AdvancedPair& in, const TimeOfImpact& got, Rules rules = Rules::random);

}  // namespace judge
}  // namespace labkit::lab04
