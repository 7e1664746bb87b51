// Lab 07: particle systems that bounce.
// Handout: handouts/07_particles.md (steps 9 and 10: handouts/07_particles.extensions.md).
// Lectures 001 (Collision Handling Part 2 of 2: dynamic collision response, particle
// systems), 002 (Math, Physics and Collision Detection: particle physics, Euler and Verlet,
// target practice, springs and damping), 003 (Simulation and Animation: the contact
// algorithm for rigid bodies, step 10) and 004 (Collision Detection: particle collisions,
// collision response).
//
// You write labs/07_particles/particles.cpp; this header is the contract.
//
// One step of the system (System::step, the lecture's handling loop):
//
//   births -> for each particle: forces -> integrate -> the step as a segment a -> b
//                                 -> collide: first hit on the segment? impulse, then
//                                    travel the remaining time from the hit point, and
//                                    test that piece again (at most `bounce_cap` times)
//                                 -> settle: never end behind a surface
//          -> age every particle; remove the dead
//
//      a                         q       a: where the particle starts the step
//        \                     /         b: where the integrator would put it
//          \                 /   v'      x: the first hit, a + t (b - a)
//            \             /             q: where it ends: x + v' (1 - t) dt, with v'
//   ===========x==========/=========        the velocity after the impulse
//   solid       \          n ^
//                 b  (never allowed: behind the surface)
//
// Surfaces. A Plane is the boundary of a solid half-space: the solid is behind it, where
// n . x + c < 0, and it is hit only from the front (one-sided). The triangles of a mesh are
// thin sheets, hit from either side (two-sided). A scene may move (Scene::velocity): all its
// surfaces translate together at a constant velocity u during the step, like one rigid
// object (a paddle, a lift), and are given where they are at the END of the step.
//
// Degenerate rules (step 4). A segment hits a plane when a is not behind it and b is:
// value(a) >= 0 and value(b) < 0, with value(x) = n . x + c. A particle exactly on the plane
// is not behind it, and one starting on it hits at t = 0 if it moves behind. "On it" for a
// is decided with value(a)'s rounding bound (step 7's plane bound): a computed value(a)
// within its bound of 0 counts as 0, because a particle resting on a plane (a bounce's
// settled point) can compute n . a + c a hair below zero; it must still hit the plane it
// moves behind. b's side is the sign of its computed value(b), with no bound. A segment
// hits a triangle when a is strictly off the triangle's plane and the segment meets the
// closed triangle (edges and vertices count; use the given watertight
// labkit::given::segment_triangle); a particle starting on the triangle's plane is leaving
// it and never hits it. A plane with a zero normal and a zero-area triangle are never hit.
// The first hit is the one with the smallest t; on a tie, planes before triangles, then the
// lower index.
//
// Tolerances. S is the largest absolute coordinate of the input's points (particle
// positions, segment ends, mesh vertices, and each plane's point nearest the origin,
// |c| / |n|), and tol = 1e-9 S. V is the largest absolute component of the input's
// velocities, and tol_v = 1e-9 V.
//  - Yes/no answers must equal the exact answer, except on ambiguous inputs, whose exact
//    answer changes under a relative perturbation of 1e-9: there either answer passes.
//  - Points within tol; velocities within tol_v; the parameter t of a hit within
//    tol / |d_a - d_b| (d: unit-normal signed distances of a and b).
//  - Unit normals within 1e-9; a triangle's within 1e-9 + 2 tol / h, h its smallest height
//    (a needle's plane turns that much when its vertices move by tol).
//  - Launch angles (step 3): each within how far the exact angle moves when the input
//    moves by a relative 1e-9 (to first order), plus 1e-15. For a near, fast shot this is
//    about 1e-9 S / x: the low angle must be right to its own size, not to the high one's.
//  - Integrators: within 1e-9 times the sum of the magnitudes of the terms added.
//  - Never behind a surface: exact (steps 7, 8). Energy: 1e-12, relative (step 8).
//  - The spring force (step 9) and the rigid-body impulse (step 10): see their steps.
//
// Input domain: answers must match the exact ones (as above) for every input whose
// coordinates, velocity and gravity components and speeds are 0 or of magnitude 2^-130 to
// 2^130 (about 1e-39 to 1e39), with masses and time steps of magnitude 2^-20 to 2^20, and
// within one input, the gaps between its surfaces (a crack) at least 2^-40 S.
// Plane normals need not be unit (any non-zero length in that range); triangles may be
// needles (aspect ratios up to 1e8). The tests draw from across it, out to about 2^-120
// and 2^120. Step 9: stiffness and damping 0 or of magnitude 2^-20 to 2^20, the rest
// length a length. Step 10: angular velocities and inverse-inertia entries 0 or of
// magnitude 2^-130 to 2^130 (its tests draw lengths and speeds from 2^-40 to 2^40, so
// that w = v / length and I^-1 = 1 / (m length^2) stay inside).
//
// Preconditions. Each function refuses invalid input with std::invalid_argument, its
// message naming the argument and the rule (e.g. "impulse: mass must be finite and > 0,
// got 0"); the tests never pass such input except in their [contract] test, which is not
// graded. Every number must be finite (no NaN, no infinity), and:
//  - emit, births, System: emitter.half_extents >= 0, direction non-zero, cone in [0, pi],
//    0 <= speed_spread <= speed, 0 <= lifetime_spread <= lifetime, mass > 0, rate >= 0,
//    owed in [0, 1);
//  - births and age: dt >= 0; the integrators, collide and System::step: dt > 0;
//  - force, the integrators, System: every particle's mass > 0; forces.drag, air_drag >= 0;
//  - aim: speed >= 0 (a zero speed or gravity is no error: count 0);
//  - hit_plane, first_hit: a zero normal is no error (never hit); a scene's triangles index
//    its vertices; bounce_cap in [0, kMaxBounceCap]; restitution and friction >= 0;
//  - impulse: normal a unit vector (| |n|^2 - 1 | <= 1e-9), mass > 0;
//  - settle: when last.hit, last names one plane or one triangle of the scene, and
//    last.normal is non-zero;
//  - spring_force: both particles valid as for force; spring.stiffness, damping and
//    rest_length >= 0;
//  - rigid_impulse: masses > 0; each inverse_inertia symmetric (exactly) with a
//    non-negative diagonal (and positive semi-definite, as an inverse inertia tensor is:
//    not checked); contact.normal a unit vector (| |n|^2 - 1 | <= 1e-9); restitution >= 0.
#pragma once

