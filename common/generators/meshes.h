// Meshes and sphere sets for the labs with search structures (06 spatial trees, 07
// particles) and for their benchmarks.
//
//  - Plain builders of adjustable size: a UV sphere, a torus, a terrain and a soup of
//    small random triangles, from a few dozen triangles to millions, the same for a
//    given seed on every machine (their random numbers come from splitmix64, not from
//    <random>'s distributions, whose output the standard leaves to each library).
//  - Closed lattice solids (boxes, octahedra, unions of unit cubes): every coordinate an
//    integer times a power of two, so that planes through their faces pass exactly
//    through other vertices, and a careful double computation decides every sign.
//  - RapidCheck generators of small ones, at every scale and far from the origin
//    (random_meshes.cpp: built for the tests only; the viewer uses the two above).
//
// Closed meshes are wound outward: each triangle's normal (v1 - v0) x (v2 - v0) points
// out of the solid.
#pragma once

#include "common/geometry.h"

#include <rapidcheck.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace labkit::gen {

// ---- Builders of adjustable size ------------------------------------------------------

// A UV sphere of about `triangles` triangles (at least 8): closed, convex, outward.
Mesh sphere_mesh(int triangles, const Vec3& center = Vec3::Zero(), double radius = 1.0);
// A torus around the z axis of about `triangles` triangles (at least 18): closed, not convex.
Mesh torus_mesh(int triangles, const Vec3& center = Vec3::Zero(), double major = 1.0, double minor = 0.35);
// A height field over [0, 1]^2, heights within 0.25 of zero: about `triangles` triangles.
Mesh terrain_mesh(int triangles, std::uint64_t seed);
// The height field z = height(x, y) over [x0, x1] x [y0, y1] on an n x n grid of squares,
// two triangles each (2 n^2), normals up; vertex (i, j) is number i (n + 1) + j, at
// x = x0 + (x1 - x0) i / n, y = y0 + (y1 - y0) j / n. Every terrain here is one.
Mesh height_field(int n, double x0, double x1, double y0, double y1,
                  const std::function<double(double, double)>& height);
// The 2 n^2 triangles of that grid, for (n + 1)^2 vertices numbered i (n + 1) + j: square
// (i, j) split along its diagonal from vertex (i, j) to (i + 1, j + 1).
std::vector<std::array<int, 3>> grid_triangles(int n);
// Adds the square [0, side]^2 at height z, as two triangles with normals up (+z).
void add_square(Mesh& mesh, double side, double z);
// `triangles` small triangles at random places in [0, 1]^3, edges about 2 / triangles^(1/3).
Mesh soup_mesh(int triangles, std::uint64_t seed);

enum class MeshKind { sphere, torus, terrain, soup };
const char* name_of(MeshKind kind);
Mesh mesh_of_kind(MeshKind kind, int triangles, std::uint64_t seed);

// ---- Closed lattice solids ---------------------------------------------------------------

// The 12 triangles of an axis-aligned box's surface.
Mesh box_mesh(const Aabb& box);
// The surface of a union of unit cubes: cube (i, j, k) is origin + scale [i, i+1] x [j, j+1] x [k, k+1].
// Each square face between a filled and an empty cube becomes two triangles. Cubes that
// touch only along an edge make that edge shared by four triangles: still a closed
// surface around a well-defined solid.
Mesh voxel_mesh(const std::vector<std::array<int, 3>>& cubes, const Vec3& origin, double scale);

// ---- RapidCheck generators ---------------------------------------------------------------

// Closed solids: lattice boxes, octahedra and unions of cubes, and coarse spheres and tori
// (whose vertices are rounded sines), at every scale, sometimes far from the origin.
rc::Gen<Mesh> closed_mesh();
// Only the lattice solids, on integers |x| <= 1024 times a power of two: exact input.
rc::Gen<Mesh> exact_closed_mesh();
// Anything a tree is built over: soups (with zero-area triangles), terrains, the closed
// solids above, piles of coincident triangles.
rc::Gen<Mesh> any_mesh();
// Lattice meshes with faces in coordinate planes (boxes, unions of cubes, flat
// terrains): planes through their vertices cut along their faces.
rc::Gen<Mesh> exact_mesh();

// A point in, on or near the mesh: a vertex, a point of a face, a point a hair off a
// face, or any point of its box (slightly enlarged). `exact`: lattice points and points
// exactly on faces only.
rc::Gen<Vec3> point_near(const Mesh& mesh, bool exact);
// A segment at the mesh: through a point of a face, from above or along it, or between
// two points near it.
rc::Gen<Segment> segment_near(const Mesh& mesh);
// Exact segments at a lattice mesh: through vertices, along faces and coordinate
// planes, ending exactly on a face; on integers, with the largest |component| of
// b - a a power of two, so that the given watertight test decides them exactly.
rc::Gen<Segment> exact_segment_near(const Mesh& mesh);

// ---- Spheres ---------------------------------------------------------------------------

// Up to 60 spheres: spread out, clustered, on one plane (all the same x), chains that
// touch exactly, coincident centres, zero radii, one huge sphere among small ones.
rc::Gen<std::vector<Sphere>> sphere_set();
// The same families on integers (centres and radii): every touching pair touches exactly.
rc::Gen<std::vector<Sphere>> exact_sphere_set();
// n spheres with centres uniform in [0, side]^3 and radii uniform in [r_min, r_max].
std::vector<Sphere> spread_spheres(int n, double side, double r_min, double r_max, std::uint64_t seed);

}  // namespace labkit::gen
