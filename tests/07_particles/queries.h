// Lab 07's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), the table of the queries, and how each input is drawn and each answer
// judged (last): a new query is written here, then defined in generators*.cpp and
// judge*.cpp. Both processes include it; the answerer uses only its first part.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too. A Random crosses as its state, and comes back advanced; a System
// (step 8) crosses whole, and comes back stepped.
#pragma once

#include "particles.h"

#include "common/fields.h"
#include "common/harness/outcome.h"
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

// ---- How each input is drawn, and the verdicts -----------------------------------------
// Declared here, beside the queries they serve; defined in generators*.cpp (gen::) and
// judge*.cpp (judge::). RapidCheck is included where the generators are called.
namespace labkit {

// A particle's step, and the surfaces it may hit.
struct StepSurfaces {
  Segment step;
  std::vector<Plane> planes;  // one-sided: solid behind
  Mesh mesh;                  // two-sided
};

}  // namespace labkit

namespace rc {
template <typename T> class Gen;
}  // namespace rc

// Seeded inputs for particles that bounce (lab 07): a particle's step as a segment
// against one-sided planes and a two-sided mesh. Same dyadic lattice as
// common/generators/generators.h: planes have small integer normals through lattice
// points, so a point "on the plane" or "on the line where two planes meet" is exactly
// there.
//
// Families on purpose: steps crossing a plane, starting exactly on it (resting, pushed
// in), ending exactly on it (touching), sliding along it, near-parallel; into the crease
// of two planes (right-angled and acute) and the corner of three; between two planes
// facing each other a hair apart (a crack: many bounces); against terrains, soups and
// closed octahedra through their shared edges and vertices, starting on a triangle's
// plane; a triangle lying in a plane (a tie); every scale from 2^-20 to 2^20, and far
// from the origin.
namespace labkit::gen {

// The scales lab 07 draws at: mostly those of scale(), and the ends of the header's input
// domain, 2^-100 and 2^100 (with 2^-60 and 2^60 between).
rc::Gen<double> particle_scale();

// A plane through `point` with a non-zero integer normal, components in [-magnitude,
// magnitude].
rc::Gen<Plane> plane_through(const Vec3& point, int magnitude = 3);

// The header's domain: two planes facing each other (a crack) are at least 2^-40 S apart,
// S the largest coordinate of the case's points (`scale`) and of each plane's point
// nearest the origin. Moved far away along the crack, a narrow one leaves no room that
// rounding can certify: such a case is not one the header promises.
bool cracks_in_domain(const std::vector<Plane>& planes, double scale);

// Steps and surfaces on the fine lattice (the random cases).
rc::Gen<StepSurfaces> step_surfaces();
// Exact degenerate cases on integer coordinates (multiples of 8, |x| <= 1024, times a
// power of two): planes crossed, touched, started on, slid along, creases and corners
// hit exactly; and steps starting exactly on a triangle's plane. No case here depends on
// a triangle's edges, which the watertight test decides in floating point.
rc::Gen<StepSurfaces> exact_step_surfaces();

// ---- Each query's cases (tests/07_particles/generators.cases.cpp) ----------------------
// Drawn over the header's whole input domain, and kept out of the judge's ambiguity band
// (lab07::judge::plane_in_doubt and the like) where a family is meant to be decisive.

rc::Gen<lab07::EmitCase> emit_case();
rc::Gen<lab07::BirthsCase> births_case();
rc::Gen<lab07::AgeCase> age_case();
rc::Gen<lab07::MotionCase> motion_case();
rc::Gen<lab07::LaunchCase> launch_case();
rc::Gen<lab07::LaunchCase> exact_launch_case();
rc::Gen<lab07::SegmentScene> plane_case();
rc::Gen<SegmentTrianglePair> sheet_case();  // lab 02's families, needles, just outside the band
rc::Gen<lab07::SegmentScene> segment_scene();
rc::Gen<lab07::SegmentScene> exact_segment_scene();
rc::Gen<lab07::ImpulseCase> impulse_case();
rc::Gen<lab07::CollideCase> collide_case(bool decided = true);
// Step 7: e = 0 off a tilted plane, sliding on to the end.
rc::Gen<lab07::CollideCase> dead_slide();
// A point computed onto a surface just hit, in a scene of that surface alone (step 7) or
// of a step's surfaces, where it may lie in a crease (step 8).
rc::Gen<lab07::SettleCase> settle_case(bool one_surface);
rc::Gen<lab07::SystemCase> system_case();

// ---- The extensions' cases (tests/07_particles/generators.bodies.cpp) ------------------
// Step 9: two particles on a spring: far apart, close together (down to 2^-20 of their
// coordinates), far from the origin, at rest length, circling (no stretching), with and
// without damping and rest length.
rc::Gen<lab07::SpringCase> spring_case();
// Step 10: two rigid bodies at a contact: general, diagonal and round inertia, hit
// through both centres (no turning), separating, sliding past (v_rel near 0, moved just
// outside the ambiguity band), a heavy body and a light one; lengths and speeds from
// 2^-40 to 2^40.
rc::Gen<lab07::RigidCase> rigid_case();

}  // namespace labkit::gen

