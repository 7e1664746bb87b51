// Lab 04 reference: time of impact by bisection.
//
// The one idea that makes it robust: decide with squares, never with roots. Every
// overlap below compares a sum of squares of input differences with a squared radius,
// so on integer input the decision is exact and touching (equality) stays touching.
// Roots are taken only for distances (step 4), after the decision.
//
// The searches never look inside the motion: they ask for poses at times of their
// choosing and test overlap there, so any callable will do.
#include "bisection.h"

#include "common/preconditions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace labkit::lab04 {

namespace {

// ---- The header's preconditions ---------------------------------------------------------
// Each check names the function, the argument and the rule, then what it got.

using namespace preconditions;

// A body of lab 04: a sphere, or a box whose axes are finite (orthonormal is the
// header's domain, not a precondition).
void require_body(const char* where, const char* name, const Sphere& s) { require_valid(where, name, s); }
void require_body(const char* where, const char* name, const Box& b) {
  if (b.center.allFinite() && b.axes.allFinite() && b.half_extents.allFinite() && b.half_extents.minCoeff() >= 0)
    return;
  require_finite(where, std::string(name) + ".center", b.center);
  require(b.axes.allFinite(), where, std::string(name) + ".axes", "be finite", "a NaN or an infinity");
  require_finite(where, std::string(name) + ".half_extents", b.half_extents);
  require(b.half_extents.minCoeff() >= 0, where, std::string(name) + ".half_extents", "be >= 0", b.half_extents);
}
void require_body(const char* where, const char* name, const Shape& b) {
  if (b.kind == Shape::Kind::sphere)
    require_body(where, name, b.sphere);
  else
    require_body(where, name, b.box);
}

// [t0, t1] and the tolerance. Why the floor on the tolerance: the halving loop stops only
// when hi - lo <= tolerance. Near t the doubles are about 2^-52 |t| apart, so with a
// tolerance below that spacing two neighbouring doubles are a bracket longer than the
// tolerance with no midpoint between them: the loop would run forever. At 2^-50 max|t|
// every bracket longer than the tolerance holds a few doubles, its computed midpoint
// lies strictly inside, and each round shrinks it to at most a little over half.
void require_times(const char* where, double t0, double t1, double tolerance) {
  require_finite(where, "t0", t0);
  require_finite(where, "t1", t1);
  if (!(t0 <= t1)) reject(where, "t0 <= t1", "hold", "t0 = " + text(t0) + ", t1 = " + text(t1));
  if (!std::isfinite(t1 - t0)) reject(where, "t1 - t0", "be finite", "t0 = " + text(t0) + ", t1 = " + text(t1));
  require_positive(where, "tolerance", tolerance);
  const double floor = std::ldexp(std::max(std::abs(t0), std::abs(t1)), -50);
  if (!(tolerance >= floor))
    reject(where, "tolerance",
           "be at least 2^-50 max(|t0|, |t1|) = " + text(floor) + " (finer times are not distinct doubles)",
           text(tolerance));
}

void require_pair(const char* where, const MovingPair& pair) {
  require_body(where, "pair.a", pair.a);
  require_body(where, "pair.b", pair.b);
  if (!pair.motion_a) reject(where, "pair.motion_a", "be a motion", "an empty std::function");
  if (!pair.motion_b) reject(where, "pair.motion_b", "be a motion", "an empty std::function");
}

RigidTransform pose_of(const Motion& motion, const char* name, double t) {
  const RigidTransform pose = motion(t);
  if (!pose.matrix().allFinite())
    throw std::invalid_argument(std::string(name) + " returned a pose that is not finite at t = " + text(t));
  return pose;
}

// The squared distance from p to the closed box. In the box's own coordinates
// s_k = (p - center) . axis_k the box is |s_k| <= h_k, so the nearest point clamps each
// s_k to [-h_k, h_k]; what is clamped away, max(|s_k| - h_k, 0), is the offset along
// that axis. Summing the squared excesses needs no constructed point.
//
//          axis 1
//            ^        p = (s_0, s_1), s_0 > h_0, s_1 > h_1: the nearest point is the
//     +------+------+ corner; the excesses (s_0 - h_0, s_1 - h_1) are the offset.
//     |      |      |
//     |      c------+--> axis 0        p beside a face (|s_1| <= h_1): only the
//     |             |                  excess along axis 0 counts.
//     +-------------+
double squared_distance(const Box& box, const Vec3& p) {
  const Vec3 d = p - box.center;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    // mutant clamp_in_world_axes (step 1, "own axes"): `.dot(box.axes.col(k))` -> `[k]`
    const double excess = std::abs(d.dot(box.axes.col(k))) - box.half_extents[k];
    if (excess > 0) sum += excess * excess;  // outside the slab of axis k
  }
  return sum;
}

