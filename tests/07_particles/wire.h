// Lab 07 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer. A Random crosses as its state,
// and comes back advanced; a System (step 8) crosses whole, and comes back stepped.
#pragma once

#include "particles.h"

#include "common/fields.h"
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
