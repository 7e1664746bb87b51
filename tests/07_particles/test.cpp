// Lab 07 tests. Each step: the hand-worked examples of handouts/07_particles.md, then
// random cases against the exact oracle (tests/07_particles/judge.cpp).
#include "07_particles/judge.h"
#include "particles.h"

#include "common/generators/meshes.h"

#include <cmath>
#include <stdexcept>
#include <string>

using namespace labkit;
using namespace labkit::lab07;
using check::Expect;
using check::Outcome;
using check::rejects;
using judge::Rules;

// The header's input domain (every coordinate, velocity and gravity component 0 or from
// 2^-130 to 2^130): shrinking a failing case stays in it.
const bool kDomain = [] {
  check::domain({check::Domain::Of::each, 0x1p-130, 0x1p130});
  return true;
}();

// What keeps each query's calls finite, in the header's words: a crash or a time-out in
// that query says it first (check::rule).
const bool kRules = [] {
  check::rule(query::collide,
              "a step applies at most bounce_cap impulses (at most kMaxBounceCap = 8); "
              "the next hit stops the particle: the loop runs at most bounce_cap + 1 times");
  check::rule(query::system, check::rule_of(query::collide));
  check::rule(query::births,
              "the count is rate * dt plus what earlier steps owed, rounded down: computed once, "
              "never counted up in a loop");
  return true;
}();

namespace {

constexpr double kDegree = M_PI / 180;

// Fails if the rule holds for no element, naming the first it fails for.
Outcome first_failure(std::initializer_list<Outcome> outcomes) {
  for (const Outcome& o : outcomes)
    if (o.verdict == Outcome::Verdict::fail) return o;
  return check::pass();
}

// ---- Runners: call the code under test, hand the answer to its judge ------------------

Outcome run_emit(const EmitCase& in) {
  std::vector<Particle> first, second;
  Random r1(std::uint64_t(in.seed)), r2(std::uint64_t(in.seed));
  for (int i = 0; i < in.count; ++i) first.push_back(answerer::emit(in.emitter, r1));
  for (int i = 0; i < in.count; ++i) second.push_back(answerer::emit(in.emitter, r2));
  return judge::emit(in, first, second);
}

std::vector<Births> run_births_steps(const BirthsCase& in) {
  std::vector<Births> got;
  Emitter e = in.emitter;
  for (int k = 0; k < in.steps; ++k) {
    got.push_back(answerer::births(e, in.dt));
    e.owed = got.back().owed;
  }
  return got;
}

Outcome run_births(const BirthsCase& in) { return judge::births(in, run_births_steps(in)); }
Outcome run_age(const AgeCase& in) { return judge::age(in, answerer::age(in.particles, in.dt)); }

Outcome run_motion(const MotionCase& in) {
  return first_failure({judge::force(in, answerer::force(in.particle, in.forces)),
                        judge::euler_step(in, answerer::euler_step(in.particle, in.forces, in.dt)),
                        judge::start_verlet(in, answerer::start_verlet(in.particle, in.forces, in.dt)),
                        judge::verlet_step(in, answerer::verlet_step(in.particle, in.forces, in.dt))});
}

Outcome run_aim(const LaunchCase& in) {
  return judge::aim(in, answerer::aim(in.from, in.target, in.speed, in.gravity));
}
Outcome run_exact_aim(const LaunchCase& in) {
  return judge::aim(in, answerer::aim(in.from, in.target, in.speed, in.gravity), Rules::exact);
}

Outcome run_first_hit(const SegmentScene& in) {
  return judge::first_hit(in, answerer::first_hit(in.segment, in.scene));
}
Outcome run_exact_first_hit(const SegmentScene& in) {
  return judge::first_hit(in, answerer::first_hit(in.segment, in.scene), Rules::exact);
}

Outcome run_impulse(const ImpulseCase& in) {
  return judge::impulse(in, answerer::impulse(in.velocity, in.object_velocity, in.normal, in.mass, in.material));
}

Collision run_collide_only(const CollideCase& in) {
  return answerer::collide(in.step, in.velocity, in.mass, in.dt, in.scene);
}
Outcome run_collide(const CollideCase& in) { return judge::collide(in, run_collide_only(in)); }
Outcome run_invariants(const CollideCase& in) { return judge::invariants(in, run_collide_only(in)); }

Outcome run_system(const SystemCase& in) {
  System system = system_of(in);
  for (int k = 0; k < in.steps; ++k) {
    answerer::step(system, in.dt);
    const Outcome o = judge::system_step(in, system, k);
    if (o.verdict == Outcome::Verdict::fail) return o;
  }
  return check::pass();
}

// ---- The handout's scenes ----------------------------------------------------------------

const Plane kFloor{{0, 0, 1}, 0};  // z = 0, solid below
const Triangle kFloorTriangle{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};

Scene floor_scene(double e, double mu, int cap = 4) {
  Scene s;
  s.planes = {kFloor};
  s.material = {e, mu};
  s.bounce_cap = cap;
  return s;
}

// The floor and a wall x = 3 facing -x: the corner of the bouncing examples.
Scene corner(int cap) {
  Scene s = floor_scene(1, 0, cap);
  s.planes.push_back(Plane{{-1, 0, 0}, 3});
  return s;
}

SegmentScene on_floor(Vec3 a, Vec3 b) {
  SegmentScene c;
  c.segment = {a, b};
  c.scene.planes = {kFloor};
  return c;
}

}  // namespace

