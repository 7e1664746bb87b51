// Lab 05's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), the table of the queries, and how each input is drawn and each answer
// judged (last): a new query is written here, then defined in generators*.cpp and
// judge*.cpp. Both processes include it; the answerer uses only its first part.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too.
#pragma once

#include "sphere_sweeps.h"

#include "common/fields.h"
#include "common/harness/outcome.h"
#include "common/harness/query.h"
#include "common/protocol/calls.h"

namespace labkit::lab05 {

LABKIT_FIELDS(PointSegmentDistance, squared_distance, t, closest)
LABKIT_FIELDS(SegmentSegmentDistance, squared_distance, s, t, closest0, closest1)
LABKIT_FIELDS(PointRectangleDistance, squared_distance, s, t, closest)
LABKIT_FIELDS(SegmentRectangleDistance, squared_distance, r, s, t, closest0, closest1)
LABKIT_FIELDS(RectangleRectangleDistance, squared_distance, closest0, closest1)
LABKIT_FIELDS(Sweep, status, time, point)

}  // namespace labkit::lab05

// clang-format off
#define LABKIT_LAB05_CALLS(CALL, METHOD)                                                              \
  CALL(PointSegmentDistance, point_segment, (const Vec3&, const Segment&))                            \
  CALL(SegmentSegmentDistance, segment_segment, (const Segment&, const Segment&))                     \
  CALL(PointRectangleDistance, point_rectangle, (const Vec3&, const Rectangle&))                      \
  CALL(SegmentRectangleDistance, segment_rectangle, (const Segment&, const Rectangle&))               \
  CALL(RectangleRectangleDistance, rectangle_rectangle, (const Rectangle&, const Rectangle&))         \
  CALL(bool, test_sphere_sphere, (const Sphere&, const Sphere&))                                      \
  CALL(bool, test_sphere_capsule, (const Sphere&, const Capsule&))                                    \
  CALL(bool, test_sphere_lozenge, (const Sphere&, const Lozenge&))                                    \
  CALL(bool, test_capsule_capsule, (const Capsule&, const Capsule&))                                  \
  CALL(bool, test_capsule_lozenge, (const Capsule&, const Lozenge&))                                  \
  CALL(bool, test_lozenge_lozenge, (const Lozenge&, const Lozenge&))                                  \
  CALL(Sweep, sweep_sphere_plane, (const Sphere&, const Vec3&, const Plane&, double))                 \
  CALL(Sweep, sweep_sphere_sphere, (const Sphere&, const Vec3&, const Sphere&, const Vec3&, double))  \
  CALL(Sweep, sweep_sphere_capsule, (const Sphere&, const Vec3&, const Capsule&, double))              \
  CALL(Sweep, sweep_box_plane, (const Box&, const Vec3&, const Plane&, double))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab05, LABKIT_LAB05_CALLS)

// ---- The inputs ------------------------------------------------------------------------
// Lab 05's inputs: what each query of sphere_sweeps.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (gen::, declared below) draw them, the judge and the viewer read them.
namespace labkit {

struct PointSegmentPair {
  Vec3 p = Vec3::Zero();
  Segment segment;
};
LABKIT_FIELDS(PointSegmentPair, p, segment)

struct SegmentPair {
  Segment first, second;
};
LABKIT_FIELDS(SegmentPair, first, second)

struct PointRectanglePair {
  Vec3 p = Vec3::Zero();
  Rectangle rectangle;
};
LABKIT_FIELDS(PointRectanglePair, p, rectangle)

struct SegmentRectanglePair {
  Segment segment;
  Rectangle rectangle;
};
LABKIT_FIELDS(SegmentRectanglePair, segment, rectangle)

struct RectanglePair {
  Rectangle first, second;
};
LABKIT_FIELDS(RectanglePair, first, second)

// Moving shapes: centre + t velocity for t in [0, duration].
struct SpherePlaneMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
LABKIT_FIELDS(SpherePlaneMotion, sphere, velocity, plane, duration)

struct SphereSphereMotion {
  Sphere s0;
  Vec3 v0 = Vec3::Zero();
  Sphere s1;
  Vec3 v1 = Vec3::Zero();
  double duration = 1.0;
};
LABKIT_FIELDS(SphereSphereMotion, s0, v0, s1, v1, duration)

// A sphere moving against a static capsule (step 6).
struct SphereCapsuleMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Capsule capsule;
  double duration = 1.0;
};
LABKIT_FIELDS(SphereCapsuleMotion, sphere, velocity, capsule, duration)

