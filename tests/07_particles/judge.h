// Lab 07's checker beyond its queries (queries.h declares the queries, their generators
// and their verdicts): what the lab's generators, judges, tests and viewer scene share.
#pragma once

#include "07_particles/queries.h"
#include "common/generators/generators.h"
#include "common/harness/check.h"

#include <rapidcheck.h>
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
