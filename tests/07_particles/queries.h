// Lab 07's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), and the table of the queries (last). Both processes include it.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too. A Random crosses as its state, and comes back advanced; a System
// (step 8) crosses whole, and comes back stepped.
#pragma once

#include "particles.h"

#include "common/fields.h"
#include "common/harness/query.h"
#include "common/inputs/inputs.h"
#include "common/protocol/calls.h"
#include "common/protocol/wire.h"

#include <vector>

namespace labkit::lab07 {

LABKIT_FIELDS(Particle, position, velocity, previous, mass, age, lifetime, alive, bounces)
LABKIT_FIELDS(Emitter, position, half_extents, direction, cone, speed, speed_spread, lifetime, lifetime_spread, mass,
              rate, owed)
LABKIT_FIELDS(Births, count, owed)
LABKIT_FIELDS(Shot, angle, velocity, time)
LABKIT_FIELDS(Aim, count, radicand, low, high)
LABKIT_FIELDS(SurfaceHit, hit, plane, triangle, t, point, normal)
LABKIT_FIELDS(Impulse, closing, v_close, normal_impulse, friction, velocity)
LABKIT_FIELDS(Bounce, hit, velocity, from)

// Coefficients (drag, restitution, friction) and plane normals are unit-free numbers:
// the ambiguity check moves them by 1e-9, not by 1e-9 S.
LABKIT_FIELDS(Forces, gravity, drag, air_drag)
LABKIT_FIELDS(Material, restitution, friction)
LABKIT_FIELDS(Scene, planes, mesh, material, bounce_cap, velocity, mesh_query)
LABKIT_FIELDS(Collision, position, velocity, bounces, stopped, trace)
LABKIT_FIELDS(System, emitter, scene, forces, integrator, random, particles, time)
LABKIT_FIELDS(Spring, stiffness, damping, rest_length)
LABKIT_FIELDS(RigidBody, centre, velocity, angular_velocity, mass, inverse_inertia)
LABKIT_FIELDS(Contact, point, normal, restitution)
LABKIT_FIELDS(RigidImpulse, closing, v_rel, j, velocity_a, angular_velocity_a, velocity_b, angular_velocity_b)

using Particles = std::vector<Particle>;
using MeshQuery = std::function<SurfaceHit(const Segment&, const Mesh&)>;

}  // namespace labkit::lab07

template <> struct labkit::wire::Codec<labkit::lab07::Random> {
  static void put(Writer& w, const lab07::Random& random) { wire::put(w, random.state()); }
  static void get(Reader& r, lab07::Random& random) {
    std::uint64_t state = 0;
    wire::get(r, state);
    random = lab07::Random(state);
  }
};

// Scene::mesh_query is the viewer's (a k-d tree); the tests never set it.
template <> struct labkit::wire::Codec<labkit::lab07::MeshQuery> {
  static void put(Writer&, const lab07::MeshQuery& query) {
    if (query) throw Error("Scene::mesh_query cannot be sent to the answerer (the tests never set it)");
  }
  static void get(Reader&, lab07::MeshQuery& query) { query = nullptr; }
};

// clang-format off
#define LABKIT_LAB07_CALLS(CALL, METHOD)                                                                \
  CALL(Particle, emit, (const Emitter&, Random&))                                                       \
  CALL(Births, births, (const Emitter&, double))                                                        \
  CALL(Particles, age, (Particles, double))                                                             \
  CALL(Vec3, force, (const Particle&, const Forces&))                                                   \
  CALL(Particle, euler_step, (const Particle&, const Forces&, double))                                  \
  CALL(Particle, start_verlet, (const Particle&, const Forces&, double))                                \
  CALL(Particle, verlet_step, (const Particle&, const Forces&, double))                                 \
  CALL(Aim, aim, (const Vec3&, const Vec3&, double, const Vec3&))                                       \
  CALL(SurfaceHit, hit_plane, (const Segment&, const Plane&))                                           \
  CALL(SurfaceHit, hit_triangle, (const Segment&, const Triangle&))                                     \
  CALL(SurfaceHit, first_hit, (const Segment&, const Scene&))                                           \
  CALL(Impulse, impulse, (const Vec3&, const Vec3&, const Vec3&, double, const Material&))              \
  CALL(Collision, collide, (const Segment&, const Vec3&, double, double, const Scene&))                 \
  CALL(Vec3, settle, (const Vec3&, const Scene&, const SurfaceHit&))                                    \
  METHOD(System, step, (double))                                                                       \
  CALL(Vec3, spring_force, (const Particle&, const Particle&, const Spring&))                             \
  CALL(RigidImpulse, rigid_impulse, (const RigidBody&, const RigidBody&, const Contact&))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab07, LABKIT_LAB07_CALLS)

