// Triangles clipped by half-spaces (lab 01).
#pragma once

#include "common/geometry.h"

#include <vector>

namespace oracle {

using labkit::Plane;
using labkit::Triangle;
using labkit::Vec3;

// The exact convex polygon triangle ∩ {x : plane.value(x) >= 0 for every plane},
// vertices rounded once, and its exact area (rounded once).
struct ClippedPolygon {
  std::vector<Vec3> vertices;
  double area = 0.0;
};
ClippedPolygon clip(const Triangle& t, const std::vector<Plane>& planes);

// The area of a ∩ b, both projected onto the plane of `reference` (the triangle they
// were cut from): the overlap of two pieces of one clipped triangle.
double overlap_area(const Triangle& a, const Triangle& b, const Triangle& reference);

// Exact: plane.value(x) >= -tolerance * |normal| for every plane.
bool inside_all(const Vec3& x, const std::vector<Plane>& planes, double tolerance);

}  // namespace oracle