// ---- Step 1 ----------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L07S1) ": worked examples", "[lab07][step1]") {
  const auto counts = [](std::vector<int> expected, std::vector<double> owed) {
    return [=](const BirthsCase& in) {
      const std::vector<Births> got = run_births_steps(in);
      Expect e("born = floor(owed + rate dt), and the fraction left over is carried to the next step in owed");
      for (std::size_t k = 0; k < expected.size() && k < got.size(); ++k) {
        e.equal("count " + std::to_string(k), got[k].count, expected[k]);
        e.near("owed " + std::to_string(k), got[k].owed, owed[k], 1e-12);
      }
      return e.outcome();
    };
  };
  BirthsCase ten{};
  ten.emitter.rate = 10;
  ten.dt = 0.25;
  ten.steps = 4;
  check::example(query::births, "10 per second, dt = 1/4: 2, 3, 2, 3", ten, counts({2, 3, 2, 3}, {0.5, 0, 0.5, 0}));
  BirthsCase three{};
  three.emitter.rate = 3;
  three.dt = 0.125;
  three.steps = 8;
  check::example(query::births, "3 per second, dt = 1/8: 3 in a second", three,
                 counts({0, 0, 1, 0, 0, 1, 0, 1}, {0.375, 0.75, 0.125, 0.5, 0.875, 0.25, 0.625, 0}));
  BirthsCase fine{};
  fine.emitter.rate = 10;
  fine.dt = 1.0 / 64;
  fine.steps = 64;
  check::example(query::births, "10 per second at 64 steps per second: 10 in a second", fine, [](const BirthsCase& in) {
    int total = 0;
    for (const Births& b : run_births_steps(in)) total += b.count;
    Expect e("the fraction of a particle owed each step (10/64) must be carried, or none is ever born");
    e.equal("births in 64 steps", total, 10);
    return e.outcome();
  });

  AgeCase ages{};
  ages.dt = 0.25;
  for (double a : {0.0, 0.25, 0.5}) {
    Particle p;
    p.position = Vec3(a, 0, 0);
    p.age = a;
    p.lifetime = a == 0.5 ? 1.0 : 0.5;
    ages.particles.push_back(p);
  }
  check::example(query::age, "ages 0, 1/4, 1/2 (lifetimes 1/2, 1/2, 1), dt 1/4: the second dies", ages,
                 [](const AgeCase& in) {
    const std::vector<Particle> got = answerer::age(in.particles, in.dt);
    Expect e("age + dt >= lifetime dies; the survivors keep their order");
    e.equal("survivors", int(got.size()), 2);
    if (got.size() == 2) {
      e.equal("first age", got[0].age, 0.25);
      e.equal("second age", got[1].age, 0.75);
      e.equal("order kept", got[1].position, Vec3(0.5, 0, 0));
    }
    return e.outcome().verdict == Outcome::Verdict::fail ? e.outcome() : judge::age(in, got);
  });

  EmitCase still{};
  still.emitter.position = Vec3(1, 2, 3);
  still.emitter.direction = Vec3(0, 0, 1);
  still.emitter.speed = 5;
  still.emitter.lifetime = 2;
  still.emitter.mass = 0.5;
  still.count = 3;
  check::example(query::emit, "no spread: at (1, 2, 3), velocity (0, 0, 5)", still, [](const EmitCase& in) {
    Random random(1);
    const Particle p = answerer::emit(in.emitter, random);
    Expect e("with no spread a particle is born at the emitter's position, speed along its direction");
    e.near("position", p.position, Vec3(1, 2, 3), 1e-12);
    e.near("velocity", p.velocity, Vec3(0, 0, 5), 1e-12);
    e.equal("lifetime", p.lifetime, 2.0);
    e.equal("mass", p.mass, 0.5);
    e.equal("age", p.age, 0.0);
    e.equal("alive", p.alive, true);
    return e.outcome().verdict == Outcome::Verdict::fail ? e.outcome() : run_emit(in);
  });

  // A cone at zero speed turns nothing: every particle is the same, and that is right.
  EmitCase resting{};
  resting.emitter.cone = 1.5;
  resting.emitter.lifetime = 0.125;
  resting.emitter.mass = 0.125;
  resting.count = 4;
  check::example(query::emit, "a wide cone at speed 0: four identical particles at rest", resting, run_emit);

  // A 60-degree cone: uniform in solid angle, the mean of cos(angle) is (1 + cos 60) / 2.
  EmitCase cone{};
  cone.emitter.position = Vec3(0, 0, 1);
  cone.emitter.half_extents = Vec3(1, 2, 0);
  cone.emitter.direction = Vec3(0, 0, 1);
  cone.emitter.cone = M_PI / 3;
  cone.emitter.speed = 10;
  cone.emitter.speed_spread = 2;
  cone.emitter.lifetime = 3;
  cone.emitter.lifetime_spread = 1;
  cone.count = 20000;
  check::example(query::emit, "a 60-degree cone, 20000 particles: spread as the ranges say", cone,
                 [](const EmitCase& in) {
    Random random(7);
    double cos_sum = 0, speed_sum = 0, life_sum = 0;
    Vec3 side = Vec3::Zero(), where = Vec3::Zero();
    for (int i = 0; i < in.count; ++i) {
      const Particle p = answerer::emit(in.emitter, random);
      const Vec3 d = p.velocity.normalized();
      cos_sum += d.z();
      side += Vec3(d.x(), d.y(), 0);
      speed_sum += p.velocity.norm();
      life_sum += p.lifetime;
      where += p.position;
    }
    const double n = in.count;
    Expect e("each attribute is drawn uniformly from its range");
    e.that("mean cos(angle to the axis)", std::abs(cos_sum / n - 0.75) <= 0.005, fmt(cos_sum / n), "0.75",
           "each attribute is drawn uniformly from its range: directions must be uniform in solid angle: cos(angle) "
           "uniform in [cos(cone), 1], mean 0.75 over a 60-degree "
           "cone; yours is " +
               fmt(cos_sum / n) + (cos_sum / n > 0.8 ? " (the angle itself drawn uniformly gives 0.827)" : ""));
    e.near("mean sideways direction", side / n, Vec3::Zero(), 0.01);
    e.near("mean speed", speed_sum / n, 10, 0.05);
    e.near("mean lifetime", life_sum / n, 3, 0.02);
    e.near("mean position", where / n, Vec3(0, 0, 1), 0.03);
    const Outcome stats = e.outcome();
    if (stats.verdict == Outcome::Verdict::fail) return stats;
    EmitCase some = in;
    some.count = 200;
    return run_emit(some);
  });
}

TEST_CASE(LABKIT_STEP(L07S1) ": random cases", "[lab07][step1][oracle]") {
  check::random_cases(query::emit, gen::emit_case(), run_emit);
  check::random_cases(query::births, gen::births_case(), run_births);
  check::random_cases(query::age, gen::age_case(), run_age);
}

// ---- Step 2 ----------------------------------------------------------------------------

namespace {

// The handout's thrown particle: from (0, 0, 10) at (2, 0, 0), g = 10 down, dt = 1/2.
MotionCase thrown() {
  MotionCase c;
  c.particle.position = Vec3(0, 0, 10);
  c.particle.velocity = Vec3(2, 0, 0);
  c.particle.previous = c.particle.position;
  c.forces.gravity = Vec3(0, 0, -10);
  c.dt = 0.5;
  return c;
}

}  // namespace

TEST_CASE(LABKIT_STEP(L07S2) ": worked examples", "[lab07][step2]") {
  check::example(query::euler_step, "two Euler steps of a thrown particle", thrown(), [](const MotionCase& in) {
    const Particle one = answerer::euler_step(in.particle, in.forces, in.dt);
    const Particle two = answerer::euler_step(one, in.forces, in.dt);
    Expect e(
        "explicit Euler takes both updates from the start of the step: p' = p + v dt with the old v (moving with "
        "the new v is semi-implicit Euler)");
    e.near("position after 1", one.position, Vec3(1, 0, 10), 1e-12);
    e.near("velocity after 1", one.velocity, Vec3(2, 0, -5), 1e-12);
    e.near("position after 2", two.position, Vec3(2, 0, 7.5), 1e-12);
    e.near("velocity after 2", two.velocity, Vec3(2, 0, -10), 1e-12);
    return e.outcome();
  });
  check::example(query::verlet_step, "two Verlet steps land on the exact parabola", thrown(), [](const MotionCase& in) {
    const Particle start = answerer::start_verlet(in.particle, in.forces, in.dt);
    const Particle one = answerer::verlet_step(start, in.forces, in.dt);
    const Particle two = answerer::verlet_step(one, in.forces, in.dt);
    Expect e(
        "start_verlet's previous = p - v dt + a dt^2 / 2 makes the first Verlet step the Taylor step "
        "p + v dt + a dt^2 / 2; then p' = 2 p - previous + a dt^2, previous' = p");
    e.near("previous at the start", start.previous, Vec3(-1, 0, 8.75), 1e-12);
    e.near("position after 1", one.position, Vec3(1, 0, 8.75), 1e-12);
    e.near("velocity after 1", one.velocity, Vec3(2, 0, -2.5), 1e-12);
    e.near("position after 2", two.position, Vec3(2, 0, 5), 1e-12);
    e.near("velocity after 2", two.velocity, Vec3(2, 0, -7.5), 1e-12);
    e.near("previous after 2", two.previous, Vec3(1, 0, 8.75), 1e-12);
    return e.outcome();
  });
  MotionCase dragged{};
  dragged.particle.mass = 2;
  dragged.particle.velocity = Vec3(4, 0, 0);
  dragged.forces = {Vec3(0, 0, -10), 0.5, 0.25};
  dragged.dt = 0.5;
  check::example(query::force, "gravity and both drags: (-2 - 4, 0, -20)", dragged, [](const MotionCase& in) {
    Expect e("F = m g - k1 v - k2 |v| v: gravity is an acceleration, both drags oppose the velocity");
    e.near("force", answerer::force(in.particle, in.forces), Vec3(-6, 0, -20), 1e-12);
    return e.outcome();
  });
  check::example(query::euler_step, "with drag: the velocity loses 6 / 2 * 1/2 along x", dragged,
                 [](const MotionCase& in) {
    const Particle one = answerer::euler_step(in.particle, in.forces, in.dt);
    Expect e("explicit Euler with drag: a = F / m at the start of the step, p' = p + v dt, v' = v + a dt");
    e.near("position", one.position, Vec3(2, 0, 0), 1e-12);
    e.near("velocity", one.velocity, Vec3(2.5, 0, -5), 1e-12);
    return e.outcome();
  });
}

