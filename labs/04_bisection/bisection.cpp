// Lab 04: time of impact by bisection. Your file: replace each stub below.
// The contract is bisection.h; the steps are in handouts/04_bisection.md.
// Check your work with:  ./labkit check 04        (one step: ./labkit check 04 --step 1)
#include "bisection.h"

#include "common/not_implemented.h"

namespace labkit::lab04 {

// L04S1: move the centre by the pose.
Sphere placed(const Sphere& sphere, const RigidTransform& pose) { not_implemented("L04S1", sphere, pose); }

// L04S1: move the centre, turn the axes.
Box placed(const Box& box, const RigidTransform& pose) { not_implemented("L04S1", box, pose); }

// L04S1: two spheres.
bool overlap(const Sphere& a, const Sphere& b) { not_implemented("L04S1", a, b); }

// L04S1: clamp in the box's own coordinates.
Vec3 closest_point(const Box& box, const Vec3& p) { not_implemented("L04S1", box, p); }

// L04S1: a sphere and a box.
bool overlap(const Sphere& a, const Box& b) { not_implemented("L04S1", a, b); }

// L04S1: pose both bodies at time t, then test.
bool overlap_at(const MovingPair& pair, double t) { not_implemented("L04S1", pair, t); }

// L04S2: the ends, then halve the bracket.
TimeOfImpact bisect(const MovingPair& pair, double t0, double t1, double tolerance) {
  not_implemented("L04S2", pair, t0, t1, tolerance);
}

// L04S3: the thinnest dimension.
double smallest_size(const Shape& shape) { not_implemented("L04S3", shape); }

// L04S3: how fast the two bodies can close on each other.
double closing_speed(const Sphere& a, const StandardMotion& motion_a, const Shape& b, const StandardMotion& motion_b,
                     double t0, double t1) {
  not_implemented("L04S3", a, motion_a, b, motion_b, t0, t1);
}

// L04S3: closing speed x (step / n) < smallest size.
int substeps_for(double closing_speed, double step, double smallest_size) {
  not_implemented("L04S3", closing_speed, step, smallest_size);
}

// L04S3: sample, then bisect the first bracket.
TimeOfImpact sample_then_bisect(const MovingPair& pair, double t0, double t1, int substeps, double tolerance) {
  not_implemented("L04S3", pair, t0, t1, substeps, tolerance);
}

// L04S4: two spheres.
double distance(const Sphere& a, const Sphere& b) { not_implemented("L04S4", a, b); }

// L04S4: a sphere and a box.
double distance(const Sphere& a, const Box& b) { not_implemented("L04S4", a, b); }

// L04S4: pose both bodies at time t, then measure.
double distance_at(const MovingPair& pair, double t) { not_implemented("L04S4", pair, t); }

// L04S4: advance by distance / speed, at least the tolerance.
TimeOfImpact advance(const MovingPair& pair, double t0, double t1, double max_closing_speed, double tolerance) {
  not_implemented("L04S4", pair, t0, t1, max_closing_speed, tolerance);
}

}  // namespace labkit::lab04
