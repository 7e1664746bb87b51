// Triangle against triangle (lab 03). Closed triangles: touching counts, coplanar ones
// intersect when they overlap in their plane, and a zero-area triangle (collinear or
// coincident vertices) never intersects anything.
#pragma once

#include "common/geometry.h"

namespace oracle {

using labkit::Triangle;

// Exact (CGAL's do_intersect, coplanar case included).
bool triangles_intersect(const Triangle& t0, const Triangle& t1);

// Could moving every vertex coordinate by at most `delta` change the answer?
// Conservative: false means certainly not; true means it might. Each vertex moves by at
// most eps = sqrt(3) delta, so each triangle by at most eps (Hausdorff), and:
//  - apart: the distance between them can shrink by at most 2 eps;
//  - intersecting: the penetration depth (the shortest translation that separates them,
//    zero for coplanar ones) can shrink by at most 2 eps, and a triangle whose smallest
//    height is below 2 eps can be flattened to zero area (then: no intersection);
//  - a zero-area triangle (never intersecting) can gain area; it is in doubt when its
//    segment or point comes within 2 eps of the other triangle.
// The lecture's interval method (lab 03, step 4), exact: where each triangle meets the
// other's plane, read on coordinate k of the line of the two planes, each end the exact
// crossing point of an edge rounded once. crossing: every vertex strictly off the other's
// plane and each triangle on both sides of it (otherwise the ends stay 0).
struct TriangleIntervals {
  bool crossing = false;
  double low0 = 0.0, high0 = 0.0;  // t0's segment in t1's plane
  double low1 = 0.0, high1 = 0.0;  // t1's segment in t0's plane
};
TriangleIntervals triangle_intervals(const Triangle& t0, const Triangle& t1, int k);
// D = n0 x n1 with n = (v1 - v0) x (v2 - v0): the direction of the planes' line, exact
// and rounded once.
labkit::Vec3 planes_line_direction(const Triangle& t0, const Triangle& t1);

bool triangle_pair_in_doubt(const Triangle& t0, const Triangle& t1, double delta);

}  // namespace oracle