// ---- The inputs ------------------------------------------------------------------------
// Lab 07's inputs: each query's arguments as one struct, whose fields() let reports print
// it and replay tokens carry it (the answers' fields are in above; the
// tokens of Forces, Material and Scene in tests/07_particles/judge.h), and at the end the
// table of the queries that take them.
namespace labkit::lab07 {

struct EmitCase {
  Emitter emitter;
  int seed = 1;
  int count = 1;  // particles emitted, twice from the same seed
};
LABKIT_FIELDS(EmitCase, emitter, seed, count)

struct BirthsCase {
  Emitter emitter;  // its rate and owed
  double dt = 0.0;
  int steps = 1;
};
LABKIT_FIELDS(BirthsCase, emitter, dt, steps)

struct AgeCase {
  std::vector<Particle> particles;
  double dt = 0.0;
};
LABKIT_FIELDS(AgeCase, particles, dt)

struct MotionCase {
  Particle particle;
  Forces forces;
  double dt = 0.0;
};
LABKIT_FIELDS(MotionCase, particle, forces, dt)

struct LaunchCase {
  Vec3 from = Vec3::Zero();
  Vec3 target = Vec3::Zero();
  double speed = 0.0;
  Vec3 gravity = Vec3::Zero();
};
LABKIT_FIELDS(LaunchCase, from, target, speed, gravity)

struct SegmentScene {
  Segment segment;
  Scene scene;
};
LABKIT_FIELDS(SegmentScene, segment, scene)

struct ImpulseCase {
  Vec3 velocity = Vec3::Zero();
  Vec3 object_velocity = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double mass = 1.0;
  Material material;
};
LABKIT_FIELDS(ImpulseCase, velocity, object_velocity, normal, mass, material)

struct CollideCase {
  Segment step;
  Vec3 velocity = Vec3::Zero();
  double mass = 1.0;
  double dt = 1.0;
  Scene scene;
};
LABKIT_FIELDS(CollideCase, step, velocity, mass, dt, scene)

struct SettleCase {
  Vec3 x = Vec3::Zero();
  Scene scene;
  SurfaceHit last;
};
LABKIT_FIELDS(SettleCase, x, scene, last)

struct SystemCase {
  Emitter emitter;
  Scene scene;
  Forces forces;
  int verlet = 0;  // 0: Euler, 1: Verlet
  int seed = 1;
  double dt = 0.0;
  int steps = 1;
};
LABKIT_FIELDS(SystemCase, emitter, scene, forces, verlet, seed, dt, steps)

struct SpringCase {
  Particle a;
  Particle b;
  Spring spring;
};
LABKIT_FIELDS(SpringCase, a, b, spring)

struct RigidCase {
  RigidBody a;
  RigidBody b;
  Contact contact;
};
LABKIT_FIELDS(RigidCase, a, b, contact)

}  // namespace labkit::lab07

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB07_QUERIES(X, X_IN)                                                                               \
  /* step 1 */ X(emit, EmitCase) X(births, BirthsCase) X(age, AgeCase)                                              \
  /* step 2 */ X(force, MotionCase) X(euler_step, MotionCase) X(verlet_step, MotionCase) X(integrators, MotionCase) \
  /* step 3 */ X(aim, LaunchCase) X_IN(exact, aim, LaunchCase)                                                      \
  /* step 4 */ X(hit_plane, SegmentScene) X(hit_triangle, SegmentTrianglePair) X(first_hit, SegmentScene)           \
               X_IN(exact, first_hit, SegmentScene)                                                                 \
  /* step 5 */ X(impulse, ImpulseCase)                                                                              \
  /* step 6 */ X(collide, CollideCase)                                                                              \
  /* step 7 */ X(settle, SettleCase) X(settled_ends, CollideCase)                                                   \
  /* step 8 */ X_IN(crease, settle, SettleCase) X(invariants, CollideCase) X(system, SystemCase)                   \
  /* step 9 */ X(spring_force, SpringCase)                                                                          \
  /* step 10 */ X(rigid_impulse, RigidCase)
// clang-format on

namespace labkit::lab07::query {
LABKIT_QUERIES(LABKIT_LAB07_QUERIES)
}  // namespace labkit::lab07::query
