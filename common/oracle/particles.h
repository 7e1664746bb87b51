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

// ---- Springs (step 9) --------------------------------------------------------------

// The force on a of a damped spring from a to b (lab 07's header, step 9):
//   d = a - b, l = |d|, u = d / l,  F_a = -(k_s (l - l_rest) + k_d ((v_a - v_b) . u)) u,
// zero when d = 0. l is the exact |d|^2 rounded and rooted in double (see above); the
// rest is exact, rounded once.
Vec3 spring_force(const Vec3& position_a, const Vec3& velocity_a, const Vec3& position_b, const Vec3& velocity_b,
                  double stiffness, double damping, double rest_length);

// ---- Rigid bodies (step 10) --------------------------------------------------------

struct Body {
  Vec3 centre = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  double mass = 1.0;
  labkit::Mat3 inverse_inertia = labkit::Mat3::Identity();  // world frame
};
struct RigidImpulse {
  bool closing = false;      // v_rel < 0, exactly
  double v_rel = 0.0;        // n . ((v_a + w_a x r_a) - (v_b + w_b x r_b)), r = point - centre
  double j = 0.0;            // -(1 + e) v_rel / denominator when closing, else 0
  double denominator = 0.0;  // 1/m_a + 1/m_b + n . ((I_a^-1 (r_a x n)) x r_a) + (the same for b)
  Vec3 velocity_a = Vec3::Zero(), angular_velocity_a = Vec3::Zero();
  Vec3 velocity_b = Vec3::Zero(), angular_velocity_b = Vec3::Zero();
};
// Lecture 003's contact algorithm with restitution e, `normal` used as given (meant to be
// unit length, from b toward a): every operation is rational, so all of it is exact.
RigidImpulse rigid_impulse(const Body& a, const Body& b, const Vec3& point, const Vec3& normal, double e);
// The invariants of an answer, exact and rounded once: the change of linear momentum
// m_a (v_a' - v_a) + m_b (v_b' - v_b) (zero for any impulse pair J, -J), and
// v_rel' + e v_rel with v_rel' the relative normal velocity of the contact points after
// (zero for a closing contact).
Vec3 momentum_change(const Body& a, const Body& b, const Vec3& velocity_a, const Vec3& velocity_b);
double restitution_defect(const Body& a, const Body& b, const Body& a_after, const Body& b_after, const Vec3& point,
                          const Vec3& normal, double e);

}  // namespace oracle
