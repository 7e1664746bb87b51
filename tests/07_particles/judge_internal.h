// Inside lab 07's judge: what its files share (tests/07_particles/judge*.cpp): scales,
// and the surfaces' verdicts that steps 4 to 7 build on, defined in
// tests/07_particles/judge.surfaces.cpp. Not for the tests or the viewer.
#pragma once

#include "07_particles/judge.h"

#include "judging.h"

#include "common/oracle/oracle.h"

#include <cmath>
#include <initializer_list>
#include <string>

namespace labkit::lab07::judge {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;
using check::verdict;
using judging::kRelative;

inline const double kRoot3 = std::sqrt(3.0);

inline double largest(const Vec3& v) { return v.cwiseAbs().maxCoeff(); }
inline bool finite(const Vec3& v) { return v.allFinite(); }

// S of a scene and some points: its mesh vertices, each plane's point nearest the origin,
// and the points.
double scale_with(const Scene& scene, std::initializer_list<Vec3> points);

// Keeps the first failure of a sequence of checks, with a prefix saying where it was.
Outcome within(const std::string& where, const Outcome& o);

bool valid_plane(const Scene& scene, int i);
bool valid_triangle(const Scene& scene, int i);

// The first hit of a segment on a scene: lab 02's mesh verdict, with planes beside the
// triangles. `left`: the hit the piece s starts from (collide), or none.
Outcome first_hit_on(const Segment& s, const Scene& scene, const SurfaceHit& got, Rules rules,
                     const SurfaceHit* left = nullptr);

// The exact unit normal of the surface a hit names, facing where the hit's normal faces.
Vec3 exact_normal(const Scene& scene, const SurfaceHit& h);

}  // namespace labkit::lab07::judge
