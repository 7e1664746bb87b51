// Lab 07's bounces: the impulse (step 5), collide's trace piece by piece (step 6), and the
// invariants of collide, settle and a whole system's step (step 7).
#include "07_particles/judge_internal.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab07::judge {

constexpr double kEnergy = 1e-12;  // the energy invariants' relative tolerance

// ---- Step 5 ----------------------------------------------------------------------------

Outcome impulse(const ImpulseCase& in, const Impulse& got) {
  const double e_ = in.material.restitution, mu = in.material.friction;
  const oracle::Impulse exact = oracle::impulse(in.velocity, in.object_velocity, in.normal, in.mass, e_, mu);
  const double V = in.velocity.norm() + in.object_velocity.norm();
  const double tol_v = kRelative * V * (2 + e_ + mu * (1 + e_)) + 1e-300;
  // v_close's sign is in doubt when moving every velocity by 1e-9 V, and the normal by
  // 1e-9, could flip it.
  const bool doubt = std::abs(exact.v_close) <= closing_band(in);
  Expect e(
      "j_n = -(1 + e) m v_close n with v_close = (v - v_obj) . n; friction opposes the sliding with min(mu |j_n|, m "
      "|v_t|)");
  if (got.closing != exact.closing && !doubt)
    return fail("closing = " + describe(exact.closing), "closing = " + describe(got.closing),
                "v_close = (v - v_obj) . n = " + fmt(exact.v_close) + ": the particle is " +
                    (exact.closing ? "closing (v_close < 0)" : "not closing (v_close >= 0)"));
  e.near("v_close", got.v_close, exact.v_close, tol_v);
  e.near("normal_impulse", got.normal_impulse, exact.normal_impulse, in.mass * tol_v);
  e.near("friction", got.friction, exact.friction, in.mass * tol_v);
  e.near("velocity", got.velocity, exact.velocity, tol_v);
  const Outcome o = e.outcome();
  if (o.verdict == Outcome::Verdict::fail) return o;
  return doubt ? ambiguous() : pass();
}

// ---- Step 6 ----------------------------------------------------------------------------

namespace {

// What any answer of collide must be: within the bounce cap, stopped only at it, finite.
Outcome collision_bounds(const Scene& scene, const Collision& got, const std::string& answer) {
  const int cap = std::clamp(scene.bounce_cap, 0, kMaxBounceCap);
  if (got.bounces < 0 || got.bounces > cap)
    return fail("between 0 and " + std::to_string(cap) + " bounces", answer,
                "the bounce cap is " + std::to_string(cap) +
                    ": at most that many impulses, then the next hit stops the particle");
  if (got.stopped && got.bounces != cap)
    return fail("no stop before the cap", answer,
                "the bounce cap: a particle stops only when it hits again after " + std::to_string(cap) + " bounces");
  if (!finite(got.position) || !finite(got.velocity))
    return fail("a finite position and velocity", answer, "not finite");
  return pass();
}

// How a verdict names piece k of the step (from the hit point of bounce k - 1 on).
std::string piece_name(int k, bool moving, const Segment& piece) {
  if (k == 0)
    return moving ? "the relative step a' -> b, a' = a + u dt = " + fmt(piece.a) +
                        " (the surfaces move at u and are given where they end the step: seen from them, the "
                        "particle starts at a + u dt)"
                  : std::string("the step a -> b");
  return "the piece after bounce " + std::to_string(k - 1) +
         (moving ? " (from -> from + (v' - u) r: the particle moves relative to the moving surfaces)" : "");
}

// The last piece of a particle that did not stop: clear to its end, where the particle
// ends with the velocity it had there.
Outcome clear_last_piece(const Scene& scene, const Segment& piece, const std::string& where, const SurfaceHit* left,
                         const Collision& got, const Vec3& v, double tol, double tol_v, const std::string& answer) {
  const Outcome o = within(where, first_hit_on(piece, scene, SurfaceHit{}, Rules::random, left));
  if (o.verdict == Outcome::Verdict::fail)
    return fail(o.expected, answer, o.why + " (a hit there is another bounce, or the stop when the cap is used up)");
  Expect e("after each hit the particle moves on from the hit point, with the new velocity, for the remaining time");
  e.that("position", (got.position - piece.b).norm() <= tol, fmt(got.position), fmt(piece.b),
         "the particle must end where " + where + " ends, " + fmt(piece.b) +
             ": after each hit it moves on from the hit point for the remaining time (1 - t) r only (tolerance " +
             fmt(tol) + ")");
  e.near("velocity", got.velocity, v, tol_v);
  const Outcome end = e.outcome();
  if (end.verdict == Outcome::Verdict::fail) return end;
  return o;
}

// Bounce k, the stop: the particle rests where the hit left it.
Outcome stopped_at(const Bounce& b, const Collision& got, const Vec3& u, double tol, double tol_v) {
  Expect e("the bounce cap: after bounce_cap impulses the next hit stops the particle, at rest on the surface");
  e.that("position", (got.position - b.from).norm() <= tol, fmt(got.position), fmt(b.from),
         "a stopped particle stays at its stopping hit's `from`");
  e.that("velocity", (got.velocity - u).norm() <= tol_v, fmt(got.velocity), fmt(u),
         "a stopped particle is at rest on the surface: velocity zero, or the moving scene's u");
  return e.outcome();
}

}  // namespace

