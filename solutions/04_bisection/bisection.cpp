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

#include <algorithm>
#include <cmath>
#include <limits>

namespace labkit::lab04 {

namespace {

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
  Posed p{placed(pair.a, pair.motion_a(t)), pair.b};
  const RigidTransform pose_b = pair.motion_b(t);
  if (pair.b.kind == Shape::Kind::sphere) p.b.sphere = placed(pair.b.sphere, pose_b);
  else p.b.box = placed(pair.b.box, pose_b);
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
// After k halvings the bracket is (t1 - t0) / 2^k long.
TimeOfImpact halve(const MovingPair& pair, double lo, double hi, double tolerance) {
  TimeOfImpact r;
  r.hit = true;
  while (hi - lo > tolerance) {
    const double mid = lo + 0.5 * (hi - lo);
    ++r.iterations;
    if (overlap_at(pair, mid)) hi = mid;  // the contact began at or before mid: look back
    else lo = mid;                        // still clear at mid: look forward
  }
  r.t = lo;
  r.t_contact = hi;
  return r;
}

}  // namespace

// ---- Step 1 ----------------------------------------------------------------------------

Sphere placed(const Sphere& sphere, const RigidTransform& pose) { return {pose * sphere.center, sphere.radius}; }

Box placed(const Box& box, const RigidTransform& pose) {
  return {pose * box.center, pose.linear() * box.axes, box.half_extents};
}

bool overlap(const Sphere& a, const Sphere& b) {
  // |c_a - c_b| <= r_a + r_b, squared: both sides are non-negative, so squaring keeps
  // the order and the equality (touching) exactly.
  const double reach = a.radius + b.radius;
  return (a.center - b.center).squaredNorm() <= reach * reach;
}

Vec3 closest_point(const Box& box, const Vec3& p) {
  const Vec3 d = p - box.center;
  Vec3 q = box.center;
  for (int k = 0; k < 3; ++k) {
    const double h = box.half_extents[k];
    q += std::clamp(d.dot(box.axes.col(k)), -h, h) * box.axes.col(k);
  }
  return q;
}

bool overlap(const Sphere& a, const Box& b) { return squared_distance(b, a.center) <= a.radius * a.radius; }

bool overlap_at(const MovingPair& pair, double t) {
  const Posed p = posed_at(pair, t);
  return p.b.kind == Shape::Kind::sphere ? overlap(p.a, p.b.sphere) : overlap(p.a, p.b.box);
}

// ---- Step 2 ----------------------------------------------------------------------------

// The lecture tests the end of the frame first ("collision detected"), then bisects back
// toward the last frame, which it knows to be clear. We test both ends: a start that
// already overlaps has no "time right before the collision".
TimeOfImpact bisect(const MovingPair& pair, double t0, double t1, double tolerance) {
  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  if (!overlap_at(pair, t1)) return no_hit(t1, 0);  // clear at both ends: nothing seen
  return halve(pair, t0, t1, tolerance);
}

// ---- Step 3 ----------------------------------------------------------------------------

double smallest_size(const Shape& shape) {
  if (shape.kind == Shape::Kind::sphere) return 2 * shape.sphere.radius;
  return 2 * shape.box.half_extents.minCoeff();
}

// A body moving at most max_speed covers at most max_speed * step / n in one sub-step.
// The lecture wants that strictly below the smallest size: n > max_speed * step / size,
// so n = floor(ratio) + 1 (when the ratio is a whole number m, n = m gives equality,
// which is not "smaller").
int substeps_for(double max_speed, double step, double smallest_size) {
  if (!(smallest_size > 0)) return 0;  // a zero size can slip between any two samples
  const double ratio = max_speed * step / smallest_size;
  if (!(ratio < kMaxSubsteps)) return 0;  // too many sub-steps (or not a number)
  return int(std::floor(ratio)) + 1;
}

// Point sampling at n sub-steps finds every contact that lasts longer than one sub-step;
// the rule above makes a body that passes right through the other take that long.
TimeOfImpact sample_then_bisect(const MovingPair& pair, double t0, double t1, int substeps, double tolerance) {
  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  double previous = t0;
  for (int k = 1; k <= substeps; ++k) {
    const double tk = k == substeps ? t1 : t0 + (t1 - t0) * k / substeps;
    if (!overlap_at(pair, tk)) {  // still clear: the next sub-step
      previous = tk;
      continue;
    }
    TimeOfImpact r = halve(pair, previous, tk, tolerance);
    r.steps = k;
    return r;
  }
  return no_hit(t1, substeps);
}

// ---- Step 4 ----------------------------------------------------------------------------

double distance(const Sphere& a, const Sphere& b) {
  const double reach = a.radius + b.radius;
  const double d2 = (a.center - b.center).squaredNorm();
  if (d2 <= reach * reach) return 0.0;  // overlapping: decided as in step 1
  return std::sqrt(d2) - reach;
}

double distance(const Sphere& a, const Box& b) {
  const double d2 = squared_distance(b, a.center);
  if (d2 <= a.radius * a.radius) return 0.0;
  return std::sqrt(d2) - a.radius;
}

double distance_at(const MovingPair& pair, double t) {
  const Posed p = posed_at(pair, t);
  return p.b.kind == Shape::Kind::sphere ? distance(p.a, p.b.sphere) : distance(p.a, p.b.box);
}

// If no point moves faster than v, the distance d(t) between the bodies shrinks at most
// at rate v (each of the two nearest points moves at most its own speed, and the bound
// covers both): d(t + s) >= d(t) - v s. So d(t + s) > 0 for every s < d(t) / v: the
// advance to t + d / v cannot pass a contact. Far apart the advances are long; close
// up they shrink with the distance, and the floor of one tolerance ends a near miss.
TimeOfImpact advance(const MovingPair& pair, double t0, double t1, double max_closing_speed, double tolerance) {
  if (overlap_at(pair, t0)) return overlapping_at_start(t0);
  double t = t0;
  int steps = 0;
  for (;;) {
    const double d = distance_at(pair, t);
    // A bound of zero: nothing moves toward anything, the whole interval is safe.
    const double safe = max_closing_speed > 0 ? d / max_closing_speed : std::numeric_limits<double>::infinity();
    const double next = std::min(t + std::max(safe, tolerance), t1);
    ++steps;
    if (overlap_at(pair, next)) {  // the contact began in (t, next]: bisection finishes
      TimeOfImpact r = halve(pair, t, next, tolerance);
      r.steps = steps;
      return r;
    }
    if (next == t1) return no_hit(t1, steps);  // clear all the way
    t = next;
  }
}

}  // namespace labkit::lab04
