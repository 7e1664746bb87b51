// Lab 07's verdicts: each judge compares one answer with the exact oracle, following the
// rules and tolerances of labs/07_particles/particles.h. The tests and the viewer both
// use them, so a red mark in the viewer and a failing case in `./labkit check` agree.
#pragma once

#include "07_particles.wire.h"

#include "common/generators/generators.h"
#include "common/generators/07_particles.h"
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

// ---- Inputs --------------------------------------------------------------------------

struct EmitCase {
  Emitter emitter;
  int seed = 1;
  int count = 1;  // particles emitted, twice from the same seed
};
template <class V> void fields(EmitCase& c, V&& v) { v("emitter", c.emitter); v("seed", c.seed); v("count", c.count); }

struct BirthsCase {
  Emitter emitter;  // its rate and owed
  double dt = 0.0;
  int steps = 1;
};
template <class V> void fields(BirthsCase& c, V&& v) { v("emitter", c.emitter); v("dt", c.dt); v("steps", c.steps); }

struct AgeCase {
  std::vector<Particle> particles;
  double dt = 0.0;
};
template <class V> void fields(AgeCase& c, V&& v) { v("particles", c.particles); v("dt", c.dt); }

struct MotionCase {
  Particle particle;
  Forces forces;
  double dt = 0.0;
};
template <class V> void fields(MotionCase& c, V&& v) { v("particle", c.particle); v("forces", c.forces); v("dt", c.dt); }

struct LaunchCase {
  Vec3 from = Vec3::Zero();
  Vec3 target = Vec3::Zero();
  double speed = 0.0;
  Vec3 gravity = Vec3::Zero();
};
template <class V> void fields(LaunchCase& c, V&& v) {
  v("from", c.from); v("target", c.target); v("speed", c.speed); v("gravity", c.gravity);
}

struct SegmentScene {
  Segment segment;
  Scene scene;
};
template <class V> void fields(SegmentScene& c, V&& v) { v("segment", c.segment); v("scene", c.scene); }

struct ImpulseCase {
  Vec3 velocity = Vec3::Zero();
  Vec3 object_velocity = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double mass = 1.0;
  Material material;
};
template <class V> void fields(ImpulseCase& c, V&& v) {
  v("velocity", c.velocity); v("object_velocity", c.object_velocity); v("normal", c.normal); v("mass", c.mass);
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
  v("step", c.step); v("velocity", c.velocity); v("mass", c.mass); v("dt", c.dt); v("scene", c.scene);
}

struct SettleCase {
  Vec3 x = Vec3::Zero();
  Scene scene;
  SurfaceHit last;
};
template <class V> void fields(SettleCase& c, V&& v) { v("x", c.x); v("scene", c.scene); v("last", c.last); }

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
  v("emitter", c.emitter); v("scene", c.scene); v("forces", c.forces); v("verlet", c.verlet); v("seed", c.seed);
  v("dt", c.dt); v("steps", c.steps);
}

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

// The judges' doubt tests, which the generators use to keep decisive families just
// outside the ambiguity band: a point's side of a plane (at input scale S), a segment
// against a two-sided triangle (at tol), and the |v_close| below which an impulse's
// "closing" is in doubt.
bool plane_in_doubt(const Plane& p, const Vec3& x, double scale);
bool sheet_in_doubt(const Segment& s, const Triangle& tri, double tol);
double closing_band(const ImpulseCase& in);

// The lab's generators.
rc::Gen<EmitCase> emit_case();
rc::Gen<BirthsCase> births_case();
rc::Gen<AgeCase> age_case();
rc::Gen<MotionCase> motion_case();
rc::Gen<LaunchCase> launch_case();
rc::Gen<LaunchCase> exact_launch_case();
rc::Gen<SegmentScene> plane_case();
rc::Gen<SegmentTrianglePair> sheet_case();  // lab 02's families, needles, just outside the band
rc::Gen<SegmentScene> segment_scene();
rc::Gen<SegmentScene> exact_segment_scene();
rc::Gen<ImpulseCase> impulse_case();
rc::Gen<CollideCase> collide_case(bool decided = true);  // step 7: false, exact degenerate steps kept
rc::Gen<SettleCase> settle_case();
rc::Gen<SystemCase> system_case();

}  // namespace judge
}  // namespace labkit::lab07
