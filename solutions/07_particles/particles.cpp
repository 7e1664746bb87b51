// Lab 07 reference: particle systems that bounce.
//
// The physics is a handful of lines per step; the care goes into two places. Decisions
// (does the step cross this surface, which side is the particle on) are made from input
// numbers, before anything is constructed. And every position the particle keeps after a
// bounce is settled: checked against the surface with a bound on its own rounding error,
// and pushed off by a hair when in doubt, so that "never behind a surface" holds exactly,
// not just nearly.
#include "particles.h"

#include "common/preconditions.h"

#include "common/given/segment_triangle.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace labkit::lab07 {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- Preconditions (the header's "Preconditions") --------------------------------------
// Invalid input is refused with std::invalid_argument naming the argument and the rule,
// before anything is computed: a NaN would otherwise flow through every formula and come
// out as a NaN position, and a zero mass as an infinite acceleration.

using namespace preconditions;
using preconditions::require_valid;  // beside the overloads for this lab's types below

void require_valid(const char* query, const std::string& name, const Emitter& e) {
  for (const auto& [field, v] :
       {std::pair{"position", e.position}, {"half_extents", e.half_extents}, {"direction", e.direction}})
    require_finite(query, name + "." + field, v);
  require((e.half_extents.array() >= 0).all(), query, name + ".half_extents", "be >= 0", e.half_extents);
  require(e.direction != Vec3::Zero(), query, name + ".direction", "be non-zero", e.direction);
  require(e.cone >= 0 && e.cone <= kPi, query, name + ".cone", "be in [0, pi]", e.cone);
  require_size(query, name + ".speed_spread", e.speed_spread);
  require(std::isfinite(e.speed) && e.speed >= e.speed_spread, query, name + ".speed", "be finite and >= speed_spread",
          e.speed);
  require_size(query, name + ".lifetime_spread", e.lifetime_spread);
  require(std::isfinite(e.lifetime) && e.lifetime >= e.lifetime_spread, query, name + ".lifetime",
          "be finite and >= lifetime_spread", e.lifetime);
  require_positive(query, name + ".mass", e.mass);
  require_size(query, name + ".rate", e.rate);
  require(e.owed >= 0 && e.owed < 1, query, name + ".owed", "be in [0, 1)", e.owed);
}

void require_valid(const char* query, const std::string& name, const Particle& p) {
  require_finite(query, name + ".position", p.position);
  require_finite(query, name + ".velocity", p.velocity);
  require_finite(query, name + ".previous", p.previous);
  require_positive(query, name + ".mass", p.mass);
  require_finite(query, name + ".age", p.age);
  require_finite(query, name + ".lifetime", p.lifetime);
}

void require_valid(const char* query, const Forces& f) {
  require_finite(query, "forces.gravity", f.gravity);
  require_size(query, "forces.drag", f.drag);
  require_size(query, "forces.air_drag", f.air_drag);
}

void require_valid(const char* query, const Plane& p, const std::string& name = "plane") {
  require_finite(query, name + ".normal", p.normal);
  require_finite(query, name + ".offset", p.offset);
}

void require_valid(const char* query, const Material& m) {
  require_size(query, "material.restitution", m.restitution);
  require_size(query, "material.friction", m.friction);
}

void require_valid(const char* query, const Scene& scene) {
  for (std::size_t i = 0; i < scene.planes.size(); ++i)
    require_valid(query, scene.planes[i], "scene.planes[" + std::to_string(i) + "]");
  require_valid(query, "scene.mesh", scene.mesh);
  require_valid(query, scene.material);
  require_finite(query, "scene.velocity", scene.velocity);
  require(scene.bounce_cap >= 0 && scene.bounce_cap <= kMaxBounceCap, query, "scene.bounce_cap",
          "be in [0, kMaxBounceCap]", double(scene.bounce_cap));
}

}  // namespace

// ---- Step 1: emitter and lifetime ----------------------------------------------------

// Uniform in solid angle over the cone: the area of the spherical cap between angles 0
// and theta is 2 pi (1 - cos theta), linear in cos theta, so cos theta is drawn uniformly
// (drawing theta itself uniformly would crowd the particles toward the axis).
Particle emit(const Emitter& emitter, Random& random) {
  require_valid("emit", "emitter", emitter);
  Particle p;
  for (int i = 0; i < 3; ++i) p.position[i] = emitter.position[i] + emitter.half_extents[i] * random.uniform(-1.0, 1.0);
  const Vec3 axis = emitter.direction.normalized();
  const Vec3 u = axis.unitOrthogonal(), w = axis.cross(u);
  // mutant cone_uniform_in_angle (step 1, "solid angle"):
  //   `const double cos_theta = random.uniform(std::cos(emitter.cone), 1.0);`
  //   -> `const double cos_theta = std::cos(random.uniform(0.0, emitter.cone));`
  const double cos_theta = random.uniform(std::cos(emitter.cone), 1.0);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const double turn = random.uniform(0.0, 2 * kPi);
  const Vec3 direction = cos_theta * axis + sin_theta * (std::cos(turn) * u + std::sin(turn) * w);
  p.velocity = random.uniform(emitter.speed - emitter.speed_spread, emitter.speed + emitter.speed_spread) * direction;
  p.lifetime = random.uniform(emitter.lifetime - emitter.lifetime_spread, emitter.lifetime + emitter.lifetime_spread);
  p.mass = emitter.mass;
  p.previous = p.position;
  return p;
}

