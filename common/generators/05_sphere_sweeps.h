// Seeded inputs for sphere-swept volumes (lab 05), on the dyadic lattice of generators.h,
// so that the degenerate families are exact: "parallel" segments are parallel, a point
// "on the side" is on it, spheres "exactly grazing" graze.
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

#include "common/geometry.h"
#include "common/harness/codec.h"

#include <rapidcheck.h>

namespace labkit {

struct PointSegmentPair {
  Vec3 p = Vec3::Zero();
  Segment segment;
};
template <class V> void fields(PointSegmentPair& x, V&& v) { v("p", x.p); v("segment", x.segment); }

struct SegmentPair {
  Segment first, second;
};
template <class V> void fields(SegmentPair& x, V&& v) { v("first", x.first); v("second", x.second); }

struct PointRectanglePair {
  Vec3 p = Vec3::Zero();
  Rectangle rectangle;
};
template <class V> void fields(PointRectanglePair& x, V&& v) { v("p", x.p); v("rectangle", x.rectangle); }

struct SegmentRectanglePair {
  Segment segment;
  Rectangle rectangle;
};
template <class V> void fields(SegmentRectanglePair& x, V&& v) { v("segment", x.segment); v("rectangle", x.rectangle); }

struct RectanglePair {
  Rectangle first, second;
};
template <class V> void fields(RectanglePair& x, V&& v) { v("first", x.first); v("second", x.second); }

// Moving shapes: centre + t velocity for t in [0, duration].
struct SpherePlaneMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
template <class V> void fields(SpherePlaneMotion& x, V&& v) {
  v("sphere", x.sphere); v("velocity", x.velocity); v("plane", x.plane); v("duration", x.duration);
}

struct SphereSphereMotion {
  Sphere s0;
  Vec3 v0 = Vec3::Zero();
  Sphere s1;
  Vec3 v1 = Vec3::Zero();
  double duration = 1.0;
};
template <class V> void fields(SphereSphereMotion& x, V&& v) {
  v("s0", x.s0); v("v0", x.v0); v("s1", x.s1); v("v1", x.v1); v("duration", x.duration);
}

// A sphere moving against a static capsule (step 6).
struct SphereCapsuleMotion {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Capsule capsule;
  double duration = 1.0;
};
template <class V> void fields(SphereCapsuleMotion& x, V&& v) {
  v("sphere", x.sphere); v("velocity", x.velocity); v("capsule", x.capsule); v("duration", x.duration);
}

struct BoxPlaneMotion {
  Box box;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
  double duration = 1.0;
};
template <class V> void fields(BoxPlaneMotion& x, V&& v) {
  v("box", x.box); v("velocity", x.velocity); v("plane", x.plane); v("duration", x.duration);
}

}  // namespace labkit

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

}  // namespace labkit::gen
