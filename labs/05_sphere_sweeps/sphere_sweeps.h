// Lab 05: sphere-swept volumes, static and moving.
// Handout: handouts/05_sphere_sweeps.md. Lectures 000 (course lecture 24, "Static
// Intersection: Sphere-Swept Volumes", tables 6.1 and 6.6), 002 (CSCE 552, "Math,
// Physics and Collision Detection": sphere-sphere sweeps and their special cases) and
// 003 ("Collision Detection - Narrow Phase": moving sphere and box against a plane).
//
// You write labs/05_sphere_sweeps/sphere_sweeps.cpp; this header is the contract.
//
// A sphere-swept volume is a core shape plus a radius: every point within r of it.
//
//     sphere            capsule                     lozenge
//       .-.          .-----------.           .---------------------.
//      ( * )        (  a*-----*b  )          |  c3-------------c2  |
//       '-'          '-----------'           | |        v ^      | |
//    core: a point   core: a segment         | |    c *-> u      | |
//                                            |  c0-------------c1  |
//                                            '---------------------'
//                                            core: a rectangle (seen from above)
//
// Two of them meet exactly when their cores are within r0 + r1 of each other (table 6.1):
// every test below is a distance between cores. Moving ones meet first when that distance
// first drops to r0 + r1.
//
// Sets are closed: touching counts. A zero-length segment (a == b) is a point; a rectangle
// with half_u == 0 or half_v == 0 is a segment (or a point); a zero radius is allowed.
// Rectangle axes u and v are unit length and perpendicular (to rounding); box axes are
// orthonormal columns (to rounding); plane normals need NOT have unit length.
//
// Input domain. Every answer must match the exact one (within the tolerances below) on
// all input where S (below) is 0 or lies in [1e-40, 1e40]: the products the tests need
// (up to degree 6 in the coordinates) then stay far from overflow and underflow. A
// plane's normal may have any non-zero length a double holds (components from 1e-300 to
// 1e300, as long as the offset is a finite double): the answer is that of the plane the
// numbers describe, so a normal of length 1e200 must not overflow |n|^2.
//
// Preconditions (every query). Every number is finite; radii, half-sizes (half_u, half_v,
// half_extents) and the duration are >= 0; a plane's normal is not zero; rectangle axes
// and box axes are unit and perpendicular to rounding (the reference checks to 1e-6).
// The reference throws std::invalid_argument naming the argument and the rule, e.g.
// "sweep_sphere_plane: plane.normal must be non-zero, got (0, 0, 0)". You are not graded
// on invalid input: your code may assume the preconditions hold.
//
// Tolerances. S is the largest absolute coordinate of the input's points (sphere centres,
// segment ends, rectangle and box centres), of its lengths (radii, half-sizes), of each
// motion's displacement (velocity * duration) and of each plane's distance from the
// origin, |offset| / |normal|. Directions and the duration do not count. tol = 1e-9 S.
//  - Distances (the square root of a reported squared distance) within tol of the exact
//    distance. Closest points within tol of their shape, and within tol of what their
//    parameters give; their distance apart within tol of the exact distance. Any closest
//    pair is accepted where it is not unique (parallel segments, a segment parallel to a
//    rectangle).
//  - Yes/no answers (tests, and a sweep's status) must equal the exact answer, except on
//    ambiguous input: input whose answer could change if every length moved by tol and
//    every direction by 1e-9. The checker bounds that change: a test is ambiguous when
//    its distance is within 20 tol of r0 + r1, a sweep when its gap at t = 0 or its
//    smallest gap over [0, T] is within 24 tol of zero (the motion and the duration move
//    the shapes too). There either answer passes, and the case is counted apart.
//  - A reported time of first contact t is certified exactly, never compared with another
//    rounded root: at t the gap (distance minus r0 + r1, or for a box its gap to the
//    plane) is at most tol, and at no time in [0, t] is it below -tol. So a time is as
//    good as the contact it describes.
//  - Moving spheres with exact coefficients: when A, B and A.A, A.B, B.B, (r0 + r1)^2
//    (step 5) are exact in double and the approach is not grazing (b^2 - ac >= b^2 / 4
//    for the quadratic a t^2 + 2 b t + c), the time must also be within a relative 1e-9
//    of the exact first root. A stable root formula achieves a few units in the last
//    place; a formula that cancels (-b - sqrt(b^2 - ac)) / a does not when contact comes
//    very soon.
#pragma once

#include "common/geometry.h"