// The fraction is carried, not dropped: at 10 particles per second and 60 steps per
// second, rate * dt = 1/6 rounds down to 0 every single step.
Births births(const Emitter& emitter, double dt) {
  require_valid("births", "emitter", emitter);
  require_size("births", "dt", dt);
  const double due = emitter.owed + emitter.rate * dt;
  const double whole = std::floor(due);
  // mutant births_drop_fraction (step 1, "fraction", "carried"): `due - whole` -> `0.0`
  return {int(whole), due - whole};
}

std::vector<Particle> age(std::vector<Particle> particles, double dt) {
  require_size("age", "dt", dt);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    require_finite("age", "particles[" + std::to_string(i) + "].age", particles[i].age);
    require_finite("age", "particles[" + std::to_string(i) + "].lifetime", particles[i].lifetime);
  }
  for (Particle& p : particles) {
    p.age += dt;
    p.alive = p.age < p.lifetime;  // reaching the lifetime is dying
  }
  particles.erase(std::remove_if(particles.begin(), particles.end(), [](const Particle& p) { return !p.alive; }),
                  particles.end());
  return particles;
}

// ---- Step 2: forces, Euler and Verlet ------------------------------------------------

// Drag always opposes the velocity: viscous drag grows with |v|, air drag with |v|^2.
Vec3 force(const Particle& p, const Forces& forces) {
  require_valid("force", "p", p);
  require_valid("force", forces);
  // The air drag taken per component, -k2 |v_i| v_i, instead of -k2 |v| v along the
  // whole velocity: right for motion along one axis only.
  // mutant drag_per_component (step 2, "whole velocity vector"):
  //   `norm() * p.velocity`
  //   -> `cwiseAbs().cwiseProduct(p.velocity)`
  return p.mass * forces.gravity - forces.drag * p.velocity - forces.air_drag * p.velocity.norm() * p.velocity;
}

// The state is S = (position, velocity) and dS/dt = (velocity, F / m), both taken at the
// start of the step: S(t + dt) = S(t) + dS/dt dt.
Particle euler_step(const Particle& p, const Forces& forces, double dt) {
  require_positive("euler_step", "dt", dt);
  const Vec3 a = force(p, forces) / p.mass;  // force() checks p and forces
  Particle next = p;
  // mutant semi_implicit_euler (step 2, "explicit Euler", "start of the step"):
  //   `+ p.velocity`
  //   -> `+ (p.velocity + a * dt)`
  next.position = p.position + p.velocity * dt;
  next.velocity = p.velocity + a * dt;
  return next;
}

// Taylor: x(dt) = x + v dt + a dt^2 / 2, and x(-dt) = x - v dt + a dt^2 / 2. With the
// second as `previous`, the Verlet step 2 x - x(-dt) + a dt^2 gives exactly the first.
Particle start_verlet(const Particle& p, const Forces& forces, double dt) {
  require_positive("start_verlet", "dt", dt);
  const Vec3 a = force(p, forces) / p.mass;  // force() checks p and forces
  Particle next = p;
  // mutant verlet_start_without_acceleration (step 2, "Taylor step"):
  //   `next.previous = p.position - p.velocity * dt + 0.5 * a * dt * dt;`
  //   -> `next.previous = p.position - p.velocity * dt;`
  next.previous = p.position - p.velocity * dt + 0.5 * a * dt * dt;
  return next;
}

// The lecture's S(t + dt) = 2 S(t) - S(t - dt) + a dt^2: add the last step's displacement
// again, bent by the acceleration. The velocity is not part of the state; the one kept is
// the average over the step just taken, which is what the collision test moves along.
Particle verlet_step(const Particle& p, const Forces& forces, double dt) {
  require_positive("verlet_step", "dt", dt);
  const Vec3 a = force(p, forces) / p.mass;  // force() checks p and forces
  Particle next = p;
  next.position = 2 * p.position - p.previous + a * dt * dt;
  next.previous = p.position;
  next.velocity = (next.position - p.position) / dt;
  return next;
}

// ---- Step 3: launch angle to hit a target --------------------------------------------

