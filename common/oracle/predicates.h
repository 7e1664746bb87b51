// Exact signs and distances that many labs share.
#pragma once

#include "common/geometry.h"

namespace oracle {

using labkit::Plane;
using labkit::Segment;
using labkit::Triangle;
using labkit::Vec3;

// Exact sign of plane.value(x) = normal . x + offset: +1 on the side the normal
// points to, 0 on the plane, -1 behind it.
int side(const Plane& plane, const Vec3& x);

// Exact sign of det[b - a, c - a, d - a]: +1 when d is on the side that
// (b - a) x (c - a) points to.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c);
// Exactly zero area: its three vertices are collinear (or coincide).
bool is_degenerate(const Triangle& t);

// Exact comparisons of a distance with a tolerance: dist <= tolerance.
bool within(const Vec3& p, const Vec3& q, double tolerance);
bool within(const Vec3& p, const Segment& s, double tolerance);
bool within(const Vec3& p, const Triangle& t, double tolerance);
bool within(const Vec3& p, const Plane& plane, double tolerance);  // |value| <= tolerance * |normal|

// Distances, exact then rounded.
double distance(const Vec3& p, const Triangle& t);
double distance(const Vec3& p, const Segment& s);

}  // namespace oracle