namespace labkit::lab05 {

// ---- Step 1 (L05S1): point-segment and segment-segment distance ---------------------

struct PointSegmentDistance {
  double squared_distance = 0.0;  // |p - closest|^2
  double t = 0.0;                 // closest = segment.a + t (b - a), 0 <= t <= 1
  Vec3 closest = Vec3::Zero();    // the segment's point nearest to p
};

// The nearest point of the closed segment: project p on the line, clamp to [0, 1]. A
// zero-length segment returns t = 0 and closest = a.
PointSegmentDistance point_segment(const Vec3& p, const Segment& segment);

struct SegmentSegmentDistance {
  double squared_distance = 0.0;  // |closest0 - closest1|^2
  double s = 0.0;                 // closest0 = first.a + s (first.b - first.a), 0 <= s <= 1
  double t = 0.0;                 // closest1 = second.a + t (second.b - second.a), 0 <= t <= 1
  Vec3 closest0 = Vec3::Zero();   // on the first segment
  Vec3 closest1 = Vec3::Zero();   // on the second
};

// A closest pair of the two closed segments. Parallel segments (and zero-length ones)
// have many closest pairs: any pair at the minimal distance is accepted. The reference
// returns the first minimal pair among: the lines' closest points (when the segments
// are not parallel and both lie inside), then each end a0, b0, a1, b1 against the other
// segment, in that order.
SegmentSegmentDistance segment_segment(const Segment& first, const Segment& second);

// ---- Step 2 (L05S2): point-, segment- and rectangle-rectangle distance ---------------

struct PointRectangleDistance {
  double squared_distance = 0.0;  // |p - closest|^2
  double s = 0.0;                 // closest = center + s u + t v,
  double t = 0.0;                 //   |s| <= half_u, |t| <= half_v
  Vec3 closest = Vec3::Zero();
};

PointRectangleDistance point_rectangle(const Vec3& p, const Rectangle& rectangle);

struct SegmentRectangleDistance {
  double squared_distance = 0.0;  // |closest0 - closest1|^2
  double r = 0.0;                 // closest0 = segment.a + r (b - a), 0 <= r <= 1
  double s = 0.0;                 // closest1 = center + s u + t v,
  double t = 0.0;                 //   |s| <= half_u, |t| <= half_v
  Vec3 closest0 = Vec3::Zero();   // on the segment
  Vec3 closest1 = Vec3::Zero();   // on the rectangle
};

// Zero when the segment meets the rectangle (then closest0 == closest1 is a common
// point, within tol). Otherwise a closest pair has an end of the segment or a point of
// the rectangle's border in it: the ends against the rectangle, the segment against the
// four sides.
SegmentRectangleDistance segment_rectangle(const Segment& segment, const Rectangle& rectangle);

struct RectangleRectangleDistance {
  double squared_distance = 0.0;  // |closest0 - closest1|^2
  Vec3 closest0 = Vec3::Zero();   // on the first rectangle
  Vec3 closest1 = Vec3::Zero();   // on the second
};

// The same argument once more: a closest pair has a point of some side of one of them,
// so it is the nearest of the eight sides against the other rectangle.
RectangleRectangleDistance rectangle_rectangle(const Rectangle& first, const Rectangle& second);

// ---- Step 3 (L05S3): sphere, capsule and lozenge pairs -------------------------------

// Do they meet (touching counts)? Each is "distance between cores <= r0 + r1".
bool test_sphere_sphere(const Sphere& a, const Sphere& b);
bool test_sphere_capsule(const Sphere& a, const Capsule& b);
bool test_sphere_lozenge(const Sphere& a, const Lozenge& b);
bool test_capsule_capsule(const Capsule& a, const Capsule& b);
bool test_capsule_lozenge(const Capsule& a, const Lozenge& b);
bool test_lozenge_lozenge(const Lozenge& a, const Lozenge& b);

// ---- Steps 4 to 7: moving shapes ----------------------------------------------------
//
// A shape moves with constant velocity v from its given position at time 0 until time
// `duration` (T >= 0): its centre at time t is center + t v. The answer is one of three.

enum class SweepStatus {
  none,         // they never touch during [0, T]
  overlapping,  // already touching or overlapping at t = 0, whatever the motion
  contact,      // apart at t = 0; they first touch at `time`, 0 <= time <= T
};

struct Sweep {
  SweepStatus status = SweepStatus::none;
  double time = 0.0;          // contact: the first time of contact; otherwise 0
  Vec3 point = Vec3::Zero();  // contact: a point where they touch at `time` (within tol of both)
};

// ---- Step 4 (L05S4): moving sphere against a plane ----------------------------------

// The plane is two-sided (a thin sheet): the sphere meets it from whichever side it starts
// on. With s(t) = (normal . c(t) + offset) / |normal| the signed distance of the centre:
// overlapping when |s(0)| <= r; else contact at the first t with |s(t)| = r, which needs
// the sphere to move toward the plane (the lecture's "T < 0: moving away" is none). Its
// point is the sphere's point nearest the plane then: c(t) - r sign(s(0)) n / |n|.
Sweep sweep_sphere_plane(const Sphere& sphere, const Vec3& velocity, const Plane& plane, double duration);

// ---- Step 5 (L05S5): moving sphere against a moving sphere --------------------------

// Relative motion: A = c0 - c1, B = v0 - v1, R = r0 + r1; |A + t B|^2 = R^2 is
//   a t^2 + 2 b t + c = 0,  a = B.B, b = A.B, c = A.A - R^2.
// Overlapping when c <= 0. None when there is no relative motion (a = 0), when they move
// apart or sideways (b >= 0), when the closest approach misses (b^2 - ac < 0), or when
// the first root is after T. An exact graze (b^2 = ac) is a contact. The point lies on the
// segment between the centres at that time, r0 / R of the way from c0(t) (R = 0: c0(t)).
Sweep sweep_sphere_sphere(const Sphere& s0, const Vec3& v0, const Sphere& s1, const Vec3& v1, double duration);

// ---- Step 6 (L05S6): moving sphere against a capsule: a Minkowski sum ---------------

// Lecture 000's table 6.6 and lecture 002's swept sphere: shrink the sphere to its centre
// and grow the capsule by the sphere's radius. The grown capsule has the same axis and
// radius R = sphere.radius + capsule.radius (a cylinder with two hemispherical caps), and
// the question becomes where the ray c + t v first enters it.
// Overlapping when the centre is within R of the axis at t = 0 (touching counts). Else
// contact at the first t in [0, T] with distance(c(t), axis) = R, or none. Moving exactly
// parallel to the axis, a zero-length axis (a == b: the capsule is a sphere) and R = 0
// are all valid. The point is the sphere's point nearest the axis then: on the segment
// from c(t) to the axis's nearest point q(t), sphere.radius / R of the way (R = 0: c(t)).
// Decide first, as in step 3 (the sphere's whole path over [0, T] is a capsule: they meet
// exactly when it meets this one), then build the time; the time is certified as in
// step 5.
Sweep sweep_sphere_capsule(const Sphere& sphere, const Vec3& velocity, const Capsule& capsule, double duration);

// ---- Step 7 (L05S7): moving box against a plane -------------------------------------

// Project the box's half-sizes onto the unit normal: rho = sum_i h_i |n . axis_i| / |n|
// is the radius of the box seen along n; then it is step 4 with the centre's distance
// against rho. The point is a point of the box (at `time`) within tol of the plane: the
// corner nearest the plane, or, when a face or an edge touches, any point of it (its
// middle, a corner of it, ...): every such point passes.
Sweep sweep_box_plane(const Box& box, const Vec3& velocity, const Plane& plane, double duration);

// ---- Step 8 (L05S8): robustness: parallel, touching, grazing ------------------------
// No new function: steps 1, 4, 5 and 6 on exact degenerate input (small integers,
// |x| <= 64, times a power of two): parallel, collinear and crossing segments,
// zero-length segments, spheres exactly touching or grazing, contact exactly at T,
// touching at t = 0 while moving away, no relative motion, spheres a hair apart that
// meet very soon, and spheres sliding exactly parallel to a capsule's axis, starting on
// it, or meeting a zero-length one. On such input the statuses must be exactly right
// (nothing is ambiguous): decide by comparing squared distances without dividing
// (num <= R^2 den), then construct. Distances keep their tol.

// ---- Step 9 (L05S9): robustness: rectangles, static pairs, boxes --------------------
// No new function (an extension, as steps 2, 3 and 7 are): steps 2, 3 and 7 on the same
// exact input: zero-size rectangles, capsules and lozenges exactly touching, boxes
// resting on the plane. (Step 3's random and worked cases still hold you to the rules on
// lines that are parallel only up to rounding: there the rounded d0 x d1 is noise, so
// measure the pair.)

}  // namespace labkit::lab05