struct BoxPlaneMotion {
  Box box;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
LABKIT_FIELDS(BoxPlaneMotion, box, velocity, plane, duration)

}  // namespace labkit

namespace labkit::lab05 {

// Step 3's inputs: two sphere-swept volumes, a of one kind and b of another.
template <class A, class B> struct VolumePair {
  A a;
  B b;
};
template <class A, class B, class Visit> void fields(VolumePair<A, B>& x, Visit&& visit) {
  visit("a", x.a);
  visit("b", x.b);
}
using SpherePair = VolumePair<Sphere, Sphere>;
using SphereCapsule = VolumePair<Sphere, Capsule>;
using SphereLozenge = VolumePair<Sphere, Lozenge>;
using CapsulePair = VolumePair<Capsule, Capsule>;
using CapsuleLozenge = VolumePair<Capsule, Lozenge>;
using LozengePair = VolumePair<Lozenge, Lozenge>;

}  // namespace labkit::lab05

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB05_QUERIES(X, X_IN)                                                                                \
  /* step 1 */ X(point_segment, PointSegmentPair) X(segment_segment, SegmentPair)                                    \
  /* step 2 */ X(point_rectangle, PointRectanglePair) X(segment_rectangle, SegmentRectanglePair)                     \
               X(rectangle_rectangle, RectanglePair)                                                                 \
  /* step 3 */ X(test_sphere_sphere, SpherePair) X(test_sphere_capsule, SphereCapsule)                               \
               X(test_sphere_lozenge, SphereLozenge) X(test_capsule_capsule, CapsulePair)                            \
               X(test_capsule_lozenge, CapsuleLozenge) X(test_lozenge_lozenge, LozengePair)                          \
  /* step 4 */ X(sweep_sphere_plane, SpherePlaneMotion)                                                              \
  /* step 5 */ X(sweep_sphere_sphere, SphereSphereMotion) X_IN(sweep_sphere_sphere, soon, SphereSphereMotion)        \
               X_IN(sweep_sphere_sphere, grazing, SphereSphereMotion)                                                \
  /* step 6 */ X(sweep_sphere_capsule, SphereCapsuleMotion)                                                          \
  /* step 7 */ X(sweep_box_plane, BoxPlaneMotion)                                                                    \
  /* step 8 */ X_IN(robust, segment_segment, SegmentPair) X_IN(robust, sweep_sphere_plane, SpherePlaneMotion)        \
               X_IN(robust, sweep_sphere_sphere, SphereSphereMotion)                                                 \
               X_IN(robust, sweep_sphere_capsule, SphereCapsuleMotion)                                               \
  /* step 9 */ X_IN(robust, segment_rectangle, SegmentRectanglePair)                                                 \
               X_IN(robust, test_sphere_capsule, SphereCapsule) X_IN(robust, test_capsule_capsule, CapsulePair)      \
               X_IN(robust, test_capsule_lozenge, CapsuleLozenge) X_IN(robust, test_lozenge_lozenge, LozengePair)    \
               X_IN(robust, sweep_box_plane, BoxPlaneMotion)
// clang-format on

namespace labkit::lab05::query {
LABKIT_QUERIES(LABKIT_LAB05_QUERIES)
}  // namespace labkit::lab05::query

// ---- How each input is drawn, and the verdicts -----------------------------------------
// Declared here, beside the queries they serve; defined in generators*.cpp (gen::) and
// judge*.cpp (judge::). RapidCheck is included where the generators are called.
namespace rc {
template <typename T> class Gen;
}  // namespace rc

