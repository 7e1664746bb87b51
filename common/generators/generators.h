// Seeded random inputs for the oracle tests, as RapidCheck generators. Every generator
// draws from a dyadic lattice (integers plus 20-bit fractions, times a power of two),
// so that the exactly degenerate families really are exact in doubles: a point "on the
// edge" is on the edge, a "coplanar" segment is coplanar. Shrinking moves numbers toward
// zero, so a failing case shrinks toward small integers a person can check by hand.
//
// The families mix ordinary cases with the hard ones on purpose: crossing, through a
// vertex or an edge, touching, coplanar, collinear, near-parallel, near an edge,
// zero-length segments, zero-area triangles, far from the origin, and every scale from
// 2^-20 (about 1e-6) to 2^20 (about 1e6).
#pragma once

#include "common/geometry.h"
#include "common/harness/codec.h"
#include "common/inputs/inputs.h"

#include <rapidcheck.h>

namespace labkit::gen {

// An integer in [-magnitude, magnitude], uniformly, shrinking toward 0.
rc::Gen<int> integer(int magnitude);
// 2^k for k in {-20, -10, 0, 10, 20}: mostly 1, shrinking toward 1.
rc::Gen<double> scale();
// A small power of two 2^-k, k in [kmin, kmax], for near-degenerate offsets.
rc::Gen<double> tiny(int kmin, int kmax);

// Integer coordinates in [-magnitude, magnitude], times `scale`.
rc::Gen<Vec3> lattice_point(double scale, int magnitude = 16);
// A lattice point plus a 20-bit fraction in each coordinate, times `scale`.
rc::Gen<Vec3> point(double scale);
// A non-zero lattice vector, times `scale`.
rc::Gen<Vec3> direction(double scale, int magnitude = 8);
// A point (p v0 + q v1 + r v2) / 8 with p + q + r = 8, p, q, r >= 0: exactly in the
// closed triangle (interior, edge or vertex).
rc::Gen<Vec3> point_in_triangle(const Triangle& t);
// A triangle with non-zero area.
rc::Gen<Triangle> triangle(double scale);
// Exactly zero area: collinear or coincident vertices.
rc::Gen<Triangle> degenerate_triangle(double scale);

rc::Gen<SegmentTrianglePair> segment_triangle();
// Random segments and triangles at one scale, about half of them crossing: no
// deliberate degeneracy (for benchmarks of typical work).
rc::Gen<SegmentTrianglePair> typical_segment_triangle();
// Exactly degenerate cases only (through vertices and edges, touching, coplanar,
// zero length, zero area) on integer coordinates |x| <= 1024 times a power of two:
// the robustness steps' input, where the header's rules must hold exactly.
rc::Gen<SegmentTrianglePair> exact_segment_triangle();

// Small meshes: soups of random triangles, lattice terrains (many segments cross their
// shared edges and vertices exactly) and closed octahedra.
rc::Gen<Mesh> mesh(double scale);
rc::Gen<SegmentMeshPair> segment_mesh();
// Lattice terrains hit exactly through shared vertices and edges.
rc::Gen<SegmentMeshPair> exact_segment_mesh();

// A rigid motion with a rotation from a small integer quaternion.
rc::Gen<RigidTransform> rigid_transform(double scale);

// Moves the case by `offset`: both ends of the segment and every vertex of the triangle.
void translate(SegmentTrianglePair& c, const Vec3& offset);

// Any case moved far from the origin (large coordinates, small features): move(case,
// offset) by a lattice offset of up to 64 times 1024 size(case) in each coordinate,
// drawn after the case.
template <class T, class Move, class Size> rc::Gen<T> far_away(rc::Gen<T> base, Move move, Size size) {
  return rc::gen::exec([base, move, size] {
    T x = *base;
    move(x, *lattice_point(size(x) * 1024.0, 64));
    return x;
  });
}

}  // namespace labkit::gen
