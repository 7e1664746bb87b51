// Seeded inputs for particles that bounce (lab 07): a particle's step as a segment
// against one-sided planes and a two-sided mesh. Same dyadic lattice as generators.h:
// planes have small integer normals through lattice points, so a point "on the plane" or
// "on the line where two planes meet" is exactly there.
//
// Families on purpose: steps crossing a plane, starting exactly on it (resting, pushed in),
// ending exactly on it (touching), sliding along it, near-parallel; into the crease of two
// planes (right-angled and acute) and the corner of three; between two planes facing each
// other a hair apart (a crack: many bounces); against terrains, soups and closed octahedra
// through their shared edges and vertices, starting on a triangle's plane; a triangle lying
// in a plane (a tie); every scale from 2^-20 to 2^20, and far from the origin.
#pragma once

#include "07_particles/inputs.h"
#include "common/generators/generators.h"

#include <rapidcheck.h>

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

// A plane through `point` with a non-zero integer normal, components in [-magnitude, magnitude].
rc::Gen<Plane> plane_through(const Vec3& point, int magnitude = 3);

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
