// Lab 07's verdicts: each judge compares one answer with the exact oracle, following the
// rules and tolerances of labs/07_particles/particles.h. The tests and the viewer both
// use them, so a red mark in the viewer and a failing case in `./labkit check` agree. The
// inputs are tests/07_particles/inputs.h, their random draws tests/07_particles/generators.h.
#pragma once

#include "07_particles/wire.h"

#include "07_particles/generators.h"
#include "07_particles/inputs.h"
#include "common/harness/check.h"

#include <string>
#include <vector>

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

// Step 1. `first` and `second`: the same count of particles emitted twice from Random(seed).
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
