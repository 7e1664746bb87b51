// Lab 07's inputs: each query's arguments as one struct, whose fields() let reports print
// it and replay tokens carry it (the answers' fields are in tests/07_particles/wire.h; the
// tokens of Forces, Material and Scene in tests/07_particles/judge.h), and at the end the
// table of the queries that take them.
#pragma once

#include "particles.h"

#include "common/fields.h"
#include "common/harness/query.h"

#include "common/inputs/inputs.h"

#include <vector>

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
