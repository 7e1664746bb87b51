// Exact distances between the cores of sphere-swept volumes (points, segments,
// rectangles), and exact facts about spheres and boxes moving with constant velocity
// (lab 05). Every double is read as the exact rational it is: a rectangle is the exact
// parallelogram center +- half_u u +- half_v v of its numbers, a box the exact
// parallelepiped of its numbers, a plane normal . x + offset = 0 with any normal length.
#pragma once

#include "common/geometry.h"

#include <memory>

namespace oracle {

using labkit::Box;
using labkit::Capsule;
using labkit::Plane;
using labkit::Rectangle;
using labkit::Segment;
using labkit::Sphere;
using labkit::Vec3;

// An exact squared distance, kept exact so that it can be compared exactly.
class SquaredDistance {
 public:
  struct Exact;  // the exact number (CGAL's, private to the oracle)
  explicit SquaredDistance(std::shared_ptr<const Exact> exact) : exact_(std::move(exact)) {}
  // Rounded to a relative 1e-12.
  double value() const;
  double distance() const;
  // The exact sign of distance - (l0 + l1 + l2), the sum taken exactly: -1, 0 or +1.
  int compare(double l0, double l1 = 0.0, double l2 = 0.0) const;

 private:
  std::shared_ptr<const Exact> exact_;
};

SquaredDistance squared_distance(const Vec3& p, const Vec3& q);
SquaredDistance squared_distance(const Vec3& p, const Segment& s);
SquaredDistance squared_distance(const Segment& s0, const Segment& s1);
SquaredDistance squared_distance(const Vec3& p, const Rectangle& r);
SquaredDistance squared_distance(const Segment& s, const Rectangle& r);
SquaredDistance squared_distance(const Rectangle& r0, const Rectangle& r1);

// Exact: is center + s u + t v within `tolerance` of x (|s|, |t| need not be in range)?
bool rectangle_point_reproduces(const Rectangle& r, double s, double t, const Vec3& x, double tolerance);

// ---- Moving shapes: positions at time t are center + t velocity ---------------------
//
// The gap of a sweep at time t: for two spheres |c0(t) - c1(t)| - (r0 + r1); for a sphere
// and a plane, the centre's distance to the plane minus r; for a box and a plane,
// (|value(c(t))| - sum_i h_i |normal . axis_i|) / |normal|. Touching is gap 0.

struct SphereSphereSweep {
  Sphere s0, s1;
  Vec3 v0 = Vec3::Zero(), v1 = Vec3::Zero();
};
struct SpherePlaneSweep {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
};
// A sphere moving against a static capsule: gap(t) = distance(c(t), axis) - (r + rc).
struct SphereCapsuleSweep {
  Sphere sphere;
  Vec3 velocity = Vec3::Zero();
  Capsule capsule;
};
struct BoxPlaneSweep {
  Box box;
  Vec3 velocity = Vec3::Zero();
  Plane plane;
};

// The exact sign of gap(t) - extra.
int gap_sign(const SphereSphereSweep& in, double t, double extra);
int gap_sign(const SpherePlaneSweep& in, double t, double extra);
int gap_sign(const BoxPlaneSweep& in, double t, double extra);
int gap_sign(const SphereCapsuleSweep& in, double t, double extra);
// The exact sign of (the smallest gap over [0, t_end]) - extra, t_end >= 0.
int min_gap_sign(const SphereSphereSweep& in, double t_end, double extra);
int min_gap_sign(const SpherePlaneSweep& in, double t_end, double extra);
int min_gap_sign(const BoxPlaneSweep& in, double t_end, double extra);
// (For the capsule: the distance between the centre's exact path c + [0, t_end] v and
// the axis, two exact segments.)
int min_gap_sign(const SphereCapsuleSweep& in, double t_end, double extra);

// The first time of contact in [0, t_end] (0 when touching at 0), or -1 when there is
// none: exact decisions, the root itself rounded (for reports only).
double first_contact(const SphereSphereSweep& in, double t_end);
double first_contact(const SpherePlaneSweep& in, double t_end);
double first_contact(const BoxPlaneSweep& in, double t_end);
double first_contact(const SphereCapsuleSweep& in, double t_end);

// Are A = c0 - c1, B = v0 - v1, R = r0 + r1 and the coefficients A.A, A.B, B.B, R^2
// exact in double (every product and every partial sum), and is the approach not
// grazing: apart at 0, approaching, and b^2 - ac >= b^2 / 4?
bool sphere_sweep_exact_and_steep(const SphereSphereSweep& in);

// Exact: is x within r + tolerance of the sphere's centre at time t?
bool within_moving_sphere(const Sphere& s, const Vec3& v, double t, const Vec3& x, double tolerance);
// Exact: is x within rc + tolerance of the capsule's axis?
bool within_capsule(const Capsule& capsule, const Vec3& x, double tolerance);
// Exact: |value(x)| <= tolerance |normal|.
bool within_plane(const Plane& plane, const Vec3& x, double tolerance);
// Exact: x in the box at time t grown by tolerance along each axis:
// |(x - c(t)) . axis_i| <= (h_i + tolerance) |axis_i|^2.
bool within_moving_box(const Box& box, const Vec3& v, double t, const Vec3& x, double tolerance);

}  // namespace oracle