struct Posed {
  Sphere a;
  Shape b;
};

// Both bodies where their motions put them at time t.
Posed posed_at(const MovingPair& pair, double t) {
  Posed p{placed(pair.a, pose_of(pair.motion_a, "pair.motion_a", t)), pair.b};
  const RigidTransform pose_b = pose_of(pair.motion_b, "pair.motion_b", t);
  if (pair.b.kind == Shape::Kind::sphere)
    p.b.sphere = placed(pair.b.sphere, pose_b);
  else
    p.b.box = placed(pair.b.box, pose_b);
  return p;
}

TimeOfImpact overlapping_at_start(double t0) {
  TimeOfImpact r;
  r.hit = true;
  r.overlapping_at_start = true;
  r.t = r.t_contact = t0;
  return r;
}

TimeOfImpact no_hit(double t1, int steps) {
  TimeOfImpact r;
  r.t = t1;
  r.steps = steps;
  return r;
}

// The lecture's bisection on a bracket that is clear at lo and overlapping at hi.
// Each test of the midpoint keeps the half whose ends still differ, so the invariant
// "clear at lo, overlapping at hi" holds throughout and a contact always lies between:
// lo only ever moves forward to a clear time, hi only backward to an overlapping one.
// After k halvings the bracket is (t1 - t0) / 2^k long, so the loop ends after about
// log2((hi - lo) / tolerance) rounds; require_times makes sure every round does halve.
TimeOfImpact halve(const MovingPair& pair, double lo, double hi, double tolerance) {
  TimeOfImpact r;
  r.hit = true;
  // mutant one_halving_too_many (step 2, "one halving too many", "hi - lo > tolerance"): `>` -> `>=`
  // Halving until the bracket has no length left: two neighbouring doubles have no
  // midpoint between them, and the loop never ends (the time-out names the bound).
  // mutant halves_to_zero (step 2, "log2", "tolerance"): `tolerance` -> `0`
  while (hi - lo > tolerance) {
    const double mid = lo + 0.5 * (hi - lo);
    ++r.iterations;
    // mutant keeps_the_wrong_half (step 2, "half whose ends differ"): `overlap_at` -> `!overlap_at`
    if (overlap_at(pair, mid))
      hi = mid;  // the contact began at or before mid: look back
    else
      lo = mid;  // still clear at mid: look forward
  }
  // mutant returns_the_overlapping_end (step 2, "last clear time", "overlapping end"): `lo` -> `hi`
  r.t = lo;
  r.t_contact = hi;
  return r;
}

}  // namespace

// ---- Step 1 ----------------------------------------------------------------------------

Sphere placed(const Sphere& sphere, const RigidTransform& pose) { return {pose * sphere.center, sphere.radius}; }

Box placed(const Box& box, const RigidTransform& pose) {
  // mutant axes_not_turned (step 1, "axes", "rotation"):
  //   `return {pose * box.center, pose.linear() * box.axes, box.half_extents};`
  //   -> `return {pose * box.center, box.axes, box.half_extents};`
  return {pose * box.center, pose.linear() * box.axes, box.half_extents};
}

bool overlap(const Sphere& a, const Sphere& b) {
  require_body("overlap", "a", a);
  require_body("overlap", "b", b);
  // |c_a - c_b| <= r_a + r_b, squared: both sides are non-negative, so squaring keeps
  // the order and the equality (touching) exactly.
  const double reach = a.radius + b.radius;
  // mutant touching_is_clear (step 1, "touching counts"): `<=` -> `<`
  return (a.center - b.center).squaredNorm() <= reach * reach;
}

Vec3 closest_point(const Box& box, const Vec3& p) {
  require_body("closest_point", "box", box);
  require_finite("closest_point", "p", p);
  const Vec3 d = p - box.center;
  Vec3 q = box.center;
  for (int k = 0; k < 3; ++k) {
    const double h = box.half_extents[k];
    // The closest point clamped in the box's own axes and left there: its local
    // coordinates returned, never taken back to the world (centre + sum of s_k axis_k).
    // mutant closest_point_left_local (step 1, "taken back to the world"):
    //   `q += std::clamp(d.dot(box.axes.col(k)), -h, h) * box.axes.col(k);`
    //   -> `q[k] = std::clamp(d.dot(box.axes.col(k)), -h, h);`
    q += std::clamp(d.dot(box.axes.col(k)), -h, h) * box.axes.col(k);
  }
  return q;
}