#include "common/geometry.h"
#include "common/given/segment_triangle.h"
#include "common/splitmix.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace labkit::lab07 {

// ---- Step 1 (L07S1): emitter and lifetime ------------------------------------------

// Given: a small seeded random number generator (SplitMix64). Every draw depends only on
// the seed and the draws before it, so an emitter is deterministic given its seed.
class Random {
 public:
  explicit Random(std::uint64_t seed = 1) : mix_{seed} {}
  std::uint64_t next() { return mix_.next(); }
  double uniform() { return mix_.uniform(); }  // in [0, 1)
  double uniform(double low, double high) { return mix_.uniform(low, high); }
  std::uint64_t state() const { return mix_.state; }  // Random(r.state()) goes on as r would

 private:
  SplitMix64 mix_;  // common/splitmix.h
};

struct Particle {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 previous = Vec3::Zero();  // Verlet only: the position one step ago
  double mass = 1.0;
  double age = 0.0;       // seconds since birth
  double lifetime = 1.0;  // it dies when its age reaches this
  bool alive = true;      // age < lifetime
  int bounces = 0;        // impulses in its last step (for display)
};

// Where particles are born and with what attributes (the lecture's emitter attributes).
// Each attribute is drawn uniformly from its range:
//  - position: in the box position +- half_extents (each axis on its own);
//  - direction: uniformly over the cone of half-angle `cone` (radians, 0 to pi) around
//    `direction` (a unit vector), that is, uniformly in solid angle: cos of the angle to
//    the axis uniform in [cos(cone), 1], the turn about the axis uniform in [0, 2 pi);
//  - speed: in [speed - speed_spread, speed + speed_spread];
//  - lifetime: in [lifetime - lifetime_spread, lifetime + lifetime_spread].
// Every particle gets the emitter's mass, age 0, alive, previous = its position.
struct Emitter {
  Vec3 position = Vec3::Zero();
  Vec3 half_extents = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();
  double cone = 0.0;
  double speed = 1.0;
  double speed_spread = 0.0;
  double lifetime = 1.0;
  double lifetime_spread = 0.0;
  double mass = 1.0;
  double rate = 0.0;  // particles per second
  double owed = 0.0;  // the fraction of a particle carried over from earlier steps, in [0, 1)
};

