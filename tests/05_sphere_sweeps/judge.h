// Lab 05's checker: the generators that draw each query's input, then the verdicts.
//
// Lab 05's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/05_sphere_sweeps/sphere_sweeps.h. The tests
// and the viewer both use them.
//
// The generators come first in this file (gen::). Seeded inputs for sphere-swept volumes
// (lab 05), on the dyadic lattice of common/generators/generators.h, so that the
// degenerate families are exact: "parallel" segments are parallel, a point "on the side"
// is on it, spheres "exactly grazing" graze.
//
// Families on purpose: crossing, parallel, collinear and nearly parallel segments, ends
// on the other shape, zero-length segments and zero-size rectangles, segments piercing
// or lying in a rectangle's plane, stacked and crossing rectangles; for moving shapes:
// approaching, moving apart, moving sideways or not at all, touching at t = 0, contact
// exactly at the end of the step, and a nearly-grazing family whose closest approach is
// within a tiny relative amount (2^-10 to 2^-52) of r0 + r1, inside and outside, at
// every scale and from far away. Exact families (for the robustness step) use integers
// |x| <= 64 times a power of two and axis-aligned rectangles and boxes.
#pragma once

#include "05_sphere_sweeps/queries.h"
#include "common/harness/check.h"
#include "common/harness/codec.h"
#include "common/oracle/sphere_sweeps.h"

#include <rapidcheck.h>
#include <string>

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

namespace labkit::lab05 {

// The exact distance between the cores of a pair (table 6.1's distance calculator): what
// step 3's generators place the radii around, and what its judge compares r0 + r1 with.
oracle::SquaredDistance core_distance(const SpherePair& p);
oracle::SquaredDistance core_distance(const SphereCapsule& p);
oracle::SquaredDistance core_distance(const SphereLozenge& p);
oracle::SquaredDistance core_distance(const CapsulePair& p);
oracle::SquaredDistance core_distance(const CapsuleLozenge& p);
oracle::SquaredDistance core_distance(const LozengePair& p);

}  // namespace labkit::lab05

namespace labkit::lab05 {

std::string describe(SweepStatus s);

namespace judge {

using check::Outcome;

using check::Rules;  // random cases, or a robustness step's exact input

// The header's S for each input, and tol = 1e-9 S.
double scale(const PointSegmentPair& in);
double scale(const SegmentPair& in);
double scale(const PointRectanglePair& in);
double scale(const SegmentRectanglePair& in);
double scale(const RectanglePair& in);
double scale(const SpherePlaneMotion& in);
double scale(const SphereSphereMotion& in);
double scale(const SphereCapsuleMotion& in);
double scale(const BoxPlaneMotion& in);

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

}  // namespace judge
}  // namespace labkit::lab05

namespace labkit {

// The header's S of the inputs whose S is not their largest length (a plane counts by its
// distance from the origin, not its normal's size): the domain check::in_domain keeps a
// shrunk case in.
inline double header_scale(const SpherePlaneMotion& in) { return lab05::judge::scale(in); }
inline double header_scale(const BoxPlaneMotion& in) { return lab05::judge::scale(in); }

}  // namespace labkit