// Seeded inputs for sphere-swept volumes (lab 05), on the dyadic lattice of
// common/generators/generators.h, so that the degenerate families are exact: "parallel"
// segments are parallel, a point "on the side" is on it, spheres "exactly grazing" graze.
//
// Families on purpose: crossing, parallel, collinear and nearly parallel segments, ends
// on the other shape, zero-length segments and zero-size rectangles, segments piercing or
// lying in a rectangle's plane, stacked and crossing rectangles; for moving shapes:
// approaching, moving apart, moving sideways or not at all, touching at t = 0, contact
// exactly at the end of the step, and a nearly-grazing family whose closest approach is
// within a tiny relative amount (2^-10 to 2^-52) of r0 + r1, inside and outside, at every
// scale and from far away. Exact families (for the robustness step) use integers |x| <=
// 64 times a power of two and axis-aligned rectangles and boxes.
namespace labkit::gen {

// `exact`: the robustness step's input (integers |x| <= 64 times a power of two,
// axis-aligned rectangles and boxes); otherwise the fine dyadic lattice, any orientation.
rc::Gen<PointSegmentPair> point_segment(bool exact = false);
rc::Gen<SegmentPair> segment_pair(bool exact = false);
rc::Gen<PointRectanglePair> point_rectangle(bool exact = false);
rc::Gen<SegmentRectanglePair> segment_rectangle(bool exact = false);
rc::Gen<RectanglePair> rectangle_pair(bool exact = false);

rc::Gen<SpherePlaneMotion> sphere_plane_motion(bool exact = false);
rc::Gen<SphereSphereMotion> sphere_sphere_motion(bool exact = false);
rc::Gen<BoxPlaneMotion> box_plane_motion(bool exact = false);
// A sphere against a static capsule: anywhere; aimed at the side; grazing the side or a
// cap (closest approach within a decisive hair of r + rc); sliding parallel to the axis
// toward a cap; starting near touching; reaching it near T; zero-length axes. `exact`:
// the robustness step's integer families (exactly parallel, exactly touching at t = 0,
// exact grazes, contact exactly at T, zero-length capsules).
rc::Gen<SphereCapsuleMotion> sphere_capsule_motion(bool exact = false);

// The nearly-grazing spheres alone: closest approach (r0 + r1)(1 + e), |e| = 2^-k for k
// in [10, 52] or e = 0, both signs, at every scale, the spheres' size from 2^-12 to 1 of
// their distance at t = 0.
rc::Gen<SphereSphereMotion> grazing_spheres();
// Spheres a hair apart at t = 0 (gap 2^-k of their size) that approach at a clear angle:
// contact comes very soon, and only a stable root formula gets its time right.
rc::Gen<SphereSphereMotion> soon_spheres(bool exact = false);

// A radius split for a sphere-swept pair: two radii r0 + r1 that sum exactly to `total`
// (a dyadic split), or only approximately when `total` has no spare bits.
rc::Gen<std::pair<double, double>> split_radius(double total);

// Step 3's inputs: the cores of the distance steps with radii chosen around their exact
// distance (exactly touching, a hair inside or outside at every scale, or anything);
// `exact`: small integers, with exactly touching pairs built from cores that lie in two
// parallel planes h apart over a common point.
rc::Gen<lab05::SpherePair> sphere_pair(bool exact = false);
rc::Gen<lab05::SphereCapsule> sphere_capsule(bool exact = false);
rc::Gen<lab05::SphereLozenge> sphere_lozenge(bool exact = false);
rc::Gen<lab05::CapsulePair> capsule_pair(bool exact = false);
rc::Gen<lab05::CapsuleLozenge> capsule_lozenge(bool exact = false);
rc::Gen<lab05::LozengePair> lozenge_pair(bool exact = false);

}  // namespace labkit::gen

// Lab 05's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/05_sphere_sweeps/sphere_sweeps.h. The tests and
// the viewer both use them.
namespace labkit::lab05::judge {

using check::Outcome;
using check::Rules;  // random cases, or a robustness step's exact input

Outcome point_segment(const PointSegmentPair& in, const PointSegmentDistance& got);
Outcome segment_segment(const SegmentPair& in, const SegmentSegmentDistance& got);
Outcome point_rectangle(const PointRectanglePair& in, const PointRectangleDistance& got);
Outcome segment_rectangle(const SegmentRectanglePair& in, const SegmentRectangleDistance& got);
Outcome rectangle_rectangle(const RectanglePair& in, const RectangleRectangleDistance& got);

Outcome test_pair(const SpherePair& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const SphereCapsule& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const SphereLozenge& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const CapsulePair& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const CapsuleLozenge& in, bool got, Rules rules = Rules::random);
Outcome test_pair(const LozengePair& in, bool got, Rules rules = Rules::random);

Outcome sweep_sphere_plane(const SpherePlaneMotion& in, const Sweep& got, Rules rules = Rules::random);
Outcome sweep_sphere_sphere(const SphereSphereMotion& in, const Sweep& got, Rules rules = Rules::random);
Outcome sweep_sphere_capsule(const SphereCapsuleMotion& in, const Sweep& got, Rules rules = Rules::random);
Outcome sweep_box_plane(const BoxPlaneMotion& in, const Sweep& got, Rules rules = Rules::random);

}  // namespace labkit::lab05::judge