//   Derivation (lecture 002, target practice). Aim at elevation theta with speed v; the
//   target is x away horizontally and y up. Horizontally v cos(theta) T = x, so
//   T = x / (v cos theta); vertically y = v sin(theta) T - g T^2 / 2. With u = tan(theta)
//   and 1 / cos^2 = 1 + u^2:
//
//       y = x u - A (1 + u^2),   A = g x^2 / (2 v^2),   so   A u^2 - x u + (A + y) = 0,
//
//   whose radicand is x^2 - 4 A (A + y) (the lecture's 969.31), and
//   u = (x +- sqrt(x^2 - 4 A (A + y))) / (2 A) = (v^2 +- sqrt(D)) / (g x) with
//   D = v^4 - 2 g y v^2 - g^2 x^2. In vectors (d = target - from, g y = -d . gravity,
//   g^2 x^2 = |d x gravity|^2): D = v^4 + 2 v^2 (d . gravity) - |d x gravity|^2, a
//   polynomial in the input, so its sign is exact on small integers.
//
//       up ^          . ' ' .   high: lobbed, slow
//          |       .  _ - - _  ' .
//          |     . -           - .'.
//          |   .'  low: flat, fast  '*  target (x, y)
//     from *-----------------------------> horizontal, toward the target
Aim aim(const Vec3& from, const Vec3& target, double speed, const Vec3& gravity) {
  require_finite("aim", "from", from);
  require_finite("aim", "target", target);
  require_size("aim", "speed", speed);
  require_finite("aim", "gravity", gravity);
  const Vec3 d = target - from;
  const double gx_squared = d.cross(gravity).squaredNorm();
  if (gx_squared == 0 || speed == 0) return {};  // straight up or down, no gravity, or no speed
  const double v2 = speed * speed;
  // mutant launch_height_sign (step 3, "height", "gravity points down"): `+ 2 * v2` -> `- 2 * v2`
  const double D = v2 * v2 + 2 * v2 * d.dot(gravity) - gx_squared;

  const double g = gravity.norm();
  const Vec3 up = -gravity / g;
  const double y = d.dot(up);
  const double x = std::sqrt(gx_squared) / g;
  Aim r;
  r.radicand = (x * x) / (v2 * v2) * D;
  if (D < 0) return r;  // out of reach: no angle gets there
  r.count = D > 0 ? 2 : 1;

  // The two roots, each in a form without cancellation: the high one adds sqrt(D) to v^2;
  // the low one is the product of the roots, (A + y) / A = (g x^2 + 2 y v^2) / (g x^2),
  // divided by the high one (v^2 - sqrt(D) would subtract two nearly equal numbers when
  // the target is close and the shot fast).
  const double root = std::sqrt(D);
  const double tan_high = (v2 + root) / (g * x);
  // The issue's: v^2 - sqrt(D) for the low root loses every digit on a near, fast shot.
  // mutant low_root_cancels (step 3, "low root", "cancels"):
  //   `const double tan_low = (g * x * x + 2 * y * v2) / (x * (v2 + root));`
  //   -> `const double tan_low = (v2 - root) / (g * x);`
  const double tan_low = (g * x * x + 2 * y * v2) / (x * (v2 + root));
  const Vec3 toward = (d - y * up).normalized();  // horizontal, toward the target
  const auto shot = [&](double tangent) {
    const double c = 1 / std::hypot(1.0, tangent), s = tangent * c;  // cos and sin of the angle
    return Shot{std::atan(tangent), speed * (c * toward + s * up), x / (speed * c)};
  };
  r.low = shot(tan_low);
  r.high = r.count == 2 ? shot(tan_high) : r.low;
  return r;
}

// ---- Step 4: the step as a segment against surfaces ----------------------------------

namespace {

// A value whose sign says the side, and a bound on the rounding error made computing it.
struct Signed {
  double value = 0.0;
  double error = 0.0;
};

// n . x + c: three products and three sums, each rounding by at most 2^-53 of its size,
// err <= 4 2^-53 (sum of |terms|) < 1e-15 (sum of |terms|).
Signed plane_value(const Plane& plane, const Vec3& x) {
  const Vec3 terms = plane.normal.cwiseProduct(x);
  return {terms.x() + terms.y() + terms.z() + plane.offset, 1e-15 * (terms.cwiseAbs().sum() + std::abs(plane.offset))};
}

}  // namespace

// One-sided: the solid is behind (value < 0). The step hits only if it starts on the
// allowed side and ends behind; value changes linearly along the segment, so it crosses
// zero at t = value(a) / (value(a) - value(b)), a division without cancellation because
// the two values have opposite signs (or value(a) = 0: t = 0).
SurfaceHit hit_plane(const Segment& segment, const Plane& plane) {
  require_valid("hit_plane", "segment", segment);
  require_valid("hit_plane", plane);
  const double length = plane.normal.norm();
  if (length == 0) return {};  // a zero normal: no plane
  // a within rounding error of the plane counts as on it: a particle resting on a plane
  // that moves behind it hits at t = 0, even when n . a + c rounds a hair below zero.
  const Signed a = plane_value(plane, segment.a);
  // Step 4's rule for a: on the plane to within value(a)'s rounding bound counts as on it.
  // mutant start_decided_by_rounded_sign (step 4, "rounding bound"):
  //   `const double va = std::abs(a.value) <= a.error ? 0.0 : a.value, vb`
  //   -> `const double va = a.value, vb`
  const double va = std::abs(a.value) <= a.error ? 0.0 : a.value, vb = plane.value(segment.b);
  // mutant plane_two_sided (step 4, "one-sided"):
  //   `if (va < 0) return {};`
  //   -> `if (va < 0 && vb >= 0) { SurfaceHit h; h.hit = true; h.t = va / (va - vb); h.point = segment.point(h.t);
  //     h.normal = -plane.normal / length; return h; } if (va < 0) return {};`
  if (va < 0) return {};  // starts behind: not this step's doing
  // mutant touching_is_behind (step 4, "not behind"): `>=` -> `>`
  if (vb >= 0) return {};  // does not end behind (touching the plane is allowed)
  SurfaceHit h;
  h.hit = true;
  h.t = va / (va - vb);
  h.point = segment.point(h.t);
  h.normal = plane.normal / length;
  return h;
}

// Two-sided: the side the particle comes from is the side a is on, decided from input
// numbers before the given watertight test builds anything.
SurfaceHit hit_triangle(const Segment& segment, const Triangle& triangle) {
  require_valid("hit_triangle", "segment", segment);
  for (int i = 0; i < 3; ++i) require_finite("hit_triangle", "triangle.v" + std::to_string(i), triangle[i]);
  const Vec3 n = triangle.normal();
  const double side = n.dot(segment.a - triangle.v0);
  if (side == 0) return {};  // starts on the plane (or no plane): it is leaving, not hitting
  const given::SegmentHit g = given::segment_triangle(segment, triangle);
  if (!g.hit) return {};  // misses the closed triangle
  SurfaceHit h;
  h.hit = true;
  h.t = g.t;
  h.point = g.point;
  h.normal = (side > 0 ? n : Vec3(-n)).normalized();
  return h;
}

