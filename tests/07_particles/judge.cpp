// Lab 07's text and replay tokens for its types, and the judges of steps 1 and 2:
// emitting, births and ageing; forces and the integrators. Step 3 (aim): judge.aim.cpp;
// surfaces and step 4: judge.surfaces.cpp; steps 5 to 7: judge.bounces.cpp.
#include "07_particles/judge_internal.h"

#include <algorithm>
#include <cmath>

namespace labkit::lab07 {

// ---- Text and replay tokens ----------------------------------------------------------

void encode(codec::Writer& w, const Forces& f) {
  codec::encode(w, f.gravity);
  w.unit(f.drag);
  w.unit(f.air_drag);
}
void decode(codec::Reader& r, Forces& f) {
  codec::decode(r, f.gravity);
  f.drag = r.real();
  f.air_drag = r.real();
}
void encode(codec::Writer& w, const Material& m) {
  w.unit(m.restitution);
  w.unit(m.friction);
}
void decode(codec::Reader& r, Material& m) {
  m.restitution = r.real();
  m.friction = r.real();
}
void encode(codec::Writer& w, const Scene& s) {
  w.count(s.planes.size());
  for (const Plane& p : s.planes) {
    for (int i = 0; i < 3; ++i) w.unit(p.normal[i]);
    w.real(p.offset);
  }
  codec::encode(w, s.mesh);
  encode(w, s.material);
  w.count(std::size_t(std::max(0, s.bounce_cap)));
  codec::encode(w, s.velocity);
}
void decode(codec::Reader& r, Scene& s) {
  s.planes.resize(r.count(64));
  for (Plane& p : s.planes) {
    codec::decode(r, p.normal);
    p.offset = r.real();
  }
  codec::decode(r, s.mesh);
  decode(r, s.material);
  s.bounce_cap = int(r.count(kMaxBounceCap));
  codec::decode(r, s.velocity);
}

std::string describe(const Forces& f) {
  return "gravity=" + fmt(f.gravity) + " drag=" + fmt(f.drag) + " air_drag=" + fmt(f.air_drag);
}
std::string describe(const Material& m) { return "e=" + fmt(m.restitution) + " mu=" + fmt(m.friction); }
std::string describe(const Scene& s) {
  std::string text = describe(s.material) + ", bounce cap " + std::to_string(s.bounce_cap) + ", " +
                     std::to_string(s.planes.size()) + (s.planes.size() == 1 ? " plane" : " planes");
  if (s.velocity != Vec3::Zero()) text += ", moving at u = " + fmt(s.velocity) + " (given where it ends the step)";
  for (std::size_t i = 0; i < s.planes.size(); ++i)
    text += "\n    plane " + std::to_string(i) + ": " + describe(s.planes[i]);
  if (s.mesh.size() > 0) text += "\n    mesh: " + describe(s.mesh);
  return text;
}
std::string describe(const Collision& c) {
  std::string text = "position " + fmt(c.position) + ", velocity " + fmt(c.velocity) + ", " +
                     std::to_string(c.bounces) + (c.bounces == 1 ? " bounce" : " bounces") +
                     (c.stopped ? ", stopped" : "");
  const int shown = std::clamp(c.bounces + (c.stopped ? 1 : 0), 0, kMaxBounceCap + 1);
  for (int k = 0; k < shown; ++k) {
    const Bounce& b = c.trace[std::size_t(k)];
    text += "\n    " + std::string(k == c.bounces ? "stop" : "bounce " + std::to_string(k)) + ": " +
            (b.hit.plane >= 0 ? "plane " + std::to_string(b.hit.plane) : "triangle " + std::to_string(b.hit.triangle)) +
            " at t = " + fmt(b.hit.t) + ", point " + fmt(b.hit.point) + ", normal " + fmt(b.hit.normal) +
            ", velocity after " + fmt(b.velocity) + ", from " + fmt(b.from);
  }
  return text;
}

System system_of(const SystemCase& c) {
  System s;
  s.emitter = c.emitter;
  s.scene = c.scene;
  s.forces = c.forces;
  s.integrator = c.verlet ? Integrator::verlet : Integrator::euler;
  s.random = Random(std::uint64_t(c.seed));
  return s;
}

}  // namespace labkit::lab07

