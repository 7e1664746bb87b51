// Lab 04: time of impact by bisection.
// Handout: handouts/04_bisection.md. Lectures 002 (overlap testing, bisect testing, its
// limits with fast objects), 000 and 004 (moving mesh vs. moving mesh: point sampling
// misses thin objects) and 003 (the 4D problem: contact between two time steps).
//
// You write labs/04_bisection/bisection.cpp; this header is the contract.
//
//   overlap?   no        no      no   yes  yes                 The lecture's bisection:
//   t          0 ...... 0.25  0.375 | 0.4375  0.5 ...... 1     clear at t0 = 0, overlap
//              |---------|-----|----|---|------|----------|    at t1 = 1; test the middle,
//                              0.40625                        keep the half whose ends
//                              (no)                           differ, until it is shorter
//   last clear time t = 0.40625, first overlap t_contact = 0.4375    than the tolerance.
//
// Two bodies move: the first is always a sphere (the ball, the bullet); the second is a
// sphere or an oriented box (the wall, the window). Each is given in its own frame and a
// Motion gives its pose at time t. Two boxes are left out on purpose: their overlap test
// is lab 03's separating-axis test, and their distance (step 4) needs a general convex
// distance algorithm; a sphere against a box needs only a closest point.
//
// Sets are closed: touching counts as overlap. "Clear at t" means the posed bodies have
// no point in common at t (their distance is positive). A sphere of radius 0 is a point;
// a box with zero half extents is a rectangle, a segment or a point. All of them count.
//
// Tolerances. S is the largest absolute coordinate of the two posed bodies at the time
// in question (centres, radii, half extents).
//  - Yes/no answers must equal the exact answer for the bodies posed by the motion's own
//    numbers (the oracle reads the pose it returns as exact), except on ambiguous
//    configurations: those whose answer changes when the input moves by a relative 1e-9
//    (the bodies touch, or nearly). There either answer passes.
//  - Distances: within 1e-9 S of the exact distance.
//  - Times are certified, not compared with another root: a search that reports a contact
//    must be clear at its t, overlap at its t_contact, and t < t_contact <= t + tolerance.
//
// The input domain on which these hold: every length (coordinates, radii, half extents,
// and what a motion adds in the times searched: velocity t, acceleration t^2 / 2) is 0
// or of magnitude between 1e-100 and 1e100, so that its square is a normal double; box
// axes are orthonormal up to rounding; spin axes are any non-zero vector. The tests draw
// scales from 2^-300 to 2^300 and tolerances down to 2^-30 (t1 - t0).
//
// Preconditions. Outside them the reference throws std::invalid_argument naming the
// function, the argument and the rule ("bisect: tolerance must be finite and > 0, got
// 0"); it never hangs. No step grades invalid input: your code may check or not.
//  - t0 and t1 finite, t0 <= t1, and t1 - t0 finite;
//  - tolerance finite, > 0 and at least 2^-50 max(|t0|, |t1|): a tolerance of 0, or one
//    below the spacing of doubles near t, would halve forever, since a bracket of two
//    neighbouring doubles has no midpoint between them;
//  - radii and half extents finite and >= 0, centres and points finite (every function
//    that takes a body checks it); the poses the motions return at the times asked
//    finite;
//  - sample_then_bisect: substeps >= 1; substeps_for, closing_speed and advance: speeds
//    and the step finite and >= 0, sizes finite and >= 0.
// The loops this bounds: bisection halves while hi - lo > tolerance, at most
// log2((t1 - t0) / tolerance) + 2 rounds (+2 for the rounding of midpoints); sampling
// tests n samples; advancement moves at least one tolerance per step, at most
// (t1 - t0) / tolerance + 1 steps.
#pragma once

#include "common/geometry.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace labkit::lab04 {

// ---- Given: motions -------------------------------------------------------------------

// A motion: the pose of a body at time t. Any callable will do (a keyframe player, a
// physics step, ...); the searches below only ever ask for poses.
using Motion = std::function<RigidTransform(double t)>;

// The standard motions of the tests and the handout, all one formula:
//   pose(t) x = start + velocity t + acceleration t^2 / 2 + R(t) x,
// where R(t) turns by the angle spin * t (radians, counter-clockwise) about `axis`
// through the body's own origin. A body whose shape sits away from its origin orbits.
struct StandardMotion {
  Vec3 start = Vec3::Zero();         // where the body's origin is at t = 0
  Vec3 velocity = Vec3::Zero();      // of the origin, at t = 0
  Vec3 acceleration = Vec3::Zero();  // constant
  Vec3 axis = Vec3::UnitZ();         // the spin axis (any non-zero length)
  double spin = 0.0;                 // radians per unit of time