namespace {

// Cheap rejection before the exact-ish test: boxes that do not overlap cannot meet.
bool boxes_apart(const Vec3& low, const Vec3& high, const Triangle& t) {
  const Vec3 t_low = t.v0.cwiseMin(t.v1).cwiseMin(t.v2), t_high = t.v0.cwiseMax(t.v1).cwiseMax(t.v2);
  return (t_low.array() > high.array()).any() || (t_high.array() < low.array()).any();
}

// The nearest hit wins; a later surface must be strictly nearer to replace an earlier
// one, which makes ties go to planes, then to lower indices.
SurfaceHit first_hit_in(const Segment& segment, const Scene& scene) {
  SurfaceHit best;
  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const SurfaceHit h = hit_plane(segment, scene.planes[i]);
    if (!h.hit || (best.hit && h.t >= best.t)) continue;  // a miss, or not nearer
    best = h;
    best.plane = int(i);
  }
  if (scene.mesh_query) {
    const SurfaceHit h = scene.mesh_query(segment, scene.mesh);
    if (h.hit && (!best.hit || h.t < best.t)) best = h;
    return best;
  }
  const Vec3 low = segment.a.cwiseMin(segment.b), high = segment.a.cwiseMax(segment.b);
  for (std::size_t i = 0; i < scene.mesh.size(); ++i) {
    const Triangle tri = scene.mesh.triangle(i);
    if (boxes_apart(low, high, tri)) continue;  // far from the segment
    const SurfaceHit h = hit_triangle(segment, tri);
    if (!h.hit || (best.hit && h.t >= best.t)) continue;  // a miss, or not nearer
    best = h;
    best.triangle = int(i);
  }
  return best;
}

}  // namespace

SurfaceHit first_hit(const Segment& segment, const Scene& scene) {
  require_valid("first_hit", "segment", segment);
  require_valid("first_hit", scene);
  return first_hit_in(segment, scene);
}

// ---- Step 5: impulse with restitution and friction -----------------------------------

//   Derivation (lecture 001). Only the relative velocity v_r = v - v_obj matters. Split
//   it along the unit normal: v_close = v_r . n, and the rest, v_t = v_r - v_close n.
//   Restitution turns v_close into -e v_close, a change of -(1 + e) v_close along n:
//   j_n = -(1 + e) m v_close n. Coulomb friction opposes v_t with at most mu |j_n|, and
//   at most what stops the sliding, m |v_t| (more would reverse it):
//
//         n ^  -e v_close (after)       v_t' = v_t (1 - f / (m |v_t|)),
//           |                           f = min(mu |j_n|, m |v_t|)
//    -------+------------>  v_t
//           |
//           v  v_close < 0 (before: closing)
Impulse impulse(const Vec3& velocity, const Vec3& object_velocity, const Vec3& normal, double mass,
                const Material& material) {
  require_finite("impulse", "velocity", velocity);
  require_finite("impulse", "object_velocity", object_velocity);
  // The formulas take n . n = 1; a normal of another length scales v_close and j_n.
  require(normal.allFinite() && std::abs(normal.squaredNorm() - 1) <= 1e-9, "impulse", "normal", "be a unit vector",
          normal);
  require_positive("impulse", "mass", mass);
  require_valid("impulse", material);
  Impulse r;
  // mutant impulse_ignores_object_velocity (step 5, "relative velocity"):
  //   `const Vec3 relative = velocity - object_velocity;`
  //   -> `const Vec3 relative = velocity;`
  const Vec3 relative = velocity - object_velocity;
  r.v_close = relative.dot(normal);
  r.velocity = velocity;
  if (!(r.v_close < 0)) return r;  // separating or sliding along: no impulse
  r.closing = true;
  const double j = -(1 + material.restitution) * mass * r.v_close;  // |j_n|, positive
  r.normal_impulse = j * normal;
  const Vec3 tangential = relative - r.v_close * normal;
  const double slide = tangential.norm();
  if (slide > 0) {
    // mutant friction_reverses_sliding (step 5, "never reverses"):
    //   `const double f = std::min(material.friction * j, mass * slide);`
    //   -> `const double f = material.friction * j;`
    const double f = std::min(material.friction * j, mass * slide);  // never reverses v_t
    r.friction = -(f / slide) * tangential;
  }
  r.velocity = velocity + (r.normal_impulse + r.friction) / mass;
  return r;
}

// ---- Step 6: bounce in the remaining time, bounce cap --------------------------------

// The lecture's best position adjustment: find when the hit happened (assuming constant
// velocity within the step), apply the impulse there, move on for the time that is left,
// and test that new path too. A particle in a crack could bounce forever in one step;
// after the cap it stops where it hits next.
//
// A moving scene (all surfaces at velocity u, given where they end the step) is the same
// loop in the frame that moves with it (lecture 004's "segment vs. moving mesh"): there the
// surfaces stand still, the particle starts at a' = a + u dt (where the scene would have
// carried a), and moves with the relative velocity v - u. Deciding against the surfaces
// where they end the step keeps the end position exact-checkable against them, as for a
// still scene.
namespace {
Vec3 settle_in(const Vec3& x, const Scene& scene, const SurfaceHit& last);
Collision collide_in(const Segment& step, const Vec3& velocity, double mass, double dt, const Scene& scene);
}  // namespace

