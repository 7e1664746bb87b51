// Particles that move and bounce (lab 07): one-sided planes, two-sided triangles,
// impulses, integrators, launch angles and the exact side tests the invariants need.
// Every double is read as the exact number it is. Where a formula needs a square root
// (a length), the exact square is rounded, its root taken in double and used exactly
// from there: a relative error near 1e-16, far below every tolerance of the lab.
#pragma once

#include "common/geometry.h"

namespace oracle {

using labkit::Plane;
using labkit::Segment;
using labkit::Triangle;
using labkit::Vec3;

// ---- Surfaces ----------------------------------------------------------------------

// The segment hits the one-sided plane: value(a) >= 0 and value(b) < 0, exactly; never
// for a zero normal.
bool plane_hit(const Segment& s, const Plane& p);
// value(a) / (value(a) - value(b)), exact, rounded once (0 when value(a) = value(b)).
double plane_hit_t(const Segment& s, const Plane& p);
// (n . x + c) / |n|, rounded (0 for a zero normal).
double plane_distance(const Plane& p, const Vec3& x);
// The exact sign of n . x + c, by a filtered predicate: cheap enough for every particle
// of every step.
int plane_side(const Plane& p, const Vec3& x);
// (x - v0) . n / |n|, n = (v1 - v0) x (v2 - v0), rounded (0 for zero area).
double triangle_plane_distance(const Triangle& t, const Vec3& x);

// The segment hits the two-sided triangle: a is strictly off its plane and the segment
// meets the closed triangle, exactly. Never for a zero-area triangle.
bool sheet_hit(const Segment& s, const Triangle& t);

// ---- Impulse -----------------------------------------------------------------------

struct Impulse {
  bool closing = false;
  double v_close = 0.0;
  Vec3 normal_impulse = Vec3::Zero();
  Vec3 friction = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
};
// Lecture 001's impulse with restitution e and Coulomb friction mu (lab 07's header),
// with `normal` used as given (meant to be unit length).
Impulse impulse(const Vec3& velocity, const Vec3& object_velocity, const Vec3& normal, double mass, double e,
                double mu);

// ---- Integrators -------------------------------------------------------------------

struct State {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 previous = Vec3::Zero();
};
struct Forces {
  Vec3 gravity = Vec3::Zero();
  double drag = 0.0;      // F = -drag v
  double air_drag = 0.0;  // F = -air_drag |v| v
};
// m g - k1 v - k2 |v| v.
Vec3 force(const Vec3& velocity, double mass, const Forces& f);
// One explicit Euler step, one position Verlet step, and Verlet's starting previous
// position (lab 07's header, step 2).
State euler_step(const State& s, double mass, const Forces& f, double dt);
State verlet_step(const State& s, double mass, const Forces& f, double dt);
State start_verlet(const State& s, double mass, const Forces& f, double dt);

// ---- Launch angles -----------------------------------------------------------------

// D = v^4 + 2 v^2 (d . g) - |d x g|^2 with d = target - from: its exact sign, and its
// value rounded.
int launch_sign(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity);
double launch_discriminant(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity);
// The lecture's radicand x^2 - 4 A (A + y) = |d x g|^2 D / (|g|^2 v^4), rounded; 0 when
// x = 0, g = 0 or v = 0.
double launch_radicand(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity);
// Exact: (target - from) x gravity = 0 (the target is straight above or below).
bool launch_vertical(const Vec3& from, const Vec3& target, const Vec3& gravity);
// Exact: |from + velocity t + gravity t^2 / 2 - target| <= tolerance.
bool trajectory_reaches(const Vec3& from, const Vec3& velocity, double t, const Vec3& gravity, const Vec3& target,
                        double tolerance);

// ---- Speeds ------------------------------------------------------------------------

// Exact: |v|^2 <= factor |reference|^2, and |v|^2 >= factor |reference|^2.
bool squared_speed_at_most(const Vec3& v, const Vec3& reference, double factor);
bool squared_speed_at_least(const Vec3& v, const Vec3& reference, double factor);

}  // namespace oracle
