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

#include "common/geometry.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>

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
  v("is_box", b.is_box); v("sphere", b.sphere); v("box", b.box); v("motion", b.motion);
}
template <class V> void fields(MovingPairCase& c, V&& v) { v("a", c.a); v("b", c.b); v("times", c.times); }
template <class V> void fields(PointBox& p, V&& v) { v("point", p.point); v("box", p.box); }
template <class V> void fields(SubstepRule& r, V&& v) {
  v("max_speed", r.max_speed); v("step", r.step); v("smallest_size", r.smallest_size);
}
template <class V> void fields(SampledPair& s, V&& v) { v("pair", s.pair); v("substeps", s.substeps); }
template <class V> void fields(AdvancedPair& a, V&& v) { v("pair", a.pair); v("speed_factor", a.speed_factor); }

// Times, spins and axes are unit-free for the ambiguity check: they move by 1e-9, not by
// 1e-9 S, and they do not count toward the length scale S.
namespace codec {
void encode(Writer& w, const MotionParameters& m);
void decode(Reader& r, MotionParameters& m);
void encode(Writer& w, const SearchTimes& t);
void decode(Reader& r, SearchTimes& t);
}  // namespace codec
std::string describe(const MotionParameters& m);  // only the parts that are not zero
std::string describe(const SearchTimes& t);
std::string describe(const MovingBody& b);  // the shape it is, and its motion

// The pose of a standard motion at time t (the formula above, as lab 04 evaluates it).
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