Collision collide(const Segment& step, const Vec3& velocity, double mass, double dt, const Scene& scene) {
  require_valid("collide", "step", step);
  require_finite("collide", "velocity", velocity);
  require_positive("collide", "mass", mass);
  require_positive("collide", "dt", dt);
  require_valid("collide", scene);
  return collide_in(step, velocity, mass, dt, scene);
}

namespace {

// collide's work on checked input: System::step checks its scene once per step, not once
// per particle (a mesh's every vertex, a thousand times a step).
Collision collide_in(const Segment& step, const Vec3& velocity, double mass, double dt, const Scene& scene) {
  const int cap = scene.bounce_cap;
  const Vec3 u = scene.velocity;
  Collision c;
  // mutant moving_surface_frozen (step 6, "relative step", "a + u dt"): `{step.a + u * dt, step.b}` -> `step`
  Segment piece = {step.a + u * dt, step.b};  // the relative step: a carried by the scene, to b
  Vec3 v = velocity;
  double remaining = dt;
  SurfaceHit last;
  for (;;) {
    const SurfaceHit hit = first_hit_in(piece, scene);
    if (!hit.hit) break;  // this piece is clear: the particle gets to its end
    Bounce& bounce = c.trace[std::size_t(c.bounces)];
    bounce.hit = hit;
    // mutant hit_point_not_settled (step 7, "strictly in front", "settle"):
    //   `settle_in(hit.point, scene, hit)`
    //   -> `hit.point`
    bounce.from = settle_in(hit.point, scene, hit);
    // mutant cap_off_by_one (step 6, "bounce cap"):
    //   `c.bounces == cap`
    //   -> `c.bounces == cap + 1 || c.bounces == kMaxBounceCap`
    if (c.bounces == cap) {  // one hit too many: stop here, at rest
      c.stopped = true;
      c.position = bounce.from;
      c.velocity = u;  // at rest on the surface, which carries it
      return c;
    }
    // A moving scene (step 6): the three ways to leave its motion out.
    // mutant collide_impulse_absolute_velocity (step 6, "relative velocity", "v - u"):
    //   `impulse(v, u,`
    //   -> `impulse(v, Vec3::Zero(),`
    v = impulse(v, u, hit.normal, mass, scene.material).velocity;  // against the moving surface: v - u
    bounce.velocity = v;
    // mutant whole_step_after_bounce (step 6, "remaining time"): `remaining *= 1 - hit.t;` -> ``
    remaining *= 1 - hit.t;
    // mutant piece_moves_with_world_velocity (step 6, "relative to the moving surfaces"):
    //   `(v - u) * remaining`
    //   -> `v * remaining`
    piece = {bounce.from, bounce.from + (v - u) * remaining};  // relative to the scene
    last = hit;
    ++c.bounces;
  }
  // collide's end position left as computed, not settled: after a bounce that
  // slides along a surface it can end a hair behind the plane, by rounding.
  // mutant end_position_not_settled (step 7, "behind"): `settle_in(piece.b, scene, last)` -> `piece.b`
  c.position = settle_in(piece.b, scene, last);
  c.velocity = v;
  return c;
}

// ---- Step 7: never behind one surface, exactly -------------------------------------------

// (x - v0) . (e1 x e2): Shewchuk's bound for orient3d, (7 + 56 2^-53) 2^-53 times the
// "permanent" (the triple product with every product made positive), below 1e-15 times it.
Signed triangle_value(const Triangle& t, const Vec3& x) {
  const Vec3 e1 = t.v1 - t.v0, e2 = t.v2 - t.v0, p = x - t.v0;
  const double value = p.dot(e1.cross(e2));
  const double permanent = std::abs(p.x()) * (std::abs(e1.y() * e2.z()) + std::abs(e1.z() * e2.y())) +
                           std::abs(p.y()) * (std::abs(e1.z() * e2.x()) + std::abs(e1.x() * e2.z())) +
                           std::abs(p.z()) * (std::abs(e1.x() * e2.y()) + std::abs(e1.y() * e2.x()));
  return {value, 1e-15 * permanent};
}

double largest(const Vec3& v) { return v.cwiseAbs().maxCoeff(); }

// The direction that moves away from all these surfaces fastest (its worst unit normal
// n_i . d largest), scaled so that n_i . d >= 1 for every one: a push of k d then moves
// each surface at least k farther off. The best direction is equally inclined to the one,
// two or three normals that limit it, so it is among: each normal; each pair's bisector;
// for each three, the d with n_i . d = 1 for all three. Zero when none moves away from all.
Vec3 away_from(const std::vector<Vec3>& normals) {
  Vec3 best = Vec3::Zero();
  double best_margin = 0;
  const auto consider = [&](const Vec3& d) {
    const double length = d.norm();
    if (!(length > 0)) return;
    double margin = std::numeric_limits<double>::infinity();
    for (const Vec3& n : normals) margin = std::min(margin, n.dot(d) / length);
    if (margin > best_margin) {
      best_margin = margin;
      best = d / length;
    }
  };
  const std::size_t k = normals.size();
  for (std::size_t i = 0; i < k; ++i) {
    consider(normals[i]);
    for (std::size_t j = i + 1; j < k; ++j) {
      consider(normals[i] + normals[j]);
      for (std::size_t l = j + 1; l < k; ++l) {
        Mat3 rows;
        rows << normals[i].transpose(), normals[j].transpose(), normals[l].transpose();
        if (rows.determinant() != 0) consider(rows.inverse() * Vec3::Ones());
      }
    }
  }
  return best_margin > 0 ? Vec3(best / best_margin) : Vec3::Zero();
}

//   Why this is needed: the hit point x = a + t (b - a) is rounded, so it lies a hair on
//   either side of the surface; after a dead (e = 0) bounce the particle slides with the
//   surface at "zero" distance, and rounding decides the side. The exact side is known
//   only when the computed value is farther from zero than its error bound. When it is
//   not, push the point off along the normals in doubt (the lecture's "collision point
//   plus some offset along the normal") by a skin of a few rounding errors, doubled until
//   nothing is in doubt. Pushing away from all of them together works even in an acute
//   crease, where pushing off one would push behind the other.
// How p stands to one surface: certainly fine, or in doubt, with how far behind it is
// (deficit) and its rounding bound (error), both as distances.
struct Standing {
  bool doubt = false;
  double deficit = 0.0;
  double error = 0.0;
};

// The surfaces settle_in keeps a point in front of: the scene's planes, and the triangle
// just hit (seen from the side the particle came from).
struct Surfaces {
  const Scene& scene;
  const SurfaceHit& last;
  bool last_triangle;
  Triangle tri;
  double facing;
  double tri_length;