// A new particle with attributes drawn from `random` as described above.
Particle emit(const Emitter& emitter, Random& random);

struct Births {
  int count = 0;      // particles born in this step
  double owed = 0.0;  // what is carried to the next step, in [0, 1)
};

// How many particles are born in a step of length dt: rate * dt plus what earlier steps
// owed, rounded down; the fraction left over is owed to the next step. Over many steps
// the count never falls a whole particle behind rate * time.
Births births(const Emitter& emitter, double dt);

// Each particle ages by dt (age + dt, one addition); one whose new age is >= its lifetime
// dies (alive = false) and is removed. The survivors keep their order.
std::vector<Particle> age(std::vector<Particle> particles, double dt);

// ---- Step 2 (L07S2): forces, Euler and Verlet --------------------------------------

struct Forces {
  Vec3 gravity = Vec3(0, 0, -9.81);  // an acceleration
  double drag = 0.0;                 // viscous damping k1:  F = -k1 v
  double air_drag = 0.0;             // aerodynamic drag k2 (1/2 rho C_D S): F = -k2 |v| v
};

// The total force on the particle: m g - k1 v - k2 |v| v, at its current velocity.
Vec3 force(const Particle& p, const Forces& forces);

// Explicit (forward) Euler, one step dt, both updates from the state at the start of the
// step, with a = force(p) / m:
//     position' = position + velocity dt,     velocity' = velocity + a dt.
// (Not semi-implicit Euler, which moves with the new velocity.) Other fields unchanged.
Particle euler_step(const Particle& p, const Forces& forces, double dt);

// Position Verlet, the lecture's S(t + dt) = 2 S(t) - S(t - dt) + a dt^2 with S the
// position and a = force(p) / m (drag uses p.velocity, the last step's velocity):
//     position' = 2 position - previous + a dt^2,   previous' = position,
//     velocity' = (position' - position) / dt       (the velocity over the step).
// It needs a constant dt and a previous position: start_verlet gives a new particle the
// previous position that makes its first Verlet step the Taylor step
// position + velocity dt + a dt^2 / 2:
//     previous = position - velocity dt + a dt^2 / 2.
Particle start_verlet(const Particle& p, const Forces& forces, double dt);
Particle verlet_step(const Particle& p, const Forces& forces, double dt);

// ---- Step 3 (L07S3): launch angle to hit a target ----------------------------------

// A shot from `from` at the given speed: p(t) = from + velocity t + gravity t^2 / 2.
struct Shot {
  double angle = 0.0;            // elevation above the horizontal, radians, in (-pi/2, pi/2)
  Vec3 velocity = Vec3::Zero();  // |velocity| = speed, aimed at the target's side
  double time = 0.0;             // when it reaches the target: p(time) = target
};

struct Aim {
  int count = 0;          // 2 (two angles), 1 (just in reach: one angle), 0 (out of reach)
  double radicand = 0.0;  // the lecture's radicand x^2 - 4 A (A + y), A = g x^2 / (2 v^2)
  Shot low;               // the lower angle (flat, fast arrival)
  Shot high;              // the higher angle (lobbed, slow arrival); equal to low when count is 1
};