bool overlap(const Sphere& a, const Box& b) {
  require_body("overlap", "a", a);
  require_body("overlap", "b", b);
  // The header's closed sets: a strict < misses a touch (handout step 5; step 1's examples
  // already touch a face).
  // mutant touching_a_box_is_clear (step 1, "touching counts"): `<=` -> `<`
  // A fuzzy 1e-9 (handout step 5): a near miss at the scale 1e-6 counts as a contact.
  // mutant magic_epsilon (step 1, "epsilon", "clear"): `a.radius * a.radius` -> `a.radius * a.radius + 1e-9`
  return squared_distance(b, a.center) <= a.radius * a.radius;
}

bool overlap_at(const MovingPair& pair, double t) {
  require_pair("overlap_at", pair);
  require_finite("overlap_at", "t", t);
  const Posed p = posed_at(pair, t);
  return p.b.kind == Shape::Kind::sphere ? overlap(p.a, p.b.sphere) : overlap(p.a, p.b.box);
}

// ---- Step 2 ----------------------------------------------------------------------------

// The lecture tests the end of the frame first ("collision detected"), then bisects back
// toward the last frame, which it knows to be clear. We test both ends: a start that
// already overlaps has no "time right before the collision".
TimeOfImpact bisect(const MovingPair& pair, double t0, double t1, double tolerance) {
  require_pair("bisect", pair);
  require_times("bisect", t0, t1, tolerance);
  // mutant start_assumed_clear (step 2, "already overlap at t0"):
  //   `if (overlap_at(pair, t0)) return overlapping_at_start(t0); if (!overlap_at(pair, t1))`
  //   -> `if (!overlap_at(pair, t1))`
  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  if (!overlap_at(pair, t1)) return no_hit(t1, 0);  // clear at both ends: nothing seen
  return halve(pair, t0, t1, tolerance);
}

// ---- Step 3 ----------------------------------------------------------------------------

double smallest_size(const Shape& shape) {
  require_body("smallest_size", "shape", shape);
  // A sphere's smallest size taken as its radius: a sphere is as thin as its diameter.
  // mutant sphere_size_is_radius (step 3, "diameter", "1/2 of the answer"):
  //   `return 2 * shape.sphere.radius`
  //   -> `return shape.sphere.radius`
  if (shape.kind == Shape::Kind::sphere) return 2 * shape.sphere.radius;
  return 2 * shape.box.half_extents.minCoeff();
}

// Bodies closing at most at closing_speed get at most closing_speed * step / n closer
// in one sub-step.
// The lecture wants that strictly below the smallest size: n > max_speed * step / size,
// so n = floor(ratio) + 1 (when the ratio is a whole number m, n = m gives equality,
// which is not "smaller").
int substeps_for(double closing_speed, double step, double smallest_size) {
  require_size("substeps_for", "closing_speed", closing_speed);
  require_size("substeps_for", "step", step);
  require_size("substeps_for", "smallest_size", smallest_size);
  if (smallest_size == 0) return 0;  // a zero size can slip between any two samples
  const double ratio = closing_speed * step / smallest_size;
  if (!(ratio < kMaxSubsteps)) return 0;  // too many sub-steps (or not a number)
  // mutant substeps_not_strict (step 3, "strict"): `int(std::floor(ratio)) + 1` -> `std::max(1, int(std::ceil(ratio)))`
  return int(std::floor(ratio)) + 1;
}

// Point sampling at n sub-steps finds every contact that lasts longer than one sub-step;
// the rule above makes a body that passes right through the other take that long.
TimeOfImpact sample_then_bisect(const MovingPair& pair, double t0, double t1, int substeps, double tolerance) {
  require_pair("sample_then_bisect", pair);
  require_times("sample_then_bisect", t0, t1, tolerance);
  require(substeps >= 1, "sample_then_bisect", "substeps", "be >= 1", substeps);
  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  double previous = t0;
  // mutant samples_the_end_only (step 3, "every sample"): `= 1` -> `= substeps`
  for (int k = 1; k <= substeps; ++k) {
    const double tk = k == substeps ? t1 : t0 + (t1 - t0) * k / substeps;
    if (!overlap_at(pair, tk)) {  // still clear: the next sub-step
      previous = tk;
      continue;
    }
    // mutant bisects_from_the_start (step 3, "first overlapping sub-step"): `previous` -> `t0`
    TimeOfImpact r = halve(pair, previous, tk, tolerance);
    r.steps = k;
    return r;
  }
  return no_hit(t1, substeps);
}