Outcome collide(const CollideCase& in, const Collision& got) {
  const Scene& scene = in.scene;
  const std::string answer = describe(got);
  if (const Outcome o = collision_bounds(scene, got, answer); o.verdict == Outcome::Verdict::fail) return o;

  const double e_ = scene.material.restitution, mu = scene.material.friction;
  // A moving scene (u != 0): the loop runs in its frame, from the relative step a' -> b.
  const Vec3 u = scene.velocity;
  const bool moving = u != Vec3::Zero();
  const double tol_v = kRelative * (in.velocity.norm() + u.norm()) * (2 + e_ + mu * (1 + e_)) + 1e-300;
  Segment piece = {in.step.a + u * in.dt, in.step.b};
  Vec3 v = in.velocity;
  double remaining = in.dt;
  bool doubt = false;
  for (int k = 0;; ++k) {
    const std::string where = piece_name(k, moving, piece);
    const SurfaceHit* left = k == 0 ? nullptr : &got.trace[std::size_t(k - 1)].hit;
    const double tol = kRelative * scale_with(scene, {piece.a, piece.b, in.step.a, in.step.b});
    if (k == got.bounces && !got.stopped) {  // the last piece: clear to its end
      const Outcome o = clear_last_piece(scene, piece, where, left, got, v, tol, tol_v, answer);
      if (o.verdict == Outcome::Verdict::fail) return o;
      doubt = doubt || o.verdict == Outcome::Verdict::ambiguous;
      break;
    }
    const Bounce& b = got.trace[std::size_t(k)];
    const Outcome o = within(where, first_hit_on(piece, scene, b.hit, Rules::random, left));
    if (o.verdict == Outcome::Verdict::fail) return fail(o.expected, answer, o.why);
    doubt = doubt || o.verdict == Outcome::Verdict::ambiguous;
    if (!b.hit.hit) return fail("a hit", answer, where + ": the trace records no hit");
    if (!finite(b.from) || !finite(b.velocity))
      return fail("a finite `from` and velocity", answer, "bounce " + std::to_string(k) + ": not finite");
    if ((b.from - b.hit.point).norm() > tol)
      return fail(fmt(b.hit.point), fmt(b.from),
                  "bounce " + std::to_string(k) + ": `from` must be the hit point (settled by at most tol)");
    if (k == got.bounces) {  // the stop
      const Outcome stop = stopped_at(b, got, u, tol, tol_v);
      return stop.verdict == Outcome::Verdict::fail ? stop : (doubt ? ambiguous() : pass());
    }
    const oracle::Impulse exact =
        oracle::impulse(v, u, exact_normal(scene, b.hit), in.mass, scene.material.restitution, scene.material.friction);
    if ((b.velocity - exact.velocity).norm() > tol_v)
      return fail(fmt(exact.velocity), fmt(b.velocity),
                  "bounce " + std::to_string(k) + ": the velocity after the impulse (e = " +
                      fmt(scene.material.restitution) + ", mu = " + fmt(scene.material.friction) + ") on " + fmt(v) +
                      (moving ? ", against surfaces moving at u = " + fmt(u) +
                                    ": the impulse takes the relative velocity v - u, impulse(v, u, n, ...)"
                              : std::string()));
    remaining *= 1 - b.hit.t;
    v = b.velocity;
    piece = {b.from, b.from + (v - u) * remaining};
  }
  return doubt ? ambiguous() : pass();
}

// ---- Step 7 ----------------------------------------------------------------------------

