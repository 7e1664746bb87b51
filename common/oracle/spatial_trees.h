// Search structures (lab 06): which triangles a segment crosses, whether a triangle meets
// a box, where a point is with respect to a closed solid, which balls meet. All exact.
#pragma once

#include "common/geometry.h"

#include <array>
#include <vector>

namespace oracle {

using labkit::Aabb;
using labkit::Mesh;
using labkit::Segment;
using labkit::Sphere;
using labkit::Triangle;
using labkit::Vec3;

// The hit rule of the given watertight test (common/given/segment_triangle.h): the closed
// segment meets the closed triangle, the triangle has area, and the segment does not lie
// in the triangle's plane (a zero-length segment lies in every plane through its point).
bool segment_crosses_triangle(const Segment& s, const Triangle& t);

// Every triangle of the mesh the segment crosses by that rule, with the exact t of the
// crossing (rounded once), sorted by t, ties by index.
struct Crossing {
  int triangle = -1;
  double t = 0.0;
};
std::vector<Crossing> segment_mesh_crossings(const Segment& s, const Mesh& mesh);

// Does the closed triangle meet the closed box (even at one point)? False for a
// zero-area triangle.
bool triangle_meets_box(const Triangle& t, const Aabb& box);

// Where p is with respect to the solid a closed mesh bounds: -1 outside, 0 on its
// surface (on some closed triangle), +1 inside. The mesh must be closed (every edge
// shared by an even number of triangles, as around a solid); its winding does not
// matter. Decided by the parity of crossings along a ray, with the ray turned until it
// passes through no edge or vertex.
int point_in_solid(const Vec3& p, const Mesh& closed);

// Could moving every coordinate of x and of the triangle by at most delta change the side
// of the triangle's plane x is on? Conservative (false means certainly not): the plane
// moves at x by at most delta (1 + sum |lambda_i|), lambda the barycentric coordinates of
// x's projection, and x itself by delta; sqrt(3) for the three coordinates, and twice
// that for good measure. True for a zero-area triangle.
bool side_in_doubt(const Triangle& plane_of, const Vec3& x, double delta);

// Do the closed balls meet: |c0 - c1| <= r0 + r1?
bool balls_meet(const Sphere& a, const Sphere& b);
// Every pair (i, j), i < j, of balls that meet, in order: the O(n^2) brute force.
std::vector<std::array<int, 2>> meeting_pairs(const std::vector<Sphere>& spheres);

// Does the closed ball meet the closed box: is the distance from its centre to the box
// <= r? Exact (the squared distance, clamped axis by axis, in exact numbers).
bool ball_meets_box(const Sphere& ball, const Aabb& box);
// Every ball that meets the box, in increasing order: the brute force.
std::vector<int> balls_meeting_box(const std::vector<Sphere>& spheres, const Aabb& box);

}  // namespace oracle