// Horizontal and vertical are set by gravity (up = -gravity / |gravity|); x >= 0 is the
// horizontal distance to the target, y its height above `from`, v the speed, g = |gravity|.
// The angles solve tan(angle) = (v^2 +- sqrt(D)) / (g x) with
//     D = v^4 - 2 g y v^2 - g^2 x^2  =  v^4 + 2 v^2 (d . gravity) - |d x gravity|^2,
// d = target - from: reachable when D >= 0; count 2 when D > 0, 1 when D = 0 (decide with
// the sign of D from the second form, computed without any division or square root).
// The radicand is reported when x > 0 (it is (x^2 / v^4) D, negative when out of reach).
// A target on the vertical through `from` (x = 0, the launch point itself included), zero
// gravity, or zero speed: count 0, radicand 0.
// The lecture's example: 25 m/s to a target 40 m away at the same height, g = 9.81: radicand
// 969.30709504, angles 19.445 and 70.555 degrees (the lecture rounds them to 19.4 and 70.6),
// times of flight 1.697 s and 4.806 s.
Aim aim(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity);

// ---- Step 4 (L07S4): the step as a segment against surfaces ------------------------

struct SurfaceHit {
  bool hit = false;            // false: no hit; the other fields mean nothing
  int plane = -1;              // first_hit: which plane (an index into scene.planes), or -1
  int triangle = -1;           // first_hit: which triangle of scene.mesh, or -1
  double t = 0.0;              // the hit point is a + t (b - a), 0 <= t <= 1
  Vec3 point = Vec3::Zero();   // that point
  Vec3 normal = Vec3::Zero();  // unit normal of the surface, pointing to the side the
                               // particle comes from (a plane: its own normal direction)
};

struct Material {
  double restitution = 0.5;  // e: 0 perfectly inelastic, 1 perfectly elastic
  double friction = 0.0;     // mu: Coulomb's dynamic friction coefficient
};

// Most impulses one step may apply (see collide).
constexpr int kMaxBounceCap = 8;

struct Scene {
  std::vector<Plane> planes;  // one-sided: solid behind
  Mesh mesh;                  // two-sided triangles
  Material material;
  int bounce_cap = 4;  // 0 to kMaxBounceCap
  // The surfaces' velocity u during the step (collide, step 6): all of them move together,
  // and planes and mesh are given where they are at the end of the step. Zero: a still
  // scene. first_hit and settle take the surfaces where they are (they ignore u).
  Vec3 velocity = Vec3::Zero();
  // Optional: the first hit of a segment on the mesh under this step's rules, used by
  // first_hit instead of trying every triangle (for example through a k-d tree, lab 06).
  // The tests never set it.
  std::function<SurfaceHit(const Segment&, const Mesh&)> mesh_query;
};

// One surface at a time (the `plane` and `triangle` fields stay -1), then the whole scene.
SurfaceHit hit_plane(const Segment& segment, const Plane& plane);
SurfaceHit hit_triangle(const Segment& segment, const Triangle& triangle);
SurfaceHit first_hit(const Segment& segment, const Scene& scene);

// ---- Step 5 (L07S5): impulse with restitution and friction -------------------------

struct Impulse {
  bool closing = false;                // v_close < 0: the particle moves into the surface
  double v_close = 0.0;                // (velocity - object_velocity) . normal
  Vec3 normal_impulse = Vec3::Zero();  // j_n = -(1 + e) m v_close n when closing, else zero
  Vec3 friction = Vec3::Zero();        // opposes the tangential relative velocity v_t:
                                       // magnitude min(mu |j_n|, m |v_t|), so it never
                                       // reverses v_t (zero when not closing or v_t = 0)
  Vec3 velocity = Vec3::Zero();        // velocity + (normal_impulse + friction) / m
};

// A particle of mass m (> 0) with `velocity` meets an object moving with `object_velocity`
// at a point where the object's unit normal is `normal` (pointing toward the particle).
// Only a closing particle gets an impulse; otherwise velocity is returned unchanged.
Impulse impulse(const Vec3& velocity, const Vec3& object_velocity, const Vec3& normal, double mass,
                const Material& material);

// ---- Step 6 (L07S6): bounce in the remaining time, bounce cap ----------------------

