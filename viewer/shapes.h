// Shapes more than one scene draws, made of render.h's lines, triangles and points:
// meshes, boxes (and any eight corners numbered as Box::corner numbers them), circles and
// wire spheres, square patches of planes, and a segment with its ends named.
#pragma once

#include "viewer/render.h"

#include "common/geometry.h"

#include <array>

namespace viewer {

// A mesh moved by `pose`: filled in `c` with dark blue-grey edges, or (not filled) its
// edges in `c`. Meshes of more than 20,000 triangles are drawn without edges.
void draw_mesh(Renderer& r, const labkit::Mesh& mesh, Color c, bool filled = true,
               const labkit::RigidTransform& pose = labkit::RigidTransform::Identity());

// Eight corners numbered as Box::corner numbers them: bit k of i picks the high side
// along axis k, so an edge joins two corners whose numbers differ in one bit.
using Corners = std::array<labkit::Vec3, 8>;
Corners corners_of(const labkit::Box& b);
void draw_edges(Renderer& r, const Corners& p, Color c, float width);
void draw_faces(Renderer& r, const Corners& p, Color c);
inline void draw_box(Renderer& r, const labkit::Box& b, Color c, float width) {
  draw_edges(r, corners_of(b), c, width);
}

// A circle around `c` in the plane of the unit vectors e1, e2, as `sides` lines.
void draw_circle(Renderer& r, const labkit::Vec3& c, const labkit::Vec3& e1, const labkit::Vec3& e2, double radius,
                 Color col, float width, int sides = 48);
// A sphere as three great circles, across the columns of `axes` (a rotation).
void draw_sphere(Renderer& r, const labkit::Vec3& c, double radius, Color col, float width, int sides = 48,
                 const labkit::Mat3& axes = labkit::Mat3::Identity());

// A square `half` from its centre c to each side, along the unit vectors u and w, its
// corners in turn: c + half (u + w), (-u + w), (-u - w), (u - w).
using Square = std::array<labkit::Vec3, 4>;
Square square_around(const labkit::Vec3& c, const labkit::Vec3& u, const labkit::Vec3& w, double half);
void fill(Renderer& r, const Square& q, Color c);
void outline(Renderer& r, const Square& q, Color c, float width, bool dashed = false);

// The segment a -> b in the input colour, its ends as handles named "a" and "b".
void draw_segment(Renderer& r, const labkit::Segment& s);

}  // namespace viewer