Outcome invariants(const CollideCase& in, const Collision& got) {
  const Scene& scene = in.scene;
  const std::string answer = describe(got);
  const int used = std::clamp(got.bounces + (got.stopped ? 1 : 0), 0, kMaxBounceCap + 1);
  if (!finite(got.position) || !finite(got.velocity))
    return fail("a finite position and velocity", answer, "not finite");
  for (int k = 0; k < used; ++k)
    if (!finite(got.trace[std::size_t(k)].from))
      return fail("a finite `from`", answer, "bounce " + std::to_string(k) + "'s `from` is not finite");
  // (1) Never behind a plane the step began in front of (in the scene's frame: a' = a + u dt).
  const Vec3 u = scene.velocity;
  const Vec3 start = in.step.a + u * in.dt;
  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const Plane& p = scene.planes[i];
    if (oracle::plane_side(p, start) < 0) continue;
    if (oracle::plane_side(p, got.position) < 0)
      return fail("a position not behind plane " + std::to_string(i), answer,
                  "the particle ends behind plane " + std::to_string(i) + ", by " +
                      fmt(-oracle::plane_distance(p, got.position)) + " (exactly: its n . x + c < 0)");
  }
  // Each `from`, strictly in front of the surface just hit; the end, not behind the last.
  const auto side_of = [&](const SurfaceHit& h, const Vec3& x) {
    if (valid_plane(scene, h.plane)) return oracle::plane_side(scene.planes[std::size_t(h.plane)], x);
    const Triangle tri = scene.mesh.triangle(std::size_t(h.triangle));
    const int facing = h.normal.dot(tri.normal()) < 0 ? -1 : 1;
    return facing * oracle::orientation(tri.v0, tri.v1, tri.v2, x);
  };
  for (int k = 0; k < used; ++k) {
    const Bounce& b = got.trace[std::size_t(k)];
    if (!b.hit.hit || valid_plane(scene, b.hit.plane) == valid_triangle(scene, b.hit.triangle))
      return fail("a hit on one surface", answer, "bounce " + std::to_string(k) + " names no valid surface");
    if (side_of(b.hit, b.from) <= 0)
      return fail("`from` strictly in front of the surface hit", answer,
                  "every `from` must be strictly in front of the surface it bounced off, exactly: bounce " +
                      std::to_string(k) + "'s " + fmt(b.from) + " is on or behind it (a rounded hit point: settle it)");
  }
  if (used > 0 && side_of(got.trace[std::size_t(used - 1)].hit, got.position) < 0)
    return fail("an end not behind the last surface hit", answer,
                "the particle ends behind the last surface it hit, seen from the side it came from (exactly)");
  // (3) and (4): energy.
  const double e = scene.material.restitution, mu = scene.material.friction;
  if (u == Vec3::Zero()) {
    if (e <= 1 && !oracle::squared_speed_at_most(got.velocity, in.velocity, 1 + kEnergy))
      return fail("|v_end|^2 <= (1 + 1e-12) |v|^2 = " + fmt(in.velocity.squaredNorm()), fmt(got.velocity.squaredNorm()),
                  "with e <= 1 against still surfaces, a bounce never adds energy");
    if (e == 1 && mu == 0 && !got.stopped && !oracle::squared_speed_at_least(got.velocity, in.velocity, 1 - kEnergy))
      return fail("|v_end|^2 = |v|^2 = " + fmt(in.velocity.squaredNorm()), fmt(got.velocity.squaredNorm()),
                  "with e = 1 and mu = 0 a bounce keeps the speed (within 1e-12)");
    return pass();
  }
  // A moving scene: the same, relative to it; v - u itself rounds, by about 1e-16 |u|.
  const double before = (in.velocity - u).squaredNorm(), after = (got.velocity - u).squaredNorm();
  const double slack = kEnergy * (before + std::sqrt(before) * u.norm());
  if (e <= 1 && after > before + slack)
    return fail("|v_end - u|^2 <= (1 + 1e-12) |v - u|^2 = " + fmt(before), fmt(after),
                "with e <= 1, a bounce never adds energy relative to the moving surfaces (u = " + fmt(u) + ")");
  if (e == 1 && mu == 0 && !got.stopped && after < before - slack)
    return fail("|v_end - u|^2 = |v - u|^2 = " + fmt(before), fmt(after),
                "with e = 1 and mu = 0 a bounce keeps the speed relative to the moving surfaces (u = " + fmt(u) + ")");
  return pass();
}