struct Bounce {
  SurfaceHit hit;                // what was hit, where, and its normal (from first_hit)
  Vec3 velocity = Vec3::Zero();  // the velocity after the impulse (not set for the stopping hit)
  Vec3 from = Vec3::Zero();      // where the particle goes on from: the hit point (step 7:
                                 // settled, see there)
};

struct Collision {
  Vec3 position = Vec3::Zero();  // where the particle ends the step
  Vec3 velocity = Vec3::Zero();  // its velocity then
  int bounces = 0;               // impulses applied: trace[0 .. bounces)
  bool stopped = false;          // the cap was reached and the particle hit again:
                                 // trace[bounces] is that hit; it stops there, at rest
                                 // on the surface (velocity: the scene's)
  std::array<Bounce, kMaxBounceCap + 1> trace;
};

// The particle moved along `step` (a -> b) during dt, and has `velocity` now (the
// integrator's). Collision handling, as the lecture's "bouncing", in the frame that moves
// with the scene (u = scene.velocity; for a still scene that frame is the world):
//   piece 0 is the relative step a' -> b with a' = a + u dt (computed as
//   step.a + scene.velocity * dt), and the remaining time r = dt: the scene is given at the
//   end of the step, and a, seen from the scene, was where the scene carries it in dt
//   (lecture 004, "segment vs. moving mesh": test a'b against the object where it ends);
//   on a piece from s to e with remaining time r: find the first hit (step 4); none: the
//   particle ends at e. Else, at the hit x = s + t (e - s): apply the impulse of step 5
//   against the moving surface, v' = impulse(v, u, normal, ...).velocity (it takes the
//   relative velocity v - u), and go on from x (`from`) with the remaining time (1 - t) r,
//   moving relative to the scene: the next piece is from -> from + (v' - u) (1 - t) r.
//   After `scene.bounce_cap` impulses, a further hit stops the particle at that hit's
//   point (its `from`), at rest on the surface: velocity u, stopped = true.
// The trace records each bounce, and the stopping hit: hits and `from` points in the
// scene's frame (where the surfaces are at the end of the step), velocities in the world.
// The end position is in both (the frames meet at the end of the step); the velocity is
// the world's. A step of a = b with u != 0 is a particle at rest struck by the scene.
Collision collide(const Segment& step, const Vec3& velocity, double mass, double dt, const Scene& scene);

// ---- Step 7 (L07S7): never behind one surface, exactly ---------------------------------

// A point computed in floating point can land a hair behind the surface it was meant to
// touch. Step 7 checks settle on one surface (the one just hit: a push along its normal
// does it) and collide's `from` and end points settled; step 8 on points in a crease of
// two or three surfaces, where a push off one can go behind another.
// settle(x, scene, last) returns x moved by less than tol (usually by a few rounding
// errors) so that, in exact arithmetic,
//  - it is not behind any plane of the scene that x is within 1000 rounding errors of
//    (value >= -1000 error, below), or in front of: a point computed to lie on a plane
//    lands within a few errors of it, and one farther behind was behind before;
//  - when last.hit, it is strictly in front of that surface, on last.normal's side.
// Decide "certainly in front" with a value and a bound on its rounding error:
//  - plane: value = n . x + c,  error = 1e-15 (|n_x x_x| + |n_y x_y| + |n_z x_z| + |c|);
//  - triangle: value = (x - v0) . ((v1 - v0) x (v2 - v0)) times the side (+1 or -1) that
//    last.normal faces, error = 1e-15 times the same triple product with every product
//    replaced by its absolute value:
//      |p_x| (|e1_y e2_z| + |e1_z e2_y|) + |p_y| (|e1_z e2_x| + |e1_x e2_z|)
//      + |p_z| (|e1_x e2_y| + |e1_y e2_x|),   p = x - v0, e1 = v1 - v0, e2 = v2 - v0;
// value >= error is certainly not behind, value > error certainly in front; anything
// else is in doubt. Then push: by the worst deficit (how far behind, if behind) plus a
// skin that doubles each round, starting at 4 times the largest error (as a distance:
// divided by |n|) plus 2^-50 |x|_inf (a few units in the last place of x's largest
// coordinate: less would not move x at all), along a direction d that moves away from
// every surface found in doubt so far in this call (unit normals n_i, the facing normal
// for the last surface), scaled so that n_i . d >= 1 for all, until nothing is in doubt.
// Take d as the best of: each n_i; each bisector n_i + n_j; for each three, the d with
// n_i . d = 1 for all three (best: the largest smallest n_i . d / |d|).
//
// collide calls settle on every `from` (with that bounce's hit) and on its end position
// (with the last hit, or none), so that:
//  (1) if a' (a + u dt, above) is not behind any plane, the end position is not behind any plane;
//  (2) every `from` is strictly in front of the surface hit there; and if the particle
//      hit anything, it ends not behind the last surface it hit, on the side it came from
//      (exactly on the surface counts as not behind);
//  (3) for e <= 1, |v_end - u|^2 <= (1 + 1e-12) |v - u|^2: energy relative to the scene
//      never grows in a bounce (a moving paddle may well speed a particle up in the world);
//  (4) for e = 1 and mu = 0, unless stopped: | |v_end - u|^2 - |v - u|^2 | <= 1e-12 |v - u|^2.
// (1) and (2) are checked exactly. (3) and (4) allow 1e-12 because each impulse rounds a
// few times (about 1e-15 relative each); a real mistake changes the energy by far more.
// With u != 0 they also allow the rounding of v_end - u: 1e-12 |v - u| |u| more.
// (1) is why step 4 decides a's side of a plane with value(a)'s rounding bound: a
// particle resting on a plane whose n . a + c rounds a hair below zero still hits it.
Vec3 settle(const Vec3& x, const Scene& scene, const SurfaceHit& last);