TEST_CASE(LABKIT_STEP(L07S2) ": random cases", "[lab07][step2][oracle]") {
  check::random_cases(query::integrators, gen::motion_case(), run_motion);
}

// ---- Step 3 ----------------------------------------------------------------------------

namespace {

LaunchCase lecture_shot(Vec3 target) { return {Vec3::Zero(), target, 25, Vec3(0, 0, -9.81)}; }

auto expect_angles(int count, double radicand, double low, double high, double low_time, double high_time) {
  return [=](const LaunchCase& in) {
    const Aim got = answerer::aim(in.from, in.target, in.speed, in.gravity);
    // The likely mistake: the radicand of a target as far below (y's sign flipped).
    const Vec3 d = in.target - in.from;
    const double g = in.gravity.norm(), x = d.cross(in.gravity).norm() / g, y = -d.dot(in.gravity) / g;
    const double A = g * x * x / (2 * in.speed * in.speed), flipped = x * x - 4 * A * (A - y);
    const bool sign_flipped = y != 0 && std::abs(got.radicand - flipped) <= 1e-9 * std::abs(flipped);
    Expect e(sign_flipped ? "the height is y = -(d . g) / |g| because gravity points down: yours is the "
                            "answer for a target as far below"
                          : "tan(angle) = (v^2 +- sqrt(D)) / (g x) with D = v^4 + 2 v^2 (d . g) - |d x g|^2 "
                            "(the height y = -(d . g) / |g|: gravity points down)");
    e.equal("count", got.count, count);
    e.near("radicand", got.radicand, radicand, 1e-9 * std::abs(radicand) + 1e-12);
    if (count > 0) {
      e.near("low.angle", got.low.angle, low, 1e-9);
      e.near("high.angle", got.high.angle, high, 1e-9);
      e.near("low.time", got.low.time, low_time, 1e-9);
      e.near("high.time", got.high.time, high_time, 1e-9);
    }
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::aim(in, got, Rules::exact);
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L07S3) ": worked examples", "[lab07][step3]") {
  // The lecture's example: 25 m/s, a target 40 m away at the launch height.
  check::example(
      query::aim, "the lecture's example: 19.445 and 70.555 degrees (the lecture rounds to 19.4 and 70.6)",
      lecture_shot({40, 0, 0}),
      expect_angles(2, 969.30709504, 0.3393874833716999, 1.2314088434231967, 1.6967868333822653, 4.8061098626660765));
  check::example(query::aim, "the lecture's example, in degrees to 0.001: 19.445 and 70.555", lecture_shot({40, 0, 0}),
                 [](const LaunchCase& in) {
    const Aim got = answerer::aim(in.from, in.target, in.speed, in.gravity);
    Expect e("tan(angle) = (v^2 +- sqrt(D)) / (g x): the lecture's shot gives 19.445 and 70.555 degrees");
    e.near("low, degrees to 0.001", std::round(got.low.angle / kDegree * 1000) / 1000, 19.445, 1e-9);
    e.near("high, degrees to 0.001", std::round(got.high.angle / kDegree * 1000) / 1000, 70.555, 1e-9);
    e.near("radicand, to 0.01", std::round(got.radicand * 100) / 100, 969.31, 1e-9);
    return e.outcome();
  });
  check::example(
      query::aim, "a target 10 m up: 36.213 and 67.823 degrees", lecture_shot({40, 0, 10}),
      expect_angles(2, 467.03509504, 0.6320328874362006, 1.18374210248556, 1.9830740305387204, 4.238835098464936));
  check::example(query::aim, "70 m is out of reach", lecture_shot({70, 0, 0}),
                 expect_angles(0, -1015.20962816, 0, 0, 0, 0));
  // D = 10^4 - 10^2 10^2 = 0: one angle, 45 degrees.
  check::example(query::aim, "just in reach: one angle, 45 degrees",
                 LaunchCase{Vec3::Zero(), {10, 0, 0}, 10, {0, 0, -10}},
                 expect_angles(1, 0, M_PI / 4, M_PI / 4, std::sqrt(2.0), std::sqrt(2.0)));
  check::example(query::aim, "straight above: no angle to solve for", lecture_shot({0, 0, 5}),
                 expect_angles(0, 0, 0, 0, 0, 0));
}

TEST_CASE(LABKIT_STEP(L07S3) ": random cases", "[lab07][step3][oracle]") {
  check::random_cases(query::aim, gen::launch_case(), run_aim);
  check::random_cases(query::exact_aim, gen::exact_launch_case(), run_exact_aim);
}

// ---- Step 4 ----------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L07S4) ": worked examples", "[lab07][step4]") {
  // The judge first: its failure says the header's rule for this case.
  const auto plane_hit = [](double t, Vec3 point) {
    return [=](const SegmentScene& in) {
      const SurfaceHit got = answerer::hit_plane(in.segment, in.scene.planes[0]);
      const Outcome judged = judge::hit_plane(in, got, Rules::exact);
      if (judged.verdict == Outcome::Verdict::fail) return judged;
      Expect e("t = value(a) / (value(a) - value(b)), the point a + t (b - a), the normal n / |n|");
      e.near("t", got.t, t, 1e-12);
      e.near("point", got.point, point, 1e-12);
      e.near("normal", got.normal, in.scene.planes[0].normal.normalized(), 1e-12);
      return e.outcome();
    };
  };
  const auto plane_miss = [](const SegmentScene& in) {
    return judge::hit_plane(in, answerer::hit_plane(in.segment, in.scene.planes[0]), Rules::exact);
  };
  check::example(query::hit_plane, "falling through the floor at t = 3/4", on_floor({1, 1, 3}, {1, 1, -1}),
                 plane_hit(0.75, {1, 1, 0}));
  check::example(query::hit_plane, "rising from below: one-sided, no hit", on_floor({1, 1, -1}, {1, 1, 3}), plane_miss);
  check::example(query::hit_plane, "resting on the floor, pushed in: t = 0", on_floor({1, 1, 0}, {1, 1, -1}),
                 plane_hit(0, {1, 1, 0}));
  check::example(query::hit_plane, "ending exactly on the floor is not behind it", on_floor({1, 1, 3}, {1, 1, 0}),
                 plane_miss);
  SegmentScene shelf = on_floor({0, 0, 3}, {0, 0, 0});
  shelf.scene.planes = {Plane{{0, 0, 2}, -2}};  // z = 1, its normal of length 2
  check::example(query::hit_plane, "z = 1 written 2 z - 2 = 0: t = 2/3", shelf, plane_hit(2.0 / 3, {0, 0, 1}));
  // The header's rule for a: n . a + c computes to -1.5e-11 here, within its rounding
  // bound (1.7e-10): a is on the plane (exactly, in fact), and moving behind it hits at t = 0.
  SegmentScene resting = on_floor({-33791.999998051404, 16384.000000954293, 16384.00000055659},
                                  {-33791.99999423671, 16384.000000954293, 16384.00000055659});
  resting.scene.planes = {Plane{{-1, 2, 1}, -82944.00000051658}};
  check::example(query::hit_plane, "resting on a plane within value(a)'s rounding bound, moving behind: t = 0", resting,
                 [](const SegmentScene& in) {
    const SurfaceHit got = answerer::hit_plane(in.segment, in.scene.planes[0]);
    Expect e(
        "a computed value(a) within its rounding bound counts as 0 (the particle rests on "
        "the plane), so a step moving behind hits at t = 0");
    e.equal("hit", got.hit, true);
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::hit_plane(in, got, Rules::exact);
  });

