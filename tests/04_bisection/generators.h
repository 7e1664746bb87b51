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

#include "04_bisection/inputs.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>

#include <string>

namespace labkit {

// The pose of a standard motion at time t (the formula of MotionParameters,
// tests/04_bisection/inputs.h, as lab 04 evaluates it).
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