  RigidTransform operator()(double t) const {
    RigidTransform pose = RigidTransform::Identity();
    if (spin != 0.0) pose.linear() = Eigen::AngleAxisd(spin * t, axis.normalized()).toRotationMatrix();
    pose.translation() = start + velocity * t + acceleration * (0.5 * t * t);
    return pose;
  }
};

inline Motion at_rest(const Vec3& position) { return StandardMotion{position}; }
inline Motion linear(const Vec3& start, const Vec3& velocity) { return StandardMotion{start, velocity}; }
inline Motion accelerating(const Vec3& start, const Vec3& velocity, const Vec3& acceleration) {
  return StandardMotion{start, velocity, acceleration};
}
// Spinning in place about an axis through the body's origin, which stays at `start`.
inline Motion rotating(const Vec3& start, const Vec3& axis, double spin) {
  return StandardMotion{start, Vec3::Zero(), Vec3::Zero(), axis, spin};
}
// Spinning about the axis while the origin moves along it by `advance` per unit of time.
inline Motion screw(const Vec3& start, const Vec3& axis, double spin, double advance) {
  return StandardMotion{start, advance * axis.normalized(), Vec3::Zero(), axis, spin};
}

// How far a body's points reach from its own origin.
inline double reach(const Sphere& s) { return s.center.norm() + s.radius; }
inline double reach(const Box& b) { return b.center.norm() + b.half_extents.norm(); }

// An upper bound on the speed of every point within `reach` of the body's origin, for t
// in [t0, t1]: the origin's speed |velocity + acceleration t| (largest at an end, the
// speed being convex in t) plus |spin| * reach for the turning.
inline double max_speed(const StandardMotion& m, double reach, double t0, double t1) {
  const double origin = std::max((m.velocity + m.acceleration * t0).norm(), (m.velocity + m.acceleration * t1).norm());
  return origin + std::abs(m.spin) * reach;
}

// ---- Given: the bodies ----------------------------------------------------------------

// The second body: a sphere or an oriented box (only the one `kind` names is used).
struct Shape {
  enum class Kind { sphere, box };
  Kind kind = Kind::sphere;
  Sphere sphere;
  Box box;
};
inline Shape shape_of(const Sphere& s) { return {Shape::Kind::sphere, s, Box{}}; }
inline Shape shape_of(const Box& b) { return {Shape::Kind::box, Sphere{}, b}; }

struct MovingPair {
  Sphere a;         // the first body, in its own frame
  Motion motion_a;  // its pose at time t
  Shape b;          // the second body, in its own frame
  Motion motion_b;
};

// What every search returns.
struct TimeOfImpact {
  bool hit = false;                   // a contact was found in [t0, t1]
  bool overlapping_at_start = false;  // the bodies overlap at t0 already: nothing was
                                      // searched, hit is true and t = t_contact = t0
  double t = 0.0;                     // hit: the last clear time found (clear at t);
                                      // no hit: t1 (clear at t1)
  double t_contact = 0.0;             // hit: the first overlapping time found, with
                                      // t < t_contact <= t + tolerance
  int steps = 0;                      // sub-steps tested (step 3) or advances (step 4)
  int iterations = 0;                 // halvings of the final bracket [t, t_contact]
};

// ---- Step 1 (L04S1): overlap at time t under any motion --------------------------------

// The body placed by a pose: the centre is moved by the pose, a box's axes are turned by
// its rotation; radius and half extents do not change.
Sphere placed(const Sphere& sphere, const RigidTransform& pose);
Box placed(const Box& box, const RigidTransform& pose);

// |c_a - c_b| <= r_a + r_b (touching counts).
bool overlap(const Sphere& a, const Sphere& b);

// The point of the closed box nearest to p: p itself when p is inside. The box's axes are
// orthonormal (up to rounding).
Vec3 closest_point(const Box& box, const Vec3& p);

// |c - closest_point(box, c)| <= r (touching counts).
bool overlap(const Sphere& a, const Box& b);

// Do the bodies overlap at time t? Pose both with their motions, then test.
bool overlap_at(const MovingPair& pair, double t);