// ---- Step 8 (L07S8): creases and corners; the handling loop ----------------------------

// settle in creases and corners (step 7's direction d from two or three normals), the
// invariants (1)-(4) on every kind of step, and the handling loop below.

enum class Integrator { euler, verlet };

// The whole system: read `particles` between steps (the viewer draws them).
struct System {
  Emitter emitter;
  Scene scene;
  Forces forces;
  Integrator integrator = Integrator::euler;
  Random random{1};
  std::vector<Particle> particles;
  double time = 0.0;

  // One step of the handling loop, in this order:
  //  1. births: births(emitter, dt) new particles from emit (with Verlet, start_verlet);
  //  2. every particle: a = position; integrate (euler_step or verlet_step); then collide
  //     the segment a -> position with the new velocity; take collide's position, velocity
  //     and bounces; with Verlet, after a bounce or a stop, previous = position - velocity dt
  //     (so that the next step goes on with the new velocity);
  //  3. age(particles, dt); time += dt.
  // It does not move the scene: with scene.velocity != 0, the caller moves the surfaces to
  // where they are at the end of each step before calling it.
  void step(double dt);
};

// ---- Step 9 (L07S9): a damped spring between two particles -------------------------
// Extension. Lecture 002's linear spring and viscous damping, between two particles.

struct Spring {
  double stiffness = 1.0;    // k_s: force per unit of stretch
  double damping = 0.0;      // k_d: force per unit of speed along the spring
  double rest_length = 1.0;  // l_rest: the length at which the spring pulls nothing
};

// The force the spring puts on `a` (the force on b is its opposite, Newton's third law):
//     d = a.position - b.position,   l = |d|,   u = d / l   (unit, from b toward a),
//     F_a = -( k_s (l - l_rest) + k_d ((a.velocity - b.velocity) . u) ) u.
// Stretched (l > l_rest) it pulls a toward b; compressed it pushes a away. The damping
// takes only the part of the relative velocity along the spring: particles circling
// each other at a fixed distance feel no damping.
// Zero length (a.position == b.position, exactly): u is undefined and the force is zero
// (a defined rule, not an error).
// Tolerance: F within
//     tol_F = 1e-9 ( k_s (S + |l - l_rest| S / l) + k_d V (1 + 4 S / l) ),
// S the largest absolute coordinate of the two positions and l_rest, V the largest
// absolute component of the two velocities. d is a difference of coordinates of size S,
// so its rounding moves the length by about 1e-16 S and turns the direction u by about
// 1e-16 S / l, which turns the whole force (k_s |l - l_rest| plus the damping's up to
// k_d 4 V): close particles far from the origin have a poorly known direction. When
// l <= 1e-9 S the direction is in doubt (it turns freely under a relative 1e-9 change of
// the input): any finite force passes.
Vec3 spring_force(const Particle& a, const Particle& b, const Spring& spring);