// Each body's points move at most its max_speed, so the gap between the two bodies
// shrinks at most at the sum: that is the speed at which they can close on each other.
// The faster body's speed alone is not enough: two bodies at 3 each, head on, close at 6.
double closing_speed(const Sphere& a, const StandardMotion& motion_a, const Shape& b, const StandardMotion& motion_b,
                     double t0, double t1) {
  require_body("closing_speed", "a", a);
  require_body("closing_speed", "b", b);
  require_finite("closing_speed", "t0", t0);
  require_finite("closing_speed", "t1", t1);
  if (!(t0 <= t1)) reject("closing_speed", "t0 <= t1", "hold", "t0 = " + text(t0) + ", t1 = " + text(t1));
  // A box's reach taken as its bounding sphere's radius |h| about its own centre: the
  // header's reach is from the body's origin, |c| + |h|, and a box set off its origin orbits.
  // mutant box_reach_from_its_centre (step 3, "each over its reach"): `reach(b.box)` -> `b.box.half_extents.norm()`
  const double reach_b = b.kind == Shape::Kind::sphere ? reach(b.sphere) : reach(b.box);
  const double speed_a = max_speed(motion_a, reach(a), t0, t1), speed_b = max_speed(motion_b, reach_b, t0, t1);
  const char* rule = "have a finite velocity, acceleration and spin";
  if (!std::isfinite(speed_a)) reject("closing_speed", "motion_a", rule, "a speed of " + text(speed_a));
  if (!std::isfinite(speed_b)) reject("closing_speed", "motion_b", rule, "a speed of " + text(speed_b));
  // The lecture's "speed of the fastest object" taken literally for two moving bodies.
  // mutant closing_speed_of_the_fastest (step 3, "relative speed", "sum"):
  //   `speed_a + speed_b`
  //   -> `std::max(speed_a, speed_b)`
  return speed_a + speed_b;
}

// ---- Step 4 ----------------------------------------------------------------------------

double distance(const Sphere& a, const Sphere& b) {
  require_body("distance", "a", a);
  require_body("distance", "b", b);
  const double reach = a.radius + b.radius;
  const double d2 = (a.center - b.center).squaredNorm();
  if (d2 <= reach * reach) return 0.0;  // overlapping: decided as in step 1
  // mutant distance_between_centres (step 4, "centres", "radii"):
  //   `return std::sqrt(d2) - reach;`
  //   -> `return std::sqrt(d2);`
  return std::sqrt(d2) - reach;
}

double distance(const Sphere& a, const Box& b) {
  require_body("distance", "a", a);
  require_body("distance", "b", b);
  const double d2 = squared_distance(b, a.center);
  if (d2 <= a.radius * a.radius) return 0.0;
  return std::sqrt(d2) - a.radius;
}

double distance_at(const MovingPair& pair, double t) {
  require_pair("distance_at", pair);
  require_finite("distance_at", "t", t);
  const Posed p = posed_at(pair, t);
  return p.b.kind == Shape::Kind::sphere ? distance(p.a, p.b.sphere) : distance(p.a, p.b.box);
}

// If no point moves faster than v, the distance d(t) between the bodies shrinks at most
// at rate v (each of the two nearest points moves at most its own speed, and the bound
// covers both): d(t + s) >= d(t) - v s. So d(t + s) > 0 for every s < d(t) / v: the
// advance to t + d / v cannot pass a contact. Far apart the advances are long; close
// up they shrink with the distance, and the floor of one tolerance ends a near miss:
// every step moves t forward by at least the tolerance (require_times makes t + tolerance
// a later double), so there are at most (t1 - t0) / tolerance + 1 steps.
TimeOfImpact advance(const MovingPair& pair, double t0, double t1, double max_closing_speed, double tolerance) {
  require_pair("advance", pair);
  require_times("advance", t0, t1, tolerance);
  require_size("advance", "max_closing_speed", max_closing_speed);
  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  double t = t0;
  int steps = 0;
  for (;;) {
    const double d = distance_at(pair, t);
    // A bound of zero: nothing moves toward anything, the whole interval is safe.
    // mutant advance_by_the_distance (step 4, "d / v", "time"): `? d / max_closing_speed :` -> `? d :`
    const double safe = max_closing_speed > 0 ? d / max_closing_speed : std::numeric_limits<double>::infinity();
    // Without the floor of one tolerance a near miss creeps forward forever (handout step 4).
    // mutant advance_without_the_floor (step 4, "at least one tolerance"): `std::max(safe, tolerance)` -> `safe`
    const double next = std::min(t + std::max(safe, tolerance), t1);
    ++steps;
    if (overlap_at(pair, next)) {  // the contact began in (t, next]: bisection finishes
      // mutant advance_without_bisecting (step 4, "bisection", "tolerance"):
      //   `TimeOfImpact r = halve(pair, t, next, tolerance);`
      //   -> `TimeOfImpact r; r.hit = true; r.t = t; r.t_contact = next;`
      TimeOfImpact r = halve(pair, t, next, tolerance);
      r.steps = steps;
      return r;
    }
    if (next == t1) return no_hit(t1, steps);  // clear all the way
    t = next;
  }
}

}  // namespace labkit::lab04
