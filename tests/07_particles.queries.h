// Lab 07's queries: the name of each question its tests ask (a replay token's prefix,
// `./labkit replay emit:...`) and the input it takes. The tests, the viewer's scene and
// its presets read this table (common/harness/query.h); a query is added or renamed here.
#pragma once

#include "common/harness/query.h"
#include "common/inputs/07_particles.h"

#define LABKIT_LAB07_QUERIES(X) \
  X(emit, "emit", EmitCase)                              \
  X(births, "births", BirthsCase)                        \
  X(age, "age", AgeCase)                                 \
  X(force, "force", MotionCase)                          \
  X(euler_step, "euler_step", MotionCase)                \
  X(verlet_step, "verlet_step", MotionCase)              \
  X(integrators, "integrators", MotionCase)              \
  X(aim, "aim", LaunchCase)                              \
  X(exact_aim, "exact.aim", LaunchCase)                  \
  X(hit_plane, "hit_plane", SegmentScene)                \
  X(hit_triangle, "hit_triangle", SegmentTrianglePair)   \
  X(first_hit, "first_hit", SegmentScene)                \
  X(exact_first_hit, "exact.first_hit", SegmentScene)    \
  X(impulse, "impulse", ImpulseCase)                     \
  X(collide, "collide", CollideCase)                     \
  X(invariants, "invariants", CollideCase)               \
  X(settle, "settle", SettleCase)                        \
  X(system, "system", SystemCase)                       

namespace labkit::lab07::query {
LABKIT_LAB07_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB07_QUERIES)
}  // namespace labkit::lab07::query