Outcome settle(const SettleCase& in, const Vec3& got) {
  const Scene& scene = in.scene;
  const double tol = kRelative * scale_with(scene, {in.x});
  const std::string rule =
      "settle moves x by less than tol to where it is, exactly, not behind any plane it was within rounding of, and "
      "strictly in front of the surface just hit";
  if (!finite(got) || (got - in.x).norm() > tol)
    return fail("a point within " + fmt(tol) + " of x", fmt(got),
                rule + ": settle moved x by " + fmt((got - in.x).norm()));
  // The planes settle must keep got in front of: all but those x is clearly behind (by
  // more than 1000 rounding errors), which are not settle's business.
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const Plane& p = scene.planes[i];
    const bool strict = in.last.hit && in.last.plane == int(i);
    const Vec3 terms = p.normal.cwiseProduct(in.x);
    const double value = terms.x() + terms.y() + terms.z() + p.offset;
    if (strict || (p.normal != Vec3::Zero() && value >= -1000 * 1e-15 * (terms.cwiseAbs().sum() + std::abs(p.offset))))
      kept.push_back(i);
  }
  const bool triangle = in.last.hit && valid_triangle(scene, in.last.triangle);
  // Two surfaces or more to stay in front of: x may sit in a crease, where the push off
  // one alone goes behind the other.
  const std::string crease = kept.size() + (triangle ? 1 : 0) > 1
                                 ? "; in a crease, push off every surface found in doubt so far, together: a push "
                                   "off one alone can go behind another"
                                 : "";
  for (std::size_t i : kept) {
    const bool strict = in.last.hit && in.last.plane == int(i);
    const int side = oracle::plane_side(scene.planes[i], got);
    if (strict ? side <= 0 : side < 0)
      return fail(strict ? "strictly in front of plane " + std::to_string(i) + " (the one just hit)"
                         : "not behind plane " + std::to_string(i),
                  fmt(got),
                  rule + ": n . x + c of plane " + std::to_string(i) + " is " + (side < 0 ? "negative" : "zero") +
                      " there" + crease);
  }
  if (triangle) {
    const Triangle tri = scene.mesh.triangle(std::size_t(in.last.triangle));
    const int facing = in.last.normal.dot(tri.normal()) < 0 ? -1 : 1;
    if (facing * oracle::orientation(tri.v0, tri.v1, tri.v2, got) <= 0)
      return fail("strictly in front of triangle " + std::to_string(in.last.triangle) + ", on last.normal's side",
                  fmt(got), rule + ": the point is on or behind the triangle's plane, on last.normal's side" + crease);
  }
  return pass();
}

Outcome system_step(const SystemCase& in, const System& after, int step) {
  const std::string which = "after step " + std::to_string(step + 1) + ", ";
  if (std::abs(after.time - (step + 1) * in.dt) > 1e-9 * (step + 1) * in.dt)
    return fail(fmt((step + 1) * in.dt), fmt(after.time), which + "time must have grown by dt each step");
  // With no particle old enough to die yet, the count is the births so far.
  const Emitter& em = in.emitter;
  if (em.lifetime - em.lifetime_spread > (step + 1) * in.dt) {
    const long double due = em.owed + (long double)em.rate * in.dt * (step + 1), slack = 1e-9L * (due + 1);
    const auto count = (long double)after.particles.size();
    if (count < std::floor(due - slack) || count > std::floor(due + slack))
      return fail(std::to_string((long long)std::floor(due)) + " particles (the births so far)",
                  std::to_string(after.particles.size()), which + "none can have died yet");
  }
  for (std::size_t i = 0; i < after.particles.size(); ++i) {
    const Particle& p = after.particles[i];
    const std::string who = which + "particle " + std::to_string(i);
    if (!finite(p.position) || !finite(p.velocity)) return fail("finite", describe(p), who + " is not finite");
    if (!p.alive || !(p.age < p.lifetime))
      return fail("alive, age < lifetime",
                  "alive = " + describe(p.alive) + ", age " + fmt(p.age) + ", lifetime " + fmt(p.lifetime),
                  who + ": the dead are removed at the end of the step");
    for (std::size_t k = 0; k < in.scene.planes.size(); ++k)
      if (oracle::plane_side(in.scene.planes[k], p.position) < 0)
        return fail("not behind plane " + std::to_string(k), fmt(p.position),
                    who + " is behind plane " + std::to_string(k) + " by " +
                        fmt(-oracle::plane_distance(in.scene.planes[k], p.position)) + " (exactly)");
  }
  return pass();
}

}  // namespace labkit::lab07::judge
