// Triangles clipped by half-spaces, and frustum planes (lab 01).
#pragma once

#include "common/geometry.h"

#include <array>
#include <vector>

namespace oracle {

using labkit::Mat4;
using labkit::Plane;
using labkit::Triangle;
using labkit::Vec3;

// The convex polygon triangle ∩ {x : plane.value(x) >= 0 for every plane}, built as
// lab 01's one-plane rule builds it, plane after plane (Sutherland-Hodgman on closed
// half-spaces: keep corners with value >= 0, cut sides whose ends have strictly
// opposite signs), in exact arithmetic; corners and area rounded once.
struct ClippedPolygon {
  std::vector<Vec3> corners;  // in order, winding like the triangle
  double area = 0.0;
  bool has_area = false;  // exactly: area > 0
  // How many triangles the rule gives: m - 2 for m corners, none without area.
  int triangles() const { return has_area ? int(corners.size()) - 2 : 0; }
};
ClippedPolygon clip(const Triangle& t, const std::vector<Plane>& planes);

// Could a small change of the input change the corners clip(t, planes) has? The change:
// every vertex coordinate moves by at most delta, every plane moves by delta along its
// normal and turns by delta / S (S the largest |coordinate| of the triangle), which
// moves no vertex's signed distance to a plane by more than 5 delta; 8 delta is used.
// Conservative: false means certainly not; true means it might. Each sign the rule
// decides is an expression in the vertices' signed distances (degree 1 for a vertex,
// 2 for an edge's cut point, 3 for a point where two planes cross the triangle), and is
// in doubt when its size does not exceed how far those distances can move it.
bool clip_in_doubt(const Triangle& t, const std::vector<Plane>& planes, double delta);

// The area of a ∩ b, both projected onto the plane of `reference` (the triangle they
// were cut from): the overlap of two pieces of one clipped triangle. Pieces separated
// by one of their edges (the usual case) cost only exact orientation tests.
double overlap_area(const Triangle& a, const Triangle& b, const Triangle& reference);

// (normal . x + offset) / |normal|, exact, rounded once.
double signed_distance(const Plane& plane, const Vec3& x);

// Exact: plane.value(x) >= -tolerance * |normal| for every plane.
bool inside_all(const Vec3& x, const std::vector<Plane>& planes, double tolerance);

// The planes of the clip volume -w <= x, y, z <= w of the view-projection matrix m,
// in the order left, right, bottom, top, near, far: the rows r3 + r0, r3 - r0, r3 + r1,
// r3 - r1, r3 + r2, r3 - r2, exact, then divided by the length of their normal (exact,
// rounded once). A row combination with a zero normal gives a zero plane.
std::array<Plane, 6> frustum_planes(const Mat4& m);

}  // namespace oracle
