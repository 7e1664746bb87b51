// Lab 04's inputs: what each query of bisection.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (tests/04_bisection/generators.h) draw them, the judge and the viewer read them.
#pragma once

#include "bisection.h"

#include "common/fields.h"
#include "common/harness/query.h"

#include "common/harness/codec.h"

#include <string>

namespace labkit {

// A standard motion, as the kit describes it (lab 04's StandardMotion holds the same):
//   pose(t) x = start + velocity t + acceleration t^2 / 2 + R(t) x,
// R(t) the turn by spin * t radians about `axis` through the body's origin.
struct MotionParameters {
  Vec3 start = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double spin = 0.0;
};

// One body: a sphere, or (is_box) an oriented box, in its own frame, and its motion.
struct MovingBody {
  bool is_box = false;
  Sphere sphere;
  Box box;
  MotionParameters motion;
};

// The times of a search: the interval [t0, t1] and the tolerance.
struct SearchTimes {
  double t0 = 0.0;
  double t1 = 1.0;
  double tolerance = 1.0 / 64;
};

// A pair (the first body is always a sphere) and a search.
struct MovingPairCase {
  MovingBody a;
  MovingBody b;
  SearchTimes times;
};

// A point and a box, for the closest point.
struct PointBox {
  Vec3 point = Vec3::Zero();
  Box box;
};

// The numbers the sub-step rule takes.
struct SubstepRule {
  double max_speed = 0.0;
  double step = 0.0;
  double smallest_size = 0.0;
};

// A pair searched by point sampling with this many sub-steps.
struct SampledPair {
  MovingPairCase pair;
  int substeps = 1;
};

// A pair searched by conservative advancement, with the closing-speed bound of its
// standard motions times speed_factor (>= 1: a looser bound is still a bound).
struct AdvancedPair {
  MovingPairCase pair;
  double speed_factor = 1.0;
};

LABKIT_FIELDS(MovingBody, is_box, sphere, box, motion)
LABKIT_FIELDS(MovingPairCase, a, b, times)
LABKIT_FIELDS(PointBox, point, box)
LABKIT_FIELDS(SubstepRule, max_speed, step, smallest_size)
LABKIT_FIELDS(SampledPair, pair, substeps)
LABKIT_FIELDS(AdvancedPair, pair, speed_factor)

// Times, spins and axes are unit-free for the ambiguity check: they move by 1e-9, not by
// 1e-9 S, and they do not count toward the length scale S.
namespace codec {
void encode(Writer& w, const MotionParameters& m);
void decode(Reader& r, MotionParameters& m);
void encode(Writer& w, const SearchTimes& t);
void decode(Reader& r, SearchTimes& t);
}  // namespace codec
// How reports print them (defined, like the codec above, in tests/04_bisection/generators.cpp).
std::string describe(const MotionParameters& m);  // only the parts that are not zero
std::string describe(const SearchTimes& t);
std::string describe(const MovingBody& b);  // the shape it is, and its motion

}  // namespace labkit

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB04_QUERIES(X, X_IN)                                                                            \
  /* step 1 */ X(placed, Sphere) X_IN(overlap, spheres, Sphere) X_IN(overlap, sphere_box, Sphere)                \
               X(closest_point, PointBox) X(overlap_at, MovingPairCase)                                          \
  /* step 2 */ X(bisect, MovingPairCase)                                                                         \
  /* step 3 */ X(tunnelling, MovingPairCase) X(smallest_size, MovingPairCase) X(closing_speed, MovingPairCase)   \
               X(substeps_for, SubstepRule) X(sample_then_bisect, SampledPair)                                   \
  /* step 4 */ X_IN(distance, spheres, Sphere) X_IN(distance, sphere_box, Sphere) X(distance_at, MovingPairCase) \
               X(advance, AdvancedPair)                                                                          \
  /* step 5 */ X_IN(robust, closest_point, PointBox) X_IN(robust, overlap_at, MovingPairCase)                    \
               X_IN(robust, bisect, MovingPairCase) X_IN(robust, substeps_for, SubstepRule)                      \
               X_IN(robust, sample_then_bisect, SampledPair) X_IN(robust, advance, AdvancedPair)
// clang-format on

namespace labkit::lab04::query {
LABKIT_QUERIES(LABKIT_LAB04_QUERIES)
}  // namespace labkit::lab04::query
