// Lab 04's checker: the generators that draw each query's input, then the verdicts.
//
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
//
// The generators, first in this file (gen::):
// Seeded inputs for time of impact (lab 04): a sphere and a sphere or an oriented box,
// each moving by a standard motion, and the times of a search.
//
// Families on purpose: bodies that run into each other (so that a search has something
// to bracket), bodies that start overlapping, bodies that touch exactly at an end, at a
// midpoint or at a sample time, bodies that graze (touch for one instant) or miss by a
// hair, fast thin bodies that pass right through each other between two samples
// (tunnelling), spinning, screwing, orbiting and accelerating bodies, zero radii and
// zero half extents, every scale from 2^-20 to 2^20 and both ends of the header's domain
// (2^-300 and 2^300), and far from the origin. The exact families use integer
// coordinates and short binary times, so that every pose is exact.
#pragma once

#include "04_bisection/queries.h"
#include "common/harness/check.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>
#include <string>

namespace labkit {

// The pose of a standard motion at time t (the formula of MotionParameters,
// tests/04_bisection/queries.h, as lab 04 evaluates it).
RigidTransform pose_at(const MotionParameters& m, double t);

}  // namespace labkit

namespace labkit::gen {

// Pairs for the overlap, bisection and advancement queries: mostly bodies that run into
// each other during [t0, t1], with starts that overlap, exact and near touching and
// grazing, and unrelated motions; every kind of standard motion; tolerances from 2^-30
// to 1/2 of the interval.
rc::Gen<MovingPairCase> moving_pair();
// Tolerances no finer than 2^-12 of the interval: conservative advancement may crawl
// forward one tolerance at a time past a near miss.
rc::Gen<MovingPairCase> advancing_pair();
// Exact input for the robustness step: integer coordinates (multiples of 8, times a power
// of two), radii that are multiples of 35 (so that Pythagorean directions give exact
// touching points), boxes with signed permutations for axes, motions without spin, and
// times that are short binary fractions; touching at t0, t1, midpoints and samples,
// grazing, zero radii and zero half extents.
rc::Gen<MovingPairCase> exact_moving_pair();
// A fast small sphere and a thin wall (or a small sphere): clear at t0 and at t1, and
// right through each other in between, faster than one sub-step of the lecture's rule
// can miss.
rc::Gen<MovingPairCase> tunnelling_pair();

rc::Gen<PointBox> point_box();
rc::Gen<PointBox> exact_point_box();
rc::Gen<SubstepRule> substep_rule();
// Mostly whole ratios (on the rule's boundary), exact in doubles: the robustness step's.
rc::Gen<SubstepRule> exact_substep_rule();
rc::Gen<SampledPair> sampled_pair();
rc::Gen<SampledPair> exact_sampled_pair();
rc::Gen<AdvancedPair> advanced_pair();
rc::Gen<AdvancedPair> exact_advanced_pair();

}  // namespace labkit::gen

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