// ---- Step 2 (L04S2): bisection to the last clear time ----------------------------------

// The lecture's overlap testing with bisection, on [t0, t1] (t0 <= t1):
//  - overlap at t0: {hit, overlapping_at_start, t = t_contact = t0}, nothing searched;
//  - clear at t1: no hit, t = t1 (point sampling saw nothing: it may have missed a
//    contact in between; that is step 3);
//  - otherwise the bracket [lo, hi] = [t0, t1] is clear at lo and overlapping at hi.
//    While hi - lo > tolerance: test the midpoint, count one iteration, and keep the
//    half whose ends still differ. Return t = lo, t_contact = hi: "the time right
//    before the collision", and the number of iterations (steps stays 0).
TimeOfImpact bisect(const MovingPair& pair, double t0, double t1, double tolerance);

// ---- Step 3 (L04S3): tunnelling and sub-steps ------------------------------------------

// The size of the body's thinnest dimension: a sphere's diameter, a box's smallest full
// extent (twice its smallest half extent).
double smallest_size(const Shape& shape);

// The speed in the lecture's rule is the speed of one object against another that
// stands still. When both move, what matters is how fast they close on each other: the
// speed of a relative to b, at most max_speed(a) + max_speed(b) (two bodies each at 3,
// head on, close at 6). closing_speed returns that sum, each body's max_speed over its
// own reach, on [t0, t1]. (The fastest body's speed alone is not a bound on it.)
double closing_speed(const Sphere& a, const StandardMotion& motion_a, const Shape& b, const StandardMotion& motion_b,
                     double t0, double t1);

// The lecture's rule: the speed times the time step must be smaller than the smallest
// object; for two moving bodies the speed is their closing speed (above). The smallest
// number of sub-steps n >= 1 with
//   closing_speed * (step / n) < smallest_size      (strictly).
// When no n up to kMaxSubsteps satisfies it (a size of zero, or a speed too high for
// the step), return 0: sub-stepping cannot make this motion safe.
constexpr int kMaxSubsteps = 1 << 20;
int substeps_for(double closing_speed, double step, double smallest_size);

// Point sampling with n = substeps sub-steps (n >= 1): test t0, then the sample times
//   t_k = t0 + (t1 - t0) * k / n   for k = 1, ..., n - 1   (computed exactly so),
//   t_n = t1.
// Overlap at t0: as bisect. At the first sample t_k that overlaps, bisect [t_{k-1}, t_k]
// (clear at t_{k-1}, overlapping at t_k) to the tolerance; steps = k. No sample
// overlaps: no hit, t = t1, steps = n. With n = 1 this is bisect itself.
TimeOfImpact sample_then_bisect(const MovingPair& pair, double t0, double t1, int substeps, double tolerance);

// ---- Step 4 (L04S4): conservative advancement ------------------------------------------

// The distance between the closed bodies: 0 when they overlap.
double distance(const Sphere& a, const Sphere& b);
double distance(const Sphere& a, const Box& b);
double distance_at(const MovingPair& pair, double t);

// Conservative advancement. max_closing_speed bounds how fast the distance can shrink
// (for standard motions: max_speed of a plus max_speed of b), so a body at distance d
// cannot touch the other before d / max_closing_speed has passed.
//  - overlap at t0: as bisect;
//  - from the clear time t, advance to next = t + max(d / max_closing_speed, tolerance),
//    but not beyond t1 (at least `tolerance` per step, so that a near miss cannot stall
//    the search); count one step;
//  - overlap at next: bisect [t, next] to the tolerance (iterations as in step 2) and
//    return; else if next == t1: no hit, t = t1; else continue from next.
// With a true speed bound this cannot jump over a contact that lasts longer than the
// tolerance: the d / speed advances are safe, and a forced advance is only `tolerance`.
TimeOfImpact advance(const MovingPair& pair, double t0, double t1, double max_closing_speed, double tolerance);

// ---- Step 5 (L04S5): robustness: touching and grazing ----------------------------------
// No new function: steps 1 to 4 must follow the rules at the top of this file on exact
// input (integer coordinates, times that are short binary fractions): bodies that touch
// at t0, at t1, at a midpoint or at a sample time, that only graze each other for one
// instant, zero radii and zero half extents, a speed bound that is exactly tight. (The
// times an advancement reaches come from a division, so the poses there are rounded: a
// touch within rounding of such a time stays ambiguous.)

}  // namespace labkit::lab04
