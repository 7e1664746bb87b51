// Lab 04's inputs: what each query of bisection.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (common/generators/04_bisection.h) draw them, the judge and the viewer read them.
#pragma once

#include "bisection.h"

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

template <class V> void fields(MovingBody& b, V&& v) {
  v("is_box", b.is_box);
  v("sphere", b.sphere);
  v("box", b.box);
  v("motion", b.motion);
}
template <class V> void fields(MovingPairCase& c, V&& v) {
  v("a", c.a);
  v("b", c.b);
  v("times", c.times);
}
template <class V> void fields(PointBox& p, V&& v) {
  v("point", p.point);
  v("box", p.box);
}
template <class V> void fields(SubstepRule& r, V&& v) {
  v("max_speed", r.max_speed);
  v("step", r.step);
  v("smallest_size", r.smallest_size);
}
template <class V> void fields(SampledPair& s, V&& v) {
  v("pair", s.pair);
  v("substeps", s.substeps);
}
template <class V> void fields(AdvancedPair& a, V&& v) {
  v("pair", a.pair);
  v("speed_factor", a.speed_factor);
}

// Times, spins and axes are unit-free for the ambiguity check: they move by 1e-9, not by
// 1e-9 S, and they do not count toward the length scale S.
namespace codec {
void encode(Writer& w, const MotionParameters& m);
void decode(Reader& r, MotionParameters& m);
void encode(Writer& w, const SearchTimes& t);
void decode(Reader& r, SearchTimes& t);
}  // namespace codec
// How reports print them (defined, like the codec above, in common/generators/04_bisection.cpp).
std::string describe(const MotionParameters& m);  // only the parts that are not zero
std::string describe(const SearchTimes& t);
std::string describe(const MovingBody& b);  // the shape it is, and its motion

}  // namespace labkit

// ---- The queries -------------------------------------------------------------------------
// The name of each question the tests ask (a replay token's prefix) and the input it takes,
// by the step that asks it first. The tests, the viewer's scene and its presets read this
// table (common/harness/query.h): a query is added or renamed here and nowhere else.
#define LABKIT_LAB04_QUERIES(X)                                          \
  /* step 1 */                                                           \
  X(placed, "placed", Sphere)                                            \
  X(overlap_spheres, "overlap.spheres", Sphere)                          \
  X(overlap_sphere_box, "overlap.sphere_box", Sphere)                    \
  X(closest_point, "closest_point", PointBox)                            \
  X(overlap_at, "overlap_at", MovingPairCase)                            \
  /* step 2 */                                                           \
  X(bisect, "bisect", MovingPairCase)                                    \
  /* step 3 */                                                           \
  X(tunnelling, "tunnelling", MovingPairCase)                            \
  X(smallest_size, "smallest_size", MovingPairCase)                      \
  X(closing_speed, "closing_speed", MovingPairCase)                      \
  X(substeps_for, "substeps_for", SubstepRule)                           \
  X(sample_then_bisect, "sample_then_bisect", SampledPair)               \
  /* step 4 */                                                           \
  X(distance_spheres, "distance.spheres", Sphere)                        \
  X(distance_sphere_box, "distance.sphere_box", Sphere)                  \
  X(distance_at, "distance_at", MovingPairCase)                          \
  X(advance, "advance", AdvancedPair)                                    \
  /* step 5 */                                                           \
  X(robust_closest_point, "robust.closest_point", PointBox)              \
  X(robust_overlap_at, "robust.overlap_at", MovingPairCase)              \
  X(robust_bisect, "robust.bisect", MovingPairCase)                      \
  X(robust_substeps_for, "robust.substeps_for", SubstepRule)             \
  X(robust_sample_then_bisect, "robust.sample_then_bisect", SampledPair) \
  X(robust_advance, "robust.advance", AdvancedPair)

namespace labkit::lab04::query {
LABKIT_LAB04_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB04_QUERIES)
}  // namespace labkit::lab04::query