  const auto triangle_hit = [](double t, Vec3 normal) {
    return [=](const SegmentTrianglePair& in) {
      const SurfaceHit got = answerer::hit_triangle(in.segment, in.triangle);
      Expect e("triangles are two-sided: hit from either side, the unit normal turned to the side a is on");
      e.equal("hit", got.hit, true);
      e.near("t", got.t, t, 1e-12);
      e.near("normal", got.normal, normal, 1e-12);
      const Outcome o = e.outcome();
      return o.verdict == Outcome::Verdict::fail ? o : judge::hit_triangle(in, got);
    };
  };
  check::example(query::hit_triangle, "from above: normal up",
                 SegmentTrianglePair{{{1, 1, 3}, {1, 1, -1}}, kFloorTriangle}, triangle_hit(0.75, {0, 0, 1}));
  check::example(query::hit_triangle, "from below: two-sided, the normal faces down",
                 SegmentTrianglePair{{{1, 1, -1}, {1, 1, 3}}, kFloorTriangle}, triangle_hit(0.25, {0, 0, -1}));
  check::example(query::hit_triangle, "starting on the triangle: leaving it, no hit",
                 SegmentTrianglePair{{{1, 1, 0}, {1, 1, -1}}, kFloorTriangle}, [](const SegmentTrianglePair& in) {
                   Expect e("a step starting exactly on a triangle's plane is leaving the sheet: no hit");
                   e.equal("hit", answerer::hit_triangle(in.segment, in.triangle).hit, false);
                   return e.outcome();
                 });

  SegmentScene floor_and_shelf;
  floor_and_shelf.segment = {{1, 3, 5}, {1, 3, -1}};
  floor_and_shelf.scene.planes = {kFloor};
  gen::add_square(floor_and_shelf.scene.mesh, 4, 2);
  check::example(query::first_hit, "the shelf (t = 1/2) before the floor (t = 5/6)", floor_and_shelf,
                 [](const SegmentScene& in) {
    const SurfaceHit got = answerer::first_hit(in.segment, in.scene);
    Expect e("the first hit is the one with the smallest t, and names its triangle (plane -1)");
    e.equal("hit", got.hit, true);
    e.equal("plane", got.plane, -1);
    e.equal("triangle", got.triangle, 1);
    e.near("t", got.t, 0.5, 1e-12);
    e.near("point", got.point, Vec3(1, 3, 2), 1e-12);
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::first_hit(in, got, Rules::exact);
  });
  SegmentScene tie;
  tie.segment = {{1, 3, 1}, {1, 3, -1}};
  tie.scene.planes = {kFloor};
  gen::add_square(tie.scene.mesh, 4, 0);
  check::example(query::first_hit, "a triangle lying on the floor: the tie goes to the plane", tie,
                 [](const SegmentScene& in) {
    const SurfaceHit got = answerer::first_hit(in.segment, in.scene);
    Expect e("on a tie in t, planes come before triangles (replace the best only when strictly nearer)");
    e.equal("hit", got.hit, true);
    e.equal("plane", got.plane, 0);
    e.equal("triangle", got.triangle, -1);
    e.near("t", got.t, 0.5, 1e-12);
    return e.outcome();
  });
  // Found by a secret-seed run: the segment passes a hair outside an edge of triangle 5
  // (in doubt, so hitting it is fine); its t is judged against the plane crossing.
  const SegmentScene edge = input_from_token<SegmentScene>(parse_token(
      "first_hit:384,3456,-512,1341.8301825301382,1747.3950400718986,-1676.8855876623131,3,1,0,0,-0,0,1,0,-0,0,0,1,-0,"
      "16,0,0,0,0,1024,0,0,2048,2048,0,3072,0,1024,0,0,1024,1024,0,1024,2048,-1024,1024,3072,-2048,2048,0,0,2048,1024,"
      "0,"
      "2048,2048,0,2048,3072,0,3072,0,0,3072,1024,0,3072,2048,0,3072,3072,0,18,0,4,5,0,5,1,1,5,6,1,6,2,2,6,7,2,7,3,4,8,"
      "9,4,9,5,5,9,10,5,10,6,6,10,11,6,11,7,8,12,13,8,13,9,9,13,14,9,14,10,10,14,15,10,15,11,0.5,0,4,0,0,0"));
  check::example(query::first_hit, "a hair outside an edge: a hit there is in doubt, either answer passes", edge,
                 run_first_hit);
}

TEST_CASE(LABKIT_STEP(L07S4) ": random cases", "[lab07][step4][oracle]") {
  check::random_cases(query::hit_plane, gen::plane_case(), [](const SegmentScene& in) {
    return judge::hit_plane(in, answerer::hit_plane(in.segment, in.scene.planes[0]));
  });
  check::random_cases(query::hit_triangle, gen::sheet_case(), [](const SegmentTrianglePair& in) {
    return judge::hit_triangle(in, answerer::hit_triangle(in.segment, in.triangle));
  });
  check::random_cases(query::first_hit, gen::segment_scene(), run_first_hit);
  check::random_cases(query::exact_first_hit, gen::exact_segment_scene(), run_exact_first_hit);
}

// ---- Step 5 ----------------------------------------------------------------------------