  Surfaces(const Scene& scene, const SurfaceHit& last)
      : scene(scene),
        last(last),
        last_triangle(last.hit && last.triangle >= 0 && std::size_t(last.triangle) < scene.mesh.size()),
        tri(last_triangle ? scene.mesh.triangle(std::size_t(last.triangle)) : Triangle{}),
        facing(last_triangle && last.normal.dot(tri.normal()) < 0 ? -1.0 : 1.0),
        tri_length(tri.normal().norm()) {}

  Standing plane(std::size_t i, const Vec3& p) const {
    const Plane& plane = scene.planes[i];
    const Signed s = plane_value(plane, p);
    // The plane just hit taken as "not behind" is enough: a point exactly on it
    // (value 0) is left there, and the next piece starts on the surface instead of off it.
    // mutant hit_plane_not_strict (step 7, "strictly in front"): `last.hit && last.plane == int(i)` -> `false`
    const bool strict = last.hit && last.plane == int(i);                    // the plane just hit: strictly in front
    if (strict ? s.value > s.error : s.value >= s.error) return Standing{};  // certainly fine
    const double length = plane.normal.norm();
    return Standing{true, std::max(0.0, -s.value / length), s.error / length};
  }
  Standing triangle(const Vec3& p) const {
    const Signed s = triangle_value(tri, p);
    if (facing * s.value > s.error) return Standing{};  // certainly in front, on the facing side
    return Standing{true, std::max(0.0, -facing * s.value / tri_length), s.error / tri_length};
  }
  // Most of the time nothing is in doubt: a particle in the open, or well off what it hit.
  bool all_fine(const Vec3& x) const {
    bool fine = !last_triangle || !triangle(x).doubt;
    for (std::size_t i = 0; i < scene.planes.size() && fine; ++i) fine = !plane(i, x).doubt;
    return fine;
  }
  // The planes to keep x in front of: all but those it is clearly behind (by more than a
  // thousand rounding errors), which it was behind before; they are not ours to fix.
  std::vector<bool> kept(const Vec3& x) const {
    std::vector<bool> keep(scene.planes.size(), false);
    for (std::size_t i = 0; i < scene.planes.size(); ++i) {
      const Signed s = plane_value(scene.planes[i], x);
      // Settle keeps x off the surface just hit and nothing else: in a crease the push
      // off that surface leaves x behind the other one.
      // mutant settles_off_last_only (step 8, "crease", "behind"):
      //   `keep[i] = scene.planes[i].normal != Vec3::Zero() && (s.value >= -1000 * s.error || (last.hit && last.plane
      //     == int(i)));`
      //   -> `keep[i] = last.hit && last.plane == int(i);`
      keep[i] =
          scene.planes[i].normal != Vec3::Zero() && (s.value >= -1000 * s.error || (last.hit && last.plane == int(i)));
    }
    return keep;
  }
};

Vec3 settle_in(const Vec3& x, const Scene& scene, const SurfaceHit& last) {
  const Surfaces surfaces(scene, last);
  if (surfaces.all_fine(x)) return x;
  const std::vector<bool> keep = surfaces.kept(x);

  // Push away from every surface found in doubt so far: once a surface has needed a push
  // it keeps getting one, so that in a crease two surfaces are pushed off together instead
  // of in turn (each turn would push behind the other). The skin starts at four times the
  // largest rounding bound (enough to certify) plus a few ulps, and doubles if it was not.
  Vec3 p = x;
  std::vector<bool> pushed(scene.planes.size(), false);
  bool pushed_triangle = false;
  for (int round = 0; round < 40; ++round) {
    Standing worst;  // doubt if any surface is in doubt; the largest deficit and error
    const auto note = [&](const Standing& st) {
      worst = {true, std::max(worst.deficit, st.deficit), std::max(worst.error, st.error)};
    };
    for (std::size_t i = 0; i < scene.planes.size(); ++i) {
      if (!keep[i]) continue;
      const Standing st = surfaces.plane(i, p);
      if (!st.doubt) continue;
      note(st);
      pushed[i] = true;
    }
    if (surfaces.last_triangle) {
      const Standing st = surfaces.triangle(p);
      if (st.doubt) {
        note(st);
        pushed_triangle = true;
      }
    }
    if (!worst.doubt) return p;
    std::vector<Vec3> normals;
    if (pushed_triangle) normals.push_back(surfaces.facing * surfaces.tri.normal() / surfaces.tri_length);
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
      if (pushed[i]) normals.push_back(scene.planes[i].normal.normalized());
    const Vec3 away = away_from(normals);
    if (away == Vec3::Zero()) return p;  // surfaces facing each other with no room between
    // At least a few ulps of p: a smaller push would not move it at all.
    p += (worst.deficit + std::ldexp(4 * worst.error + 0x1p-50 * std::max(largest(p), 1e-290), round)) * away;
  }
  return p;  // a corner too sharp to get out of by small pushes: give up near x
}

}  // namespace