// Lab 07's verdicts: each judge compares one answer with the exact oracle, following the
// rules and tolerances of labs/07_particles/particles.h. The tests and the viewer both
// use them, so a red mark in the viewer and a failing case in `./labkit check` agree. The
// inputs are in tests/07_particles/queries.h, their random draws below.
namespace labkit::lab07::judge {

using check::Outcome;
using check::Rules;  // random cases, or a robustness step's exact input

// Step 1. `first` and `second`: the same count of particles emitted twice from
// Random(seed).
Outcome emit(const EmitCase& in, const std::vector<Particle>& first, const std::vector<Particle>& second);
// got[k]: the births of step k, each step starting from the owed of the one before.
Outcome births(const BirthsCase& in, const std::vector<Births>& got);
Outcome age(const AgeCase& in, const std::vector<Particle>& got);

// Step 2.
Outcome force(const MotionCase& in, const Vec3& got);
Outcome euler_step(const MotionCase& in, const Particle& got);
Outcome start_verlet(const MotionCase& in, const Particle& got);
Outcome verlet_step(const MotionCase& in, const Particle& got);

// Step 3.
Outcome aim(const LaunchCase& in, const Aim& got, Rules rules = Rules::random);

// Step 4. hit_plane: the scene's first plane; hit_triangle: lab 02's pair.
Outcome hit_plane(const SegmentScene& in, const SurfaceHit& got, Rules rules = Rules::random);
Outcome hit_triangle(const SegmentTrianglePair& in, const SurfaceHit& got);
Outcome first_hit(const SegmentScene& in, const SurfaceHit& got, Rules rules = Rules::random);

// Step 5.
Outcome impulse(const ImpulseCase& in, const Impulse& got);

// Step 6: the trace, piece by piece: each hit is the first hit of its piece, each
// velocity the impulse's, each piece the remaining time from the last `from`.
Outcome collide(const CollideCase& in, const Collision& got);

// Step 7: the invariants of collide (exact), settle, and one step of a whole system.
Outcome invariants(const CollideCase& in, const Collision& got);
Outcome settle(const SettleCase& in, const Vec3& got);
// The system after its step number `step` (from 0): every particle alive, young enough,
// not behind any plane (exactly); the count equal to the births while none can have died.
Outcome system_step(const SystemCase& in, const System& after, int step);

// Step 9 (tests/07_particles/judge.bodies.cpp).
Outcome spring_force(const SpringCase& in, const Vec3& got);
// Step 10.
Outcome rigid_impulse(const RigidCase& in, const RigidImpulse& got);

}  // namespace labkit::lab07::judge