// ---- Step 10 (L07S10): rigid-body impulse with its angular part --------------------
// Extension. Lecture 003's contact algorithm: two rigid bodies meet at one point; one
// impulse J = j n changes both linear and angular velocities.

struct RigidBody {
  Vec3 centre = Vec3::Zero();               // centre of mass
  Vec3 velocity = Vec3::Zero();             // of the centre of mass
  Vec3 angular_velocity = Vec3::Zero();     // w, radians per second, world frame
  double mass = 1.0;                        // m
  Mat3 inverse_inertia = Mat3::Identity();  // I^-1 in the WORLD frame: R I_body^-1 R^T
};

struct Contact {
  Vec3 point = Vec3::Zero();    // where the bodies touch
  Vec3 normal = Vec3::UnitZ();  // unit, from b toward a: the impulse pushes a along +n
  double restitution = 0.5;     // e
};

struct RigidImpulse {
  bool closing = false;            // v_rel < 0: the contact points move together
  double v_rel = 0.0;              // n . (v_pa - v_pb), see below
  double j = 0.0;                  // the impulse's size (0 when not closing)
  Vec3 velocity_a = Vec3::Zero();  // after the impulse (unchanged when not closing)
  Vec3 angular_velocity_a = Vec3::Zero();
  Vec3 velocity_b = Vec3::Zero();
  Vec3 angular_velocity_b = Vec3::Zero();
};

// With r_a = point - a.centre, r_b = point - b.centre, the contact points' velocities
// v_pa = v_a + w_a x r_a and v_pb = v_b + w_b x r_b, and v_rel = n . (v_pa - v_pb):
//  - closing when v_rel < 0; v_rel = 0 (sliding or resting) and v_rel > 0 are not closing,
//    and the bodies are returned unchanged;
//  - when closing:  j = -(1 + e) v_rel / (1/m_a + 1/m_b + n . ((I_a^-1 (r_a x n)) x r_a)
//                                                      + n . ((I_b^-1 (r_b x n)) x r_b)),
//    J = j n,   v_a' = v_a + J / m_a,   v_b' = v_b - J / m_b,
//    w_a' = w_a + I_a^-1 (r_a x J),   w_b' = w_b - I_b^-1 (r_b x J).
// Then the contact points separate at -e times the speed they closed with
// (n . (v_pa' - v_pb') = -e v_rel), and the momentum m_a v_a + m_b v_b is unchanged.
// Tolerances. S: the largest absolute coordinate of the centres and the point; for each
// body R = |r| + S (r's length, plus the size of the coordinates r is a difference of) and
// K = 3 times the largest absolute entry of its I^-1; T = |v_a| + |v_b| + |w_a| R_a + |w_b| R_b
// (the size of v_rel's terms); D the exact denominator of j, D_abs = 1/m_a + 1/m_b +
// K_a R_a^2 + K_b R_b^2 (the size of its terms).
//  - closing: exact, except when 0 < |v_rel| <= 1e-8 T, where either answer passes (an
//    exact tie, v_rel = 0, is not closing: the rule above);
//  - v_rel within 1e-9 T;  j within tol_j = 1e-9 ((1 + e) T + |j| D_abs) / D;
//  - v_a within 1e-9 |v_a| + (tol_j + 1e-9 |j|) / m_a, w_a within 1e-9 |w_a| +
//    K_a R_a (tol_j + 1e-9 |j|) (the same for b);
//  - the two invariants above, checked exactly on your velocities, within what those
//    tolerances allow.
RigidImpulse rigid_impulse(const RigidBody& a, const RigidBody& b, const Contact& contact);

}  // namespace labkit::lab07