Vec3 settle(const Vec3& x, const Scene& scene, const SurfaceHit& last) {
  require_finite("settle", "x", x);
  require_valid("settle", scene);
  if (last.hit) {
    const bool plane = last.plane >= 0 && std::size_t(last.plane) < scene.planes.size();
    const bool triangle = last.triangle >= 0 && std::size_t(last.triangle) < scene.mesh.size();
    require(plane != triangle, "settle", "last",
            "name one plane or one triangle of the scene when last.hit (plane, triangle)",
            Vec3(last.plane, last.triangle, 0));
    require(last.normal.allFinite() && last.normal != Vec3::Zero(), "settle", "last.normal", "be finite and non-zero",
            last.normal);
  }
  return settle_in(x, scene, last);
}

// ---- Step 8: creases and corners; the handling loop --------------------------------------

void System::step(double dt) {
  require_positive("System::step", "dt", dt);
  require_valid("System::step", "emitter", emitter);
  require_valid("System::step", forces);
  require_valid("System::step", scene);
  for (std::size_t i = 0; i < particles.size(); ++i)
    require_valid("System::step", "particles[" + std::to_string(i) + "]", particles[i]);
  // 1. Births, with their attributes.
  const Births born = births(emitter, dt);
  emitter.owed = born.owed;
  for (int i = 0; i < born.count; ++i) {
    const Particle p = emit(emitter, random);
    particles.push_back(integrator == Integrator::verlet ? start_verlet(p, forces, dt) : p);
  }
  // 2. Forces and integration, then the step as a segment: test, impulse, position.
  for (Particle& p : particles) {
    const Vec3 a = p.position;
    p = integrator == Integrator::euler ? euler_step(p, forces, dt) : verlet_step(p, forces, dt);
    const Collision c = collide_in({a, p.position}, p.velocity, p.mass, dt, scene);
    p.position = c.position;
    p.velocity = c.velocity;
    p.bounces = c.bounces;
    // Verlet keeps its velocity in (position - previous): rewrite it after a bounce.
    // mutant verlet_previous_kept (step 8, "previous", "Verlet"):
    //   `if (integrator == Integrator::verlet && (c.bounces > 0 || c.stopped)) p.previous = p.position - p.velocity *
    //     dt;`
    //   -> ``
    if (integrator == Integrator::verlet && (c.bounces > 0 || c.stopped)) p.previous = p.position - p.velocity * dt;
  }
  // 3. Death: those whose time is up.
  particles = age(std::move(particles), dt);
  time += dt;
}

// ---- Step 9 (L07S9): a damped spring between two particles -------------------------

// Hooke's law: a spring pulls in proportion to how far it is stretched beyond its rest
// length, along its own line. With u the unit vector from b to a, a stretched spring
// (l > l_rest) pulls a back toward b: F_a = -k_s (l - l_rest) u. The damper resists the
// rate at which the length changes, and that rate is dl/dt = (v_a - v_b) . u: only the
// part of the relative velocity along the spring. Damping the whole relative velocity
// would also brake two particles that circle each other at a fixed length, which no
// spring does. The force on b is -F_a (Newton's third law), so the pair's momentum is
// kept.
Vec3 spring_force(const Particle& a, const Particle& b, const Spring& spring) {
  require_valid("spring_force", "a", a);
  require_valid("spring_force", "b", b);
  require_size("spring_force", "spring.stiffness", spring.stiffness);
  require_size("spring_force", "spring.damping", spring.damping);
  require_size("spring_force", "spring.rest_length", spring.rest_length);
  // d = b - a gives the force on b (or the sign flipped): the spring pushes when
  // stretched.
  // mutant spring_force_on_b (step 9, "force is on a"): `a.position - b` -> `b.position - a`
  const Vec3 d = a.position - b.position;
  const double l = d.norm();
  if (l == 0) return Vec3::Zero();  // no direction to pull along: the header's rule
  const Vec3 u = d / l;
  // Hooke's law on the whole length: a spring that is never at rest.
  // mutant spring_ignores_rest_length (step 9, "rest length"):
  //   `const double stretch = l - spring.rest_length;`
  //   -> `const double stretch = l;`
  const double stretch = l - spring.rest_length;                // > 0: stretched
  const double lengthening = (a.velocity - b.velocity).dot(u);  // dl/dt
  // Step 9 (extension): the damper on the whole relative velocity brakes particles that
  // circle each other at a fixed length; a spring damps only the change of its length.
  // mutant spring_damps_whole_relative_velocity (step 9, "along the spring"):
  //   `return -(spring.stiffness * stretch + spring.damping * lengthening) * u;`
  //   -> `return -spring.stiffness * stretch * u - spring.damping * (a.velocity - b.velocity);`
  return -(spring.stiffness * stretch + spring.damping * lengthening) * u;
}