namespace {

auto expect_impulse(std::string rule, bool closing, Vec3 normal_impulse, Vec3 friction, Vec3 velocity) {
  return [=](const ImpulseCase& in) {
    const Impulse got = answerer::impulse(in.velocity, in.object_velocity, in.normal, in.mass, in.material);
    Expect e(rule);
    e.equal("closing", got.closing, closing);
    e.near("normal_impulse", got.normal_impulse, normal_impulse, 1e-12);
    e.near("friction", got.friction, friction, 1e-12);
    e.near("velocity", got.velocity, velocity, 1e-12);
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::impulse(in, got);
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L07S5) ": worked examples", "[lab07][step5]") {
  const Vec3 up(0, 0, 1);
  check::example(
      query::impulse, "e = 1/2, mu = 1/4: sliding slows", ImpulseCase{{3, 0, -4}, Vec3::Zero(), up, 2, {0.5, 0.25}},
      expect_impulse("j_n = -(1 + e) m v_close n; friction opposes the sliding v_t with min(mu |j_n|, m |v_t|)", true,
                     {0, 0, 12}, {-3, 0, 0}, {1.5, 0, 2}));
  check::example(
      query::impulse, "mu = 1: friction stops the sliding, never reverses it",
      ImpulseCase{{3, 0, -4}, Vec3::Zero(), up, 2, {0.5, 1}},
      expect_impulse("friction never reverses the sliding: its size is min(mu |j_n|, m |v_t|), at most what stops v_t",
                     true, {0, 0, 12}, {-6, 0, 0}, {0, 0, 2}));
  check::example(query::impulse, "e = 1, mu = 0: the speed is kept",
                 ImpulseCase{{3, 0, -4}, Vec3::Zero(), up, 1, {1, 0}},
                 expect_impulse("e = 1 turns v_close around at full size: j_n = -2 m v_close n", true, {0, 0, 8},
                                {0, 0, 0}, {3, 0, 4}));
  check::example(query::impulse, "a paddle rising at 2 meets a ball falling at 3: it leaves at 7",
                 ImpulseCase{{0, 0, -3}, {0, 0, 2}, up, 1, {1, 0}},
                 expect_impulse("only the relative velocity v - v_obj matters: v_close = (v - v_obj) . n", true,
                                {0, 0, 10}, {0, 0, 0}, {0, 0, 7}));
  check::example(
      query::impulse, "a floor falling faster than the ball: no impulse",
      ImpulseCase{{0, 0, -1}, {0, 0, -3}, up, 1, {1, 0}},
      expect_impulse("only the relative velocity v - v_obj matters: (v - v_obj) . n = 2 > 0, the particle is not "
                     "closing, and gets no impulse",
                     false, {0, 0, 0}, {0, 0, 0}, {0, 0, -1}));
}

TEST_CASE(LABKIT_STEP(L07S5) ": random cases", "[lab07][step5][oracle]") {
  check::random_cases(query::impulse, gen::impulse_case(), run_impulse);
}

// ---- Step 6 ----------------------------------------------------------------------------

namespace {

auto expect_collision(std::string rule, Vec3 position, Vec3 velocity, int bounces, bool stopped) {
  return [=](const CollideCase& in) {
    const Collision got = run_collide_only(in);
    Expect e(rule);
    e.near("position", got.position, position, 1e-9);
    e.near("velocity", got.velocity, velocity, 1e-9);
    e.equal("bounces", got.bounces, bounces);
    e.equal("stopped", got.stopped, stopped);
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::collide(in, got);
  };
}

CollideCase into_floor(double e, double mu) { return {{{0, 0, 1}, {2, 0, -1}}, {2, 0, -2}, 1, 1, floor_scene(e, mu)}; }
CollideCase into_corner(int cap) { return {{{0, 0, 1}, {4, 0, -1}}, {4, 0, -2}, 1, 1, corner(cap)}; }
// The floor rising at (0, 0, 2), at z = 0 at the end of a step of 1 s.
CollideCase rising_floor(Segment step, Vec3 velocity, double e) {
  CollideCase c{step, velocity, 1, 1, floor_scene(e, 0)};
  c.scene.velocity = Vec3(0, 0, 2);
  return c;
}

}  // namespace

TEST_CASE(LABKIT_STEP(L07S6) ": worked examples", "[lab07][step6]") {
  const std::string remaining =
      "after a hit at t the particle goes on from the hit point, with the new velocity, for the "
      "remaining time (1 - t) r only";
  const std::string cap =
      "the bounce cap: after bounce_cap impulses, the next hit stops the particle there, velocity zero";
  check::example(query::collide, "e = 1: from (1, 0, 0) half a step at (2, 0, 2)", into_floor(1, 0),
                 expect_collision(remaining, {2, 0, 1}, {2, 0, 2}, 1, false));
  check::example(query::collide, "e = 1/2: up at 1 instead of 2", into_floor(0.5, 0),
                 expect_collision(remaining, {2, 0, 0.5}, {2, 0, 1}, 1, false));
  check::example(query::collide, "floor, then wall: two bounces", into_corner(4),
                 expect_collision(remaining + ", and that piece is tested again", {2, 0, 1}, {-4, 0, 2}, 2, false));
  check::example(query::collide, "cap 1: stopped at the wall", into_corner(1),
                 expect_collision(cap, {3, 0, 0.5}, {0, 0, 0}, 1, true));
  check::example(query::collide, "cap 0: stopped at the floor", into_corner(0),
                 expect_collision(cap, {2, 0, 0}, {0, 0, 0}, 0, true));
  check::example(
      query::collide, "no hit: the step stands",
      CollideCase{{{0, 0, 3}, {1, 0, 2}}, {1, 0, -1}, 1, 1, floor_scene(1, 0)},
      expect_collision("a step that hits nothing ends at b with its velocity", {1, 0, 2}, {1, 0, -1}, 0, false));
  // A moving floor (the lecture's paddle): rising at u = (0, 0, 2), at z = 0 at the end of
  // the step, so at z = -2 when it starts. Seen from the floor the particle starts at
  // a' = a + u dt = (0, 0, 3) and moves with v - u = (1, 0, -4): it meets it at t = 3/4.
  const std::string relative =
      "a moving scene, in its own frame: the relative step a + u dt -> b finds the hit, the "
      "impulse takes the relative velocity v - u, and the particle goes on relative to the moving "
      "surfaces, from -> from + (v' - u) (1 - t) r";
  check::example(query::collide, "a rising floor (u = (0, 0, 2), e = 1/2): hit at t = 3/4, ends at (1, 0, 0.5)",
                 rising_floor({{0, 0, 1}, {1, 0, -1}}, {1, 0, -2}, 0.5),
                 expect_collision(relative, {1, 0, 0.5}, {1, 0, 4}, 1, false));
  check::example(query::collide, "a ball at rest struck by the rising floor (e = 1): it leaves at 2 u",
                 rising_floor({{0, 0, -0.5}, {0, 0, -0.5}}, {0, 0, 0}, 1),
                 expect_collision(relative, {0, 0, 0.5}, {0, 0, 4}, 1, false));
  Scene lift = floor_scene(0.5, 0, 0);
  lift.velocity = Vec3(0, 0, 2);
  check::example(
      query::collide, "cap 0 on the rising floor: stopped on it, moving with it",
      CollideCase{{{0, 0, 1}, {1, 0, -1}}, {1, 0, -2}, 1, 1, lift},
      expect_collision("the bounce cap on a moving scene: the particle stops at the hit, at rest on the surface, "
                       "so with the surface's velocity u",
                       {0.75, 0, 0}, {0, 0, 2}, 0, true));
}

TEST_CASE(LABKIT_STEP(L07S6) ": random cases", "[lab07][step6][oracle]") {
  check::random_cases(query::collide, gen::collide_case(), run_collide);
}

// ---- Step 7 ----------------------------------------------------------------------------

namespace {

Outcome run_settle(const SettleCase& in) { return judge::settle(in, answerer::settle(in.x, in.scene, in.last)); }

// collide's ends, judged by the invariants first: a `from` or an end behind its surface
// is named as such before the trace is compared.
Outcome run_settled_ends(const CollideCase& in) {
  const Collision got = run_collide_only(in);
  const Outcome o = judge::invariants(in, got);
  return o.verdict == Outcome::Verdict::fail ? o : judge::collide(in, got);
}

}  // namespace

TEST_CASE(LABKIT_STEP(L07S7) ": worked examples", "[lab07][step7]") {
  SettleCase on{};
  on.x = Vec3(1, 1, 0);
  on.scene = floor_scene(0, 0);
  on.last = {true, 0, -1, 0.5, Vec3(1, 1, 0), Vec3(0, 0, 1)};
  check::example(query::settle, "exactly on the floor just hit: lifted off it", on, run_settle);
  SettleCase behind = on;
  behind.x = Vec3(0.125, 0, -1.3877787807814457e-17);
  check::example(query::settle, "a hair below the floor: back above it", behind, run_settle);
  SettleCase sheet{};
  sheet.x = Vec3(1, 1, 0);
  gen::add_square(sheet.scene.mesh, 4, 0);
  sheet.last = {true, -1, 0, 0.5, Vec3(1, 1, 0), Vec3(0, 0, -1)};
  check::example(query::settle, "on a sheet hit from below: below it", sheet, run_settle);

  // A dead bounce (e = 0) along the floor: the hit point a + t (b - a) comes out
  // 1.4e-17 below the floor, and the particle would slide on there.
  const CollideCase dead{{{0, 0, 0.1}, {1, 0, -0.7}}, {1, 0, -0.8}, 1, 1, floor_scene(0, 0)};
  check::example(query::settled_ends, "a dead bounce slides on, above the floor", dead, run_settled_ends);
}

TEST_CASE(LABKIT_STEP(L07S7) ": one surface, random cases", "[lab07][step7][oracle]") {
  check::random_cases(query::settle, gen::settle_case(true), run_settle);
  // A dead slide along a tilted plane, whose end lands within rounding of it: an end
  // position not settled is caught at the default count.
  check::random_cases(query::settled_ends, gen::dead_slide(), run_settled_ends);
}

// ---- Step 8 ----------------------------------------------------------------------------

TEST_CASE(LABKIT_STEP(L07S8) ": worked examples", "[lab07][step8]") {
  SettleCase crease{};
  crease.x = Vec3(0, 1, 0);
  crease.scene = floor_scene(0, 0);
  crease.scene.planes.push_back(Plane{{1, 0, -2}, 0});  // x >= 2 z: a wedge 26.6 degrees wide
  crease.last = {true, 0, -1, 0.5, Vec3(1, 1, 0), Vec3(0, 0, 1)};
  check::example(query::crease_settle, "in an acute crease: off both planes at once", crease, run_settle);

  check::example(query::invariants, "e = 1: the speed is kept through two bounces", into_corner(4), run_invariants);
  // Found by a seed sweep: a starts exactly on plane 0, where n . a + c rounds to -1.5e-11.
  check::example(
      query::invariants, "resting exactly on a plane, n . a + c rounding below zero, then moving behind it",
      input_from_token<CollideCase>(parse_token(
          "invariants:-33791.999998051404,16384.000000954293,16384.00000055659,-33791.99999423671,"
          "16384.000000954293,16384.00000055659,6.103515625e-05,0,0,0.125,0.0625,3,-1,2,1,-82944.00000051658,"
          "-0,-0,-1,16384.00000055659,0,1,0,-16384.00000000062,0,0,0,0,0,0,0,0")),
      run_invariants);
  CollideCase crack{{{0.5, 0, 0.25}, {8.5, 0, -7.75}}, {8, 0, -8}, 1, 1, floor_scene(1, 0, kMaxBounceCap)};
  crack.scene.planes.push_back(Plane{{0, 0, -1}, 0.5});  // a ceiling at z = 1/2: a crack to bounce in
  check::example(query::invariants, "in a crack, up to the cap", crack, [](const CollideCase& in) {
    const Collision got = run_collide_only(in);
    Expect e("the bounce cap: after bounce_cap impulses, the next hit stops the particle");
    e.equal("stopped", got.stopped, true);
    const Outcome o = e.outcome();
    return first_failure({o, judge::invariants(in, got), judge::collide(in, got)});
  });
}

TEST_CASE(LABKIT_STEP(L07S8) ": the handling loop, worked examples", "[lab07][step8]") {
  // Ten per second, one each step of 1/10 s; each lives 4 steps (lifetime 0.35).
  SystemCase fountain{};
  fountain.emitter.position = Vec3(0, 0, 1);
  fountain.emitter.direction = Vec3(0, 0, 1);
  fountain.emitter.speed = 5;
  fountain.emitter.lifetime = 0.35;
  fountain.emitter.rate = 10;
  fountain.scene = floor_scene(0.5, 0.1);
  fountain.dt = 0.1;
  fountain.steps = 10;
  check::example(query::system, "a fountain after 10 steps: the last 3 born are alive", fountain,
                 [](const SystemCase& in) {
    System system = system_of(in);
    for (int k = 0; k < in.steps; ++k) answerer::step(system, in.dt);
    Expect e("one birth per step (rate dt = 1), dead at age >= lifetime 0.35, never behind the floor");
    e.equal("particles", int(system.particles.size()), 3);
    e.near("time", system.time, 1.0, 1e-12);
    for (const Particle& p : system.particles)
      e.that("above the floor", p.position.z() >= 0, fmt(p.position), "z >= 0",
             "one birth per step (rate dt = 1), dead at age >= lifetime 0.35, never behind the floor: a particle is "
             "below the floor");
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : run_system(in);
  });
  // One particle dropped onto the floor with Verlet: after the bounce, previous is
  // rewritten so that the next step goes on upward.
  SystemCase drop{};
  drop.scene = floor_scene(1, 0);
  drop.forces.gravity = Vec3::Zero();
  drop.verlet = 1;
  drop.dt = 0.5;
  check::example(query::system, "Verlet: a bounce rewrites previous", drop, [](const SystemCase& in) {
    System system = system_of(in);
    Particle p;
    p.position = Vec3(0, 0, 1);
    p.velocity = Vec3(0, 0, -4);
    p.lifetime = 10;
    system.particles = {answerer::start_verlet(p, system.forces, in.dt)};
    answerer::step(system, in.dt);  // from z = 1 toward z = -1: hits at t = 1/2, back up to z = 1
    Expect e(
        "Verlet keeps its velocity in position - previous: after a bounce, previous = position - velocity dt, or "
        "the next step goes on with the velocity from before the bounce");
    e.equal("particles", int(system.particles.size()), 1);
    if (system.particles.size() == 1) {
      const Particle& q = system.particles[0];
      e.near("position", q.position, Vec3(0, 0, 1), 1e-12);
      e.near("velocity", q.velocity, Vec3(0, 0, 4), 1e-12);
      e.near("previous", q.previous, Vec3(0, 0, -1), 1e-12);
      e.equal("bounces", q.bounces, 1);
    }
    answerer::step(system, in.dt);
    if (system.particles.size() == 1) e.near("position after 2", system.particles[0].position, Vec3(0, 0, 3), 1e-12);
    return e.outcome();
  });
}

TEST_CASE(LABKIT_STEP(L07S8) ": creases, invariants and the loop, random cases", "[lab07][step8][oracle]") {
  check::random_cases(query::crease_settle, gen::settle_case(false), run_settle);
  check::random_cases(query::invariants, gen::collide_case(false), run_invariants);
  check::random_cases(query::system, gen::system_case(), run_system);
}

// ---- Step 9 (extension) ----------------------------------------------------------------

namespace {

Outcome run_spring(const SpringCase& in) {
  return judge::spring_force(in, answerer::spring_force(in.a, in.b, in.spring));
}

SpringCase spring_case(Vec3 a, Vec3 va, Vec3 b, Vec3 vb, Spring spring) {
  SpringCase c;
  c.a.position = a, c.a.velocity = va, c.b.position = b, c.b.velocity = vb, c.spring = spring;
  return c;
}

auto expect_spring(std::string rule, Vec3 force) {
  return [=](const SpringCase& in) {
    const Vec3 got = answerer::spring_force(in.a, in.b, in.spring);
    Expect e(rule);
    e.near("force", got, force, 1e-12);
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::spring_force(in, got);
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L07S9) ": worked examples", "[lab07][step9]") {
  const Vec3 zero = Vec3::Zero();
  check::example(
      query::spring_force, "stretched by 2: it pulls a back toward b",
      spring_case({3, 0, 0}, zero, zero, zero, {2, 0, 1}),
      expect_spring("Hooke's law: F_a = -k_s (l - l_rest) u, the stretch beyond the rest length, with u = (a - b) / l "
                    "the unit vector from b to a (the force is on a)",
                    {-4, 0, 0}));
  check::example(
      query::spring_force, "compressed to half its rest length: it pushes a away from b",
      spring_case({0, 0.5, 0}, zero, zero, zero, {4, 0, 1}),
      expect_spring("the rest length: a spring shorter than l_rest pushes, k_s (l - l_rest) < 0", {0, 2, 0}));
  check::example(query::spring_force,
                 "at rest length, a moving away along the spring and sideways: only the first is damped",
                 spring_case({3, 0, 0}, {2, 5, 0}, zero, zero, {2, 0.5, 3}),
                 expect_spring("damping acts along the spring: k_d ((v_a - v_b) . u) u, the sideways 5 is not damped",
                               {-1, 0, 0}));
  check::example(query::spring_force, "both particles at one point: no direction, no force; half a unit apart, a push",
                 spring_case({1, 1, 1}, {1, 0, 0}, {1, 1, 1}, zero, {2, 0.5, 1}),
                 [](const SpringCase& in) {
    // The zero force alone would be earned by a file that does nothing: the same
    // spring, a moved half a unit along x, must push (-2 (0.5 - 1) - 0.5 * 1 = 0.5).
    SpringCase apart = in;
    apart.a.position.x() += 0.5;
    const Outcome moved = expect_spring(
        "zero length is the only special case: half a unit apart, a is pushed away, "
        "-(k_s (l - l_rest) + k_d ((v_a - v_b) . u)) u = (0.5, 0, 0)",
        {0.5, 0, 0})(apart);
    if (moved.verdict == Outcome::Verdict::fail) return moved;
    return expect_spring("zero length: a and b at the same point give the spring no direction, and the force is zero",
                         Vec3::Zero())(in);
  });
}

TEST_CASE(LABKIT_STEP(L07S9) ": random cases", "[lab07][step9][oracle]") {
  check::random_cases(query::spring_force, gen::spring_case(), run_spring);
}

// ---- Step 10 (extension) ---------------------------------------------------------------

namespace {

Outcome run_rigid(const RigidCase& in) {
  return judge::rigid_impulse(in, answerer::rigid_impulse(in.a, in.b, in.contact));
}

// The handout's example: a (mass 1, I^-1 = 1) centred at (-1, 0, 1) meets b (mass 1,
// I^-1 = 1) centred at (0, 0, -1) at the origin, normal +z (from b toward a), e = 1/2.
RigidCase lever(Vec3 va, Vec3 wa) {
  RigidCase c;
  c.a.centre = {-1, 0, 1}, c.a.velocity = va, c.a.angular_velocity = wa;
  c.b.centre = {0, 0, -1};
  c.contact = {Vec3::Zero(), Vec3::UnitZ(), 0.5};
  return c;
}

auto expect_rigid(std::string rule, bool closing, double j, Vec3 va, Vec3 wa, Vec3 vb, Vec3 wb) {
  return [=](const RigidCase& in) {
    const RigidImpulse got = answerer::rigid_impulse(in.a, in.b, in.contact);
    Expect e(rule);
    e.equal("closing", got.closing, closing);
    e.near("j", got.j, j, 1e-12);
    e.near("velocity_a", got.velocity_a, va, 1e-12);
    e.near("angular_velocity_a", got.angular_velocity_a, wa, 1e-12);
    e.near("velocity_b", got.velocity_b, vb, 1e-12);
    e.near("angular_velocity_b", got.angular_velocity_b, wb, 1e-12);
    const Outcome o = e.outcome();
    return o.verdict == Outcome::Verdict::fail ? o : judge::rigid_impulse(in, got);
  };
}

}  // namespace

TEST_CASE(LABKIT_STEP(L07S10) ": worked examples", "[lab07][step10]") {
  const Vec3 zero = Vec3::Zero();
  check::example(
      query::rigid_impulse, "a falls at 2 onto b off its centre: j = 1, and a starts to turn", lever({0, 0, -2}, zero),
      expect_rigid("j = -(1 + e) v_rel / (1/m_a + 1/m_b + n . ((I_a^-1 (r_a x n)) x r_a) + ...) = 3 / 3: the "
                   "angular terms add 1 to the denominator (a's lever arm); w_a' = w_a + I_a^-1 (r_a x J)",
                   true, 1, {0, 0, -1}, {0, -1, 0}, {0, 0, -1}, zero));
  check::example(query::rigid_impulse, "a still body spinning into b: its contact point closes at 2",
                 lever(zero, {0, 2, 0}),
                 expect_rigid("the contact point moves with v + w x r: w_a x r_a = (-2, 0, -2) closes at 2", true, 1,
                              {0, 0, 1}, {0, 1, 0}, {0, 0, -1}, zero));
  check::example(
      query::rigid_impulse, "a rising away from b: no impulse", lever({0, 0, 2}, zero),
      expect_rigid("v_rel = 2 > 0: the bodies separate, and nothing changes", false, 0, {0, 0, 2}, zero, zero, zero));
  check::example(query::rigid_impulse, "a sliding over b: v_rel = 0 is not closing", lever({3, 0, 0}, zero),
                 expect_rigid("closing only when v_rel < 0: sliding (v_rel = 0) gets no impulse", false, 0, {3, 0, 0},
                              zero, zero, zero));
}

TEST_CASE(LABKIT_STEP(L07S10) ": random cases", "[lab07][step10][oracle]") {
  check::random_cases(query::rigid_impulse, gen::rigid_case(), run_rigid);
}

// Step 8's creases stay in the header's domain at the settled point's scale (CI's sweep,
// seed 914): a step nearly along a plane crosses it far beyond its ends, and there two
// planes facing each other 3e-31 apart are a crack of 2^-98 S, which no push can
// certify, not the 2^-40 S the header promises. The generator draws no such case.
TEST_CASE("L07 step 8: a crack is measured at the scale of the point settled", "[lab07][contract]") {
  const std::vector<Plane> crack{{{1, 2, 2}, -3.160836977044716e-30}, {{-1, -2, -2}, 4.048305495418354e-30}};
  CHECK(gen::cracks_in_domain(crack, 1e-30));                        // at the step's own scale
  CHECK_FALSE(gen::cracks_in_domain(crack, 8.831770080097674e-17));  // at the point x
}

// ---- Preconditions (the header's "Preconditions"): the reference only ------------------
// Tagged [contract], in no step: students are not graded on invalid input. Each call must
// throw std::invalid_argument whose message names the argument.

TEST_CASE("L07 preconditions: invalid input is refused, naming the argument", "[lab07][contract]") {
  const double nan = std::nan(""), inf = HUGE_VAL;
  const Vec3 bad(nan, 0, 0);
  Random random(1);
  const auto emitter_with = [](auto change) {
    Emitter e;
    change(e);
    return e;
  };
  rejects("emitter.position", [&] { answerer::emit(emitter_with([&](Emitter& e) { e.position = bad; }), random); });
  rejects("emitter.half_extents",
          [&] { answerer::emit(emitter_with([](Emitter& e) { e.half_extents = Vec3(-1, 0, 0); }), random); });
  rejects("emitter.direction",
          [&] { answerer::emit(emitter_with([](Emitter& e) { e.direction = Vec3::Zero(); }), random); });
  rejects("emitter.cone", [&] { answerer::emit(emitter_with([](Emitter& e) { e.cone = 4; }), random); });
  rejects("emitter.speed", [&] { answerer::emit(emitter_with([](Emitter& e) { e.speed_spread = 2; }), random); });
  rejects("emitter.lifetime", [&] { answerer::emit(emitter_with([&](Emitter& e) { e.lifetime = nan; }), random); });
  rejects("emitter.mass", [&] { answerer::emit(emitter_with([](Emitter& e) { e.mass = 0; }), random); });
  rejects("emitter.mass", [&] { answerer::emit(emitter_with([&](Emitter& e) { e.mass = nan; }), random); });
  rejects("emitter.rate", [&] { answerer::births(emitter_with([](Emitter& e) { e.rate = -1; }), 0.1); });
  rejects("emitter.owed", [&] { answerer::births(emitter_with([](Emitter& e) { e.owed = 1; }), 0.1); });
  rejects("dt", [&] { answerer::births(Emitter{}, nan); });
  rejects("dt", [&] { answerer::age({Particle{}}, -1); });
  Particle nan_age;
  nan_age.age = nan;
  rejects("particles[0].age", [&] { answerer::age({nan_age}, 0.1); });

  // The issue's: a NaN or zero mass gave a NaN position.
  for (const double mass : {0.0, -1.0, nan}) {
    Particle p;
    p.mass = mass;
    rejects("p.mass", [&] { answerer::force(p, Forces{}); });
    rejects("p.mass", [&] { answerer::euler_step(p, Forces{}, 0.1); });
    rejects("p.mass", [&] { answerer::verlet_step(p, Forces{}, 0.1); });
  }
  Particle lost;
  lost.position = Vec3(inf, 0, 0);
  rejects("p.position", [&] { answerer::euler_step(lost, Forces{}, 0.1); });
  rejects("forces.gravity", [&] { answerer::euler_step(Particle{}, Forces{bad, 0, 0}, 0.1); });
  rejects("forces.drag", [&] { answerer::euler_step(Particle{}, Forces{Vec3::Zero(), -1, 0}, 0.1); });
  rejects("forces.air_drag", [&] { answerer::euler_step(Particle{}, Forces{Vec3::Zero(), 0, nan}, 0.1); });
  rejects("dt", [&] { answerer::start_verlet(Particle{}, Forces{}, 0); });
  rejects("dt", [&] { answerer::verlet_step(Particle{}, Forces{}, nan); });

  rejects("from", [&] { answerer::aim(bad, Vec3(1, 0, 0), 1, Vec3(0, 0, -1)); });
  rejects("target", [&] { answerer::aim(Vec3::Zero(), bad, 1, Vec3(0, 0, -1)); });
  rejects("speed", [&] { answerer::aim(Vec3::Zero(), Vec3(1, 0, 0), -1, Vec3(0, 0, -1)); });
  rejects("speed", [&] { answerer::aim(Vec3::Zero(), Vec3(1, 0, 0), nan, Vec3(0, 0, -1)); });
  rejects("gravity", [&] { answerer::aim(Vec3::Zero(), Vec3(1, 0, 0), 1, bad); });

  const Segment down{{0, 0, 1}, {0, 0, -1}};
  rejects("segment.a", [&] { answerer::hit_plane({bad, Vec3::Zero()}, kFloor); });
  rejects("segment.b", [&] { answerer::hit_plane({Vec3::Zero(), Vec3(0, 0, inf)}, kFloor); });
  rejects("plane.normal", [&] { answerer::hit_plane(down, Plane{bad, 0}); });
  rejects("plane.offset", [&] { answerer::hit_plane(down, Plane{Vec3::UnitZ(), nan}); });
  rejects("segment.a", [&] { answerer::hit_triangle({bad, Vec3::Zero()}, kFloorTriangle); });
  rejects("triangle.v1", [&] { answerer::hit_triangle(down, Triangle{Vec3::Zero(), bad, Vec3::UnitY()}); });
  Scene scene = floor_scene(0.5, 0);
  scene.planes.push_back(Plane{Vec3::UnitX(), nan});
  rejects("scene.planes[1].offset", [&] { answerer::first_hit(down, scene); });
  scene = floor_scene(0.5, 0);
  gen::add_square(scene.mesh, 4, 0);
  scene.mesh.vertices[2] = bad;
  rejects("scene.mesh.vertices[2]", [&] { answerer::first_hit(down, scene); });
  scene = floor_scene(0.5, 0);
  gen::add_square(scene.mesh, 4, 0);
  scene.mesh.triangles[1][2] = 4;
  rejects("scene.mesh.triangles[1]", [&] { answerer::first_hit(down, scene); });
  rejects("segment.a", [&] { answerer::first_hit({bad, Vec3::Zero()}, floor_scene(0.5, 0)); });

  const Vec3 up(0, 0, 1), v(3, 0, -4);
  rejects("velocity", [&] { answerer::impulse(bad, Vec3::Zero(), up, 1, {0.5, 0}); });
  rejects("object_velocity", [&] { answerer::impulse(v, bad, up, 1, {0.5, 0}); });
  rejects("normal", [&] { answerer::impulse(v, Vec3::Zero(), Vec3(0, 0, 2), 1, {0.5, 0}); });
  rejects("normal", [&] { answerer::impulse(v, Vec3::Zero(), Vec3::Zero(), 1, {0.5, 0}); });
  rejects("mass", [&] { answerer::impulse(v, Vec3::Zero(), up, 0, {0.5, 0}); });
  rejects("mass", [&] { answerer::impulse(v, Vec3::Zero(), up, nan, {0.5, 0}); });
  rejects("material.restitution", [&] { answerer::impulse(v, Vec3::Zero(), up, 1, {-0.5, 0}); });
  rejects("material.friction", [&] { answerer::impulse(v, Vec3::Zero(), up, 1, {0.5, nan}); });

  rejects("step.a", [&] { answerer::collide({bad, Vec3::Zero()}, v, 1, 1, floor_scene(1, 0)); });
  rejects("velocity", [&] { answerer::collide(down, bad, 1, 1, floor_scene(1, 0)); });
  rejects("mass", [&] { answerer::collide(down, v, 0, 1, floor_scene(1, 0)); });
  rejects("mass", [&] { answerer::collide(down, v, nan, 1, floor_scene(1, 0)); });
  rejects("dt", [&] { answerer::collide(down, v, 1, 0, floor_scene(1, 0)); });
  scene = floor_scene(1, 0);
  scene.velocity = bad;
  rejects("scene.velocity", [&] { answerer::collide(down, v, 1, 1, scene); });
  rejects("scene.bounce_cap", [&] { answerer::collide(down, v, 1, 1, floor_scene(1, 0, kMaxBounceCap + 1)); });
  rejects("scene.bounce_cap", [&] { answerer::collide(down, v, 1, 1, floor_scene(1, 0, -1)); });
  rejects("material.restitution", [&] { answerer::collide(down, v, 1, 1, floor_scene(nan, 0)); });

  const SurfaceHit floor_hit{true, 0, -1, 0.5, Vec3::Zero(), up};
  rejects("x", [&] { answerer::settle(bad, floor_scene(0, 0), floor_hit); });
  rejects("last", [&] {
    answerer::settle(Vec3::Zero(), floor_scene(0, 0), SurfaceHit{true, 3, -1, 0.5, Vec3::Zero(), up});
  });
  rejects("last.normal", [&] {
    answerer::settle(Vec3::Zero(), floor_scene(0, 0), SurfaceHit{true, 0, -1, 0.5, Vec3::Zero(), bad});
  });

  System system;
  rejects("dt", [&] { answerer::step(system, 0); });
  system.particles = {Particle{}};
  system.particles[0].mass = 0;
  rejects("particles[0].mass", [&] { answerer::step(system, 0.1); });
  system.particles[0].mass = 1;
  system.emitter.mass = nan;
  rejects("emitter.mass", [&] { answerer::step(system, 0.1); });
  system.emitter.mass = 1;
  system.scene.planes = {Plane{bad, 0}};
  rejects("scene.planes[0].normal", [&] { answerer::step(system, 0.1); });

  const Particle far{Vec3(1, 0, 0)};
  rejects("spring.stiffness", [&] { answerer::spring_force(far, Particle{}, Spring{-1, 0, 1}); });
  rejects("spring.damping", [&] { answerer::spring_force(far, Particle{}, Spring{1, nan, 1}); });
  rejects("spring.rest_length", [&] { answerer::spring_force(far, Particle{}, Spring{1, 0, -1}); });
  rejects("a.position", [&] { answerer::spring_force(Particle{bad}, Particle{}, Spring{}); });
  Particle massless;
  massless.mass = 0;
  rejects("b.mass", [&] { answerer::spring_force(far, massless, Spring{}); });

  RigidBody body;
  const Contact contact{Vec3::Zero(), up, 0.5};
  body.mass = 0;
  rejects("a.mass", [&] { answerer::rigid_impulse(body, RigidBody{}, contact); });
  body = RigidBody{};
  body.inverse_inertia(0, 1) = 1;  // not symmetric
  rejects("b.inverse_inertia", [&] { answerer::rigid_impulse(RigidBody{}, body, contact); });
  body = RigidBody{};
  body.angular_velocity = bad;
  rejects("a.angular_velocity", [&] { answerer::rigid_impulse(body, RigidBody{}, contact); });
  rejects("contact.normal", [&] {
    answerer::rigid_impulse(RigidBody{}, RigidBody{}, Contact{Vec3::Zero(), Vec3(0, 0, 2), 0.5});
  });
  rejects("contact.restitution", [&] {
    answerer::rigid_impulse(RigidBody{}, RigidBody{}, Contact{Vec3::Zero(), up, -0.5});
  });

  // Documented results, not errors: zero speed or gravity (count 0), a zero normal (no hit).
  CHECK(answerer::aim(Vec3::Zero(), Vec3(1, 0, 0), 0, Vec3(0, 0, -1)).count == 0);
  CHECK(answerer::aim(Vec3::Zero(), Vec3(1, 0, 0), 1, Vec3::Zero()).count == 0);
  CHECK(!answerer::hit_plane(down, Plane{Vec3::Zero(), 0}).hit);
}