namespace labkit::lab07::judge {

// ---- Step 1 ----------------------------------------------------------------------------

Outcome emit(const EmitCase& in, const std::vector<Particle>& first, const std::vector<Particle>& second) {
  const Emitter& em = in.emitter;
  const Vec3 axis = em.direction.normalized();
  const double tol = kRelative * std::max({largest(em.position), largest(em.half_extents), 1e-300});
  const double tol_v = kRelative * (em.speed + em.speed_spread);
  const double tol_l = kRelative * (std::abs(em.lifetime) + em.lifetime_spread);
  const double cos_cone = std::cos(std::min(em.cone, M_PI));
  bool varied = false;
  for (std::size_t i = 0; i < first.size(); ++i) {
    const Particle& p = first[i];
    const std::string which = "particle " + std::to_string(i) + ": ";
    const Vec3 off = (p.position - em.position).cwiseAbs() - em.half_extents;
    if (!finite(p.position) || off.maxCoeff() > tol)
      return fail("a position within position +- half_extents", fmt(p.position),
                  which + "its position is " + fmt(off.maxCoeff()) + " outside the emitter's box");
    const double speed = p.velocity.norm();
    if (!(speed >= em.speed - em.speed_spread - tol_v && speed <= em.speed + em.speed_spread + tol_v))
      return fail("a speed in [" + fmt(em.speed - em.speed_spread) + ", " + fmt(em.speed + em.speed_spread) + "]",
                  fmt(speed), which + "its speed is out of the emitter's range");
    if (speed > 0 && p.velocity.dot(axis) / speed < cos_cone - 1e-9)
      return fail("a direction within " + fmt(em.cone) + " rad of " + fmt(axis), fmt(p.velocity),
                  which + "its direction is " + fmt(std::acos(std::clamp(p.velocity.dot(axis) / speed, -1.0, 1.0))) +
                      " rad from the cone's axis");
    if (!(p.lifetime >= em.lifetime - em.lifetime_spread - tol_l &&
          p.lifetime <= em.lifetime + em.lifetime_spread + tol_l))
      return fail("a lifetime in [" + fmt(em.lifetime - em.lifetime_spread) + ", " +
                      fmt(em.lifetime + em.lifetime_spread) + "]",
                  fmt(p.lifetime), which + "its lifetime is out of the emitter's range");
    Expect e("a particle is born with the emitter's mass, age 0, alive, and previous = position");
    e.equal("mass", p.mass, em.mass);
    e.equal("age", p.age, 0.0);
    e.equal("alive", p.alive, true);
    e.equal("previous", p.previous, p.position);
    e.equal("bounces", p.bounces, 0);
    const Outcome o = e.outcome();
    if (o.verdict == Outcome::Verdict::fail) return fail(o.expected, o.got, which + "a newborn particle: " + o.why);
    const Particle& q = second[i];
    if (q.position != p.position || q.velocity != p.velocity || q.lifetime != p.lifetime)
      return fail(describe(p), describe(q),
                  which + "emitted again from the same seed it came out different: draw only from `random`");
    if (i > 0 &&
        (p.position != first[0].position || p.velocity != first[0].velocity || p.lifetime != first[0].lifetime))
      varied = true;
  }
  // A spread only shows when it moves something: the cone turns nothing at zero speed.
  const bool moving = em.speed != 0 || em.speed_spread > 0;
  const bool spread =
      em.half_extents != Vec3::Zero() || (em.cone > 0 && moving) || em.speed_spread > 0 || em.lifetime_spread > 0;
  if (spread && first.size() >= 4 && !varied)
    return fail("particles that differ (the emitter has spreads)", "identical particles",
                "every particle came out the same");
  return pass();
}

Outcome births(const BirthsCase& in, const std::vector<Births>& got) {
  long double due = in.emitter.owed, total = 0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    due += (long double)in.emitter.rate * in.dt;
    total += got[k].count;
    const long double slack = 1e-9L * (due + 1);
    const std::string which = "step " + std::to_string(k) + ": ";
    if (got[k].count < 0) return fail("a count >= 0", describe(got[k].count), which + "a negative number of births");
    if (!(got[k].owed >= 0 && got[k].owed < 1))
      return fail("owed in [0, 1)", fmt(got[k].owed), which + "what is owed must be the fraction left over");
    if (total < std::floor(due - slack) || total > std::floor(due + slack))
      return fail(std::to_string((long long)std::floor(due)) + " births so far", std::to_string((long long)total),
                  which + "after " + std::to_string(k + 1) +
                      " steps the births must be owed + rate * time = " + fmt(double(due)) + ", rounded down");
    if (std::abs((long double)got[k].owed + total - due) > slack + 1e-15L * due)
      return fail("births + owed = " + fmt(double(due)), fmt(double(got[k].owed + total)),
                  which + "the births so far plus what is owed must add up to owed + rate * time");
  }
  return pass();
}