// ---- Step 10 (L07S10): rigid-body impulse with its angular part --------------------

namespace {

void require_valid(const char* query, const std::string& name, const RigidBody& body) {
  require_finite(query, name + ".centre", body.centre);
  require_finite(query, name + ".velocity", body.velocity);
  require_finite(query, name + ".angular_velocity", body.angular_velocity);
  require_positive(query, name + ".mass", body.mass);
  const Mat3& m = body.inverse_inertia;
  const bool symmetric = m.allFinite() && m(0, 1) == m(1, 0) && m(0, 2) == m(2, 0) && m(1, 2) == m(2, 1);
  const bool diagonal = m(0, 0) >= 0 && m(1, 1) >= 0 && m(2, 2) >= 0;
  if (!symmetric || !diagonal)
    reject(query, name + ".inverse_inertia", "be finite, symmetric, with a diagonal >= 0",
           "rows " + text(Vec3(m.row(0))) + " " + text(Vec3(m.row(1))) + " " + text(Vec3(m.row(2))));
}

}  // namespace

// Derivation (lecture 003). A body's material point at the contact moves with
// v_p = v + w x r, r = point - centre. An impulse J = j n at that point changes the
// momentum by J (v' = v + J / m) and the angular momentum by the torque impulse r x J
// (w' = w + I^-1 (r x J), with I^-1 in the world frame). So the contact point's velocity
// changes by
//     dv_p = J / m + (I^-1 (r x J)) x r  =  j (n / m + (I^-1 (r x n)) x r),
// and along the normal by j (1/m + n . ((I^-1 (r x n)) x r)). b gets -J. Newton's law of
// restitution asks v_rel' = -e v_rel; v_rel' - v_rel = j * (the sum of both bodies' terms),
// so j = -(1 + e) v_rel / (1/m_a + 1/m_b + angular terms). The angular terms equal
// (r x n) . I^-1 (r x n) >= 0: a body that can turn gives way more easily than one that
// cannot, so j is never more than the particle formula's.
RigidImpulse rigid_impulse(const RigidBody& a, const RigidBody& b, const Contact& contact) {
  require_valid("rigid_impulse", "a", a);
  require_valid("rigid_impulse", "b", b);
  require_finite("rigid_impulse", "contact.point", contact.point);
  const Vec3& n = contact.normal;
  require(n.allFinite() && std::abs(n.squaredNorm() - 1) <= 1e-9, "rigid_impulse", "contact.normal", "be a unit vector",
          n);
  require_size("rigid_impulse", "contact.restitution", contact.restitution);
  RigidImpulse out;
  out.velocity_a = a.velocity, out.angular_velocity_a = a.angular_velocity;
  out.velocity_b = b.velocity, out.angular_velocity_b = b.angular_velocity;
  const Vec3 r_a = contact.point - a.centre, r_b = contact.point - b.centre;
  const Vec3 v_pa = a.velocity + a.angular_velocity.cross(r_a), v_pb = b.velocity + b.angular_velocity.cross(r_b);
  out.v_rel = n.dot(v_pa - v_pb);
  if (!(out.v_rel < 0)) return out;  // moving apart, or resting/sliding (v_rel = 0): no impulse
  out.closing = true;
  const Vec3 turn_a = a.inverse_inertia * r_a.cross(n), turn_b = b.inverse_inertia * r_b.cross(n);
  // Step 10 (extension): the particle formula j = -(1 + e) v_rel / (1/m_a + 1/m_b): the
  // bodies' turning left out of j, so the contact points do not separate at -e v_rel.
  // mutant rigid_angular_part_forgotten (step 10, "angular terms", "denominator"):
  //   `const double denominator = 1 / a.mass + 1 / b.mass + n.dot(turn_a.cross(r_a)) + n.dot(turn_b.cross(r_b));`
  //   -> `const double denominator = 1 / a.mass + 1 / b.mass;`
  const double denominator = 1 / a.mass + 1 / b.mass + n.dot(turn_a.cross(r_a)) + n.dot(turn_b.cross(r_b));
  out.j = -(1 + contact.restitution) * out.v_rel / denominator;
  const Vec3 J = out.j * n;
  out.velocity_a = a.velocity + J / a.mass;  // p_a += J
  out.velocity_b = b.velocity - J / b.mass;  // p_b -= J
  // J x r instead of r x J: the torque impulse turns the body the wrong way.
  // mutant rigid_torque_order_swapped (step 10, "r_a x J"): `r_a.cross(J` -> `J.cross(r_a`
  out.angular_velocity_a = a.angular_velocity + a.inverse_inertia * r_a.cross(J);  // L_a += r_a x J
  // The angular momentum change r x J taken as the angular velocity change: the
  // inverse inertia not applied.
  // mutant rigid_inverse_inertia_not_applied (step 10, "inverse inertia"):
  //   `out.angular_velocity_b = b.angular_velocity - b.inverse_inertia * r_b.cross(J);`
  //   -> `out.angular_velocity_b = b.angular_velocity - r_b.cross(J);`
  out.angular_velocity_b = b.angular_velocity - b.inverse_inertia * r_b.cross(J);  // L_b -= r_b x J
  return out;
}

}  // namespace labkit::lab07
