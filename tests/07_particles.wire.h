// Lab 07 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer. A Random crosses as its state,
// and comes back advanced; a System (step 8) crosses whole, and comes back stepped.
#pragma once

#include "particles.h"

#include "common/protocol/wire.h"

#include <vector>

namespace labkit::lab07 {

template <class V> void fields(Particle& p, V&& v) {
  v("position", p.position);
  v("velocity", p.velocity);
  v("previous", p.previous);
  v("mass", p.mass);
  v("age", p.age);
  v("lifetime", p.lifetime);
  v("alive", p.alive);
  v("bounces", p.bounces);
}
template <class V> void fields(Emitter& e, V&& v) {
  v("position", e.position);
  v("half_extents", e.half_extents);
  v("direction", e.direction);
  v("cone", e.cone);
  v("speed", e.speed);
  v("speed_spread", e.speed_spread);
  v("lifetime", e.lifetime);
  v("lifetime_spread", e.lifetime_spread);
  v("mass", e.mass);
  v("rate", e.rate);
  v("owed", e.owed);
}
template <class V> void fields(Births& b, V&& v) {
  v("count", b.count);
  v("owed", b.owed);
}
template <class V> void fields(Shot& s, V&& v) {
  v("angle", s.angle);
  v("velocity", s.velocity);
  v("time", s.time);
}
template <class V> void fields(Aim& a, V&& v) {
  v("count", a.count);
  v("radicand", a.radicand);
  v("low", a.low);
  v("high", a.high);
}
template <class V> void fields(SurfaceHit& h, V&& v) {
  v("hit", h.hit);
  v("plane", h.plane);
  v("triangle", h.triangle);
  v("t", h.t);
  v("point", h.point);
  v("normal", h.normal);
}
template <class V> void fields(Impulse& i, V&& v) {
  v("closing", i.closing);
  v("v_close", i.v_close);
  v("normal_impulse", i.normal_impulse);
  v("friction", i.friction);
  v("velocity", i.velocity);
}
template <class V> void fields(Bounce& b, V&& v) {
  v("hit", b.hit);
  v("velocity", b.velocity);
  v("from", b.from);
}

// Coefficients (drag, restitution, friction) and plane normals are unit-free numbers:
// the ambiguity check moves them by 1e-9, not by 1e-9 S.
template <class V> void fields(Forces& f, V&& v) {
  v("gravity", f.gravity);
  v("drag", f.drag);
  v("air_drag", f.air_drag);
}
template <class V> void fields(Material& m, V&& v) {
  v("restitution", m.restitution);
  v("friction", m.friction);
}
template <class V> void fields(Scene& s, V&& v) {
  v("planes", s.planes);
  v("mesh", s.mesh);
  v("material", s.material);
  v("bounce_cap", s.bounce_cap);
  v("velocity", s.velocity);
  v("mesh_query", s.mesh_query);
}
template <class V> void fields(Collision& c, V&& v) {
  v("position", c.position);
  v("velocity", c.velocity);
  v("bounces", c.bounces);
  v("stopped", c.stopped);
  v("trace", c.trace);
}
template <class V> void fields(System& s, V&& v) {
  v("emitter", s.emitter);
  v("scene", s.scene);
  v("forces", s.forces);
  v("integrator", s.integrator);
  v("random", s.random);
  v("particles", s.particles);
  v("time", s.time);
}

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
  METHOD(System, step, (double))
// clang-format on