Outcome age(const AgeCase& in, const std::vector<Particle>& got) {
  std::vector<Particle> expected;
  for (Particle p : in.particles) {
    p.age += in.dt;
    p.alive = p.age < p.lifetime;
    if (p.alive) expected.push_back(p);
  }
  std::string want, have;
  for (const Particle& p : expected) want += (want.empty() ? "" : ", ") + fmt(p.age) + "/" + fmt(p.lifetime);
  for (const Particle& p : got) have += (have.empty() ? "" : ", ") + fmt(p.age) + "/" + fmt(p.lifetime);
  want = "ages/lifetimes [" + want + "]";
  have = "ages/lifetimes [" + have + "]";
  if (got.size() != expected.size())
    return fail(want, have,
                std::to_string(expected.size()) + " particles survive (a new age >= the lifetime dies), not " +
                    std::to_string(got.size()));
  for (std::size_t i = 0; i < got.size(); ++i) {
    const Particle &g = got[i], &x = expected[i];
    if (g.position != x.position || g.velocity != x.velocity || g.lifetime != x.lifetime)
      return fail(want, have, "survivor " + std::to_string(i) + " is not the one expected there: keep their order");
    if (g.age != x.age)
      return fail(want, have, "survivor " + std::to_string(i) + "'s age must be age + dt = " + fmt(x.age));
    if (!g.alive) return fail(want, have, "survivor " + std::to_string(i) + " says alive = false");
  }
  return pass();
}

// ---- Step 2 ----------------------------------------------------------------------------

namespace {

oracle::Forces exact_forces(const Forces& f) { return {f.gravity, f.drag, f.air_drag}; }
oracle::State state_of(const Particle& p) { return {p.position, p.velocity, p.previous}; }

// The size of the acceleration's terms, for tolerances: |g| + (k1 |v| + k2 |v|^2) / m.
double acceleration_size(const MotionCase& in) {
  const double v = in.particle.velocity.norm();
  return largest(in.forces.gravity) +
         (std::abs(in.forces.drag) * v + std::abs(in.forces.air_drag) * v * v) / in.particle.mass;
}

Outcome compare_particle(const std::string& rule, const MotionCase& in, const oracle::State& exact, const Particle& got,
                         double tol_p, double tol_v) {
  Expect e(rule);
  e.near("position", got.position, exact.position, tol_p);
  e.near("velocity", got.velocity, exact.velocity, tol_v);
  e.near("previous", got.previous, exact.previous, tol_p);
  e.equal("mass", got.mass, in.particle.mass);
  e.equal("age", got.age, in.particle.age);
  e.equal("lifetime", got.lifetime, in.particle.lifetime);
  e.equal("alive", got.alive, in.particle.alive);
  return e.outcome();
}

double position_tolerance(const MotionCase& in) {
  const Particle& p = in.particle;
  return kRelative * (largest(p.position) + largest(p.previous) + in.dt * largest(p.velocity) +
                      in.dt * in.dt * acceleration_size(in) + 1e-300);
}

}  // namespace

Outcome force(const MotionCase& in, const Vec3& got) {
  const Vec3 exact = oracle::force(in.particle.velocity, in.particle.mass, exact_forces(in.forces));
  Expect e(
      "F = m g - k1 v - k2 |v| v: gravity is an acceleration, and each drag opposes the whole velocity vector "
      "(|v| is the speed, not one component's size)");
  e.near("force", got, exact, kRelative * in.particle.mass * acceleration_size(in) + 1e-300);
  return e.outcome();
}

Outcome euler_step(const MotionCase& in, const Particle& got) {
  const oracle::State exact =
      oracle::euler_step(state_of(in.particle), in.particle.mass, exact_forces(in.forces), in.dt);
  const double tol_v = kRelative * (largest(in.particle.velocity) + in.dt * acceleration_size(in) + 1e-300);
  return compare_particle(
      "explicit Euler takes both updates from the start of the step: a = F / m, p' = p + v dt, "
      "v' = v + a dt, previous' = p",
      in, exact, got, position_tolerance(in), tol_v);
}

Outcome start_verlet(const MotionCase& in, const Particle& got) {
  const oracle::State exact =
      oracle::start_verlet(state_of(in.particle), in.particle.mass, exact_forces(in.forces), in.dt);
  return compare_particle(
      "start_verlet keeps the particle and sets previous = p - v dt + a dt^2 / 2, so that the "
      "first Verlet step is the Taylor step",
      in, exact, got, position_tolerance(in), kRelative * largest(in.particle.velocity) + 1e-300);
}

Outcome verlet_step(const MotionCase& in, const Particle& got) {
  const oracle::State exact =
      oracle::verlet_step(state_of(in.particle), in.particle.mass, exact_forces(in.forces), in.dt);
  const double tol_p = position_tolerance(in);
  return compare_particle("a Verlet step: p' = 2 p - previous + a dt^2, previous' = p, v' = (p' - p) / dt", in, exact,
                          got, tol_p, tol_p / in.dt);
}

}  // namespace labkit::lab07::judge
