// Lab 04's checker beyond its queries (queries.h declares the queries, their generators
// and their verdicts): what the lab's generators, judges, tests and viewer scene share.
#pragma once

#include "04_bisection/queries.h"
#include "common/harness/check.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>
#include <string>

namespace labkit {

// The pose at time t of the standard motion these parameters describe: the header's
// StandardMotion, evaluated as the lab evaluates it.
RigidTransform pose_at(const MotionParameters& m, double t);

}  // namespace labkit

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

// The closing speed the advancement is given: speed_factor times closing_speed_of.
double closing_speed_of(const AdvancedPair& in);

}  // namespace judge
}  // namespace labkit::lab04
