// Lab 07's checker: the generators that draw each query's input, then the verdicts.
//
// Lab 07's verdicts: each judge compares one answer with the exact oracle, following the
// rules and tolerances of labs/07_particles/particles.h. The tests and the viewer both
// use them, so a red mark in the viewer and a failing case in `./labkit check` agree. The
// inputs are in tests/07_particles/queries.h, their random draws below.
//
// The generators come first in this file (gen::). Seeded inputs for particles that bounce
// (lab 07): a particle's step as a segment against one-sided planes and a two-sided mesh.
// Same dyadic lattice as common/generators/generators.h: planes have small integer
// normals through lattice points, so a point "on the plane" or "on the line where two
// planes meet" is exactly there.
//
// Families on purpose: steps crossing a plane, starting exactly on it (resting, pushed in),
// ending exactly on it (touching), sliding along it, near-parallel; into the crease of two
// planes (right-angled and acute) and the corner of three; between two planes facing each
// other a hair apart (a crack: many bounces); against terrains, soups and closed octahedra
// through their shared edges and vertices, starting on a triangle's plane; a triangle lying
// in a plane (a tie); every scale from 2^-20 to 2^20, and far from the origin.
#pragma once

#include "07_particles/queries.h"
#include "common/generators/generators.h"
#include "common/harness/check.h"

#include <rapidcheck.h>
#include <string>
#include <vector>

namespace labkit {

// A particle's step, and the surfaces it may hit.
struct StepSurfaces {
  Segment step;
  std::vector<Plane> planes;  // one-sided: solid behind
  Mesh mesh;                  // two-sided
};

}  // namespace labkit

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

namespace labkit::lab07 {

// ---- Text and replay tokens for the lab's types -------------------------------------

void encode(codec::Writer& w, const Forces& f);
void decode(codec::Reader& r, Forces& f);
void encode(codec::Writer& w, const Material& m);
void decode(codec::Reader& r, Material& m);
void encode(codec::Writer& w, const Scene& s);
void decode(codec::Reader& r, Scene& s);
std::string describe(const Forces& f);
std::string describe(const Material& m);
std::string describe(const Scene& s);
std::string describe(const Collision& c);  // the bounces used, not the whole trace
using labkit::describe;

// A System set up from the case, before its first step.
System system_of(const SystemCase& c);

namespace judge {

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

// The judges' doubt tests, which the generators use to keep decisive families just
// outside the ambiguity band: a point's side of a plane (at input scale S), a segment
// against a two-sided triangle (at tol), and the |v_close| below which an impulse's
// "closing" is in doubt.
bool plane_in_doubt(const Plane& p, const Vec3& x, double scale);
bool sheet_in_doubt(const Segment& s, const Triangle& tri, double tol);
double closing_band(const ImpulseCase& in);
// Step 9: the spring's direction is in doubt (l <= 1e-9 S); step 10: |v_rel| below this
// band leaves "closing" in doubt.
bool spring_in_doubt(const SpringCase& in);
double rigid_closing_band(const RigidCase& in);

}  // namespace judge
}  // namespace labkit::lab07
