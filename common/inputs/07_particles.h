// Lab 07's inputs: each query's arguments as one struct, whose fields() let reports print
// it and replay tokens carry it (the answers' fields are in tests/07_particles.wire.h; the
// tokens of Forces, Material and Scene in tests/07_particles.judge.h), and at the end the
// table of the queries that take them.
#pragma once

#include "particles.h"

#include "common/harness/query.h"

#include "common/inputs/inputs.h"

#include <vector>

namespace labkit::lab07 {

struct EmitCase {
  Emitter emitter;
  int seed = 1;
  int count = 1;  // particles emitted, twice from the same seed
};
template <class V> void fields(EmitCase& c, V&& v) {
  v("emitter", c.emitter);
  v("seed", c.seed);
  v("count", c.count);
}

struct BirthsCase {
  Emitter emitter;  // its rate and owed
  double dt = 0.0;
  int steps = 1;
};
template <class V> void fields(BirthsCase& c, V&& v) {
  v("emitter", c.emitter);
  v("dt", c.dt);
  v("steps", c.steps);
}

struct AgeCase {
  std::vector<Particle> particles;
  double dt = 0.0;
};
template <class V> void fields(AgeCase& c, V&& v) {
  v("particles", c.particles);
  v("dt", c.dt);
}

struct MotionCase {
  Particle particle;
  Forces forces;
  double dt = 0.0;
};
template <class V> void fields(MotionCase& c, V&& v) {
  v("particle", c.particle);
  v("forces", c.forces);
  v("dt", c.dt);
}

struct LaunchCase {
  Vec3 from = Vec3::Zero();
  Vec3 target = Vec3::Zero();
  double speed = 0.0;
  Vec3 gravity = Vec3::Zero();
};
template <class V> void fields(LaunchCase& c, V&& v) {
  v("from", c.from);
  v("target", c.target);
  v("speed", c.speed);
  v("gravity", c.gravity);
}

struct SegmentScene {
  Segment segment;
  Scene scene;
};
template <class V> void fields(SegmentScene& c, V&& v) {
  v("segment", c.segment);
  v("scene", c.scene);
}

struct ImpulseCase {
  Vec3 velocity = Vec3::Zero();
  Vec3 object_velocity = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double mass = 1.0;
  Material material;
};
template <class V> void fields(ImpulseCase& c, V&& v) {
  v("velocity", c.velocity);
  v("object_velocity", c.object_velocity);
  v("normal", c.normal);
  v("mass", c.mass);
  v("material", c.material);
}

struct CollideCase {
  Segment step;
  Vec3 velocity = Vec3::Zero();
  double mass = 1.0;
  double dt = 1.0;
  Scene scene;
};
template <class V> void fields(CollideCase& c, V&& v) {
  v("step", c.step);
  v("velocity", c.velocity);
  v("mass", c.mass);
  v("dt", c.dt);
  v("scene", c.scene);
}

struct SettleCase {
  Vec3 x = Vec3::Zero();
  Scene scene;
  SurfaceHit last;
};
template <class V> void fields(SettleCase& c, V&& v) {
  v("x", c.x);
  v("scene", c.scene);
  v("last", c.last);
}

struct SystemCase {
  Emitter emitter;
  Scene scene;
  Forces forces;
  int verlet = 0;  // 0: Euler, 1: Verlet
  int seed = 1;
  double dt = 0.0;
  int steps = 1;
};
template <class V> void fields(SystemCase& c, V&& v) {
  v("emitter", c.emitter);
  v("scene", c.scene);
  v("forces", c.forces);
  v("verlet", c.verlet);
  v("seed", c.seed);
  v("dt", c.dt);
  v("steps", c.steps);
}

}  // namespace labkit::lab07

// ---- The queries -------------------------------------------------------------------------
// The name of each question the tests ask (a replay token's prefix) and the input it takes,
// by the step that asks it first. The tests, the viewer's scene and its presets read this
// table (common/harness/query.h): a query is added or renamed here and nowhere else.
#define LABKIT_LAB07_QUERIES(X)                        \
  /* step 1 */                                         \
  X(emit, "emit", EmitCase)                            \
  X(births, "births", BirthsCase)                      \
  X(age, "age", AgeCase)                               \
  /* step 2 */                                         \
  X(force, "force", MotionCase)                        \
  X(euler_step, "euler_step", MotionCase)              \
  X(verlet_step, "verlet_step", MotionCase)            \
  X(integrators, "integrators", MotionCase)            \
  /* step 3 */                                         \
  X(aim, "aim", LaunchCase)                            \
  X(exact_aim, "exact.aim", LaunchCase)                \
  /* step 4 */                                         \
  X(hit_plane, "hit_plane", SegmentScene)              \
  X(hit_triangle, "hit_triangle", SegmentTrianglePair) \
  X(first_hit, "first_hit", SegmentScene)              \
  X(exact_first_hit, "exact.first_hit", SegmentScene)  \
  /* step 5 */                                         \
  X(impulse, "impulse", ImpulseCase)                   \
  /* step 6 */                                         \
  X(collide, "collide", CollideCase)                   \
  /* step 7 */                                         \
  X(invariants, "invariants", CollideCase)             \
  X(settle, "settle", SettleCase)                      \
  X(system, "system", SystemCase)

namespace labkit::lab07::query {
LABKIT_LAB07_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB07_QUERIES)
}  // namespace labkit::lab07::query
