// Segment against triangle and mesh (labs 02, 06, 07). Closed sets: touching counts,
// a segment lying in the triangle's plane counts where it meets the triangle, and a
// zero-area triangle is never hit.
#pragma once

#include "common/geometry.h"

#include <string>
#include <vector>

namespace oracle {

using labkit::Mesh;
using labkit::RigidTransform;
using labkit::Segment;
using labkit::Triangle;
using labkit::Vec3;

bool segment_hits_triangle(const Segment& s, const Triangle& t);

// Could moving every input coordinate by at most `delta` change whether the segment
// meets the triangle? Conservative: false means certainly not; true means it might.
// A miss is in doubt when the two are within about 2 sqrt(3) delta of touching; a hit
// when an end is within its perturbation bound of the plane, or the crossing point is
// within its bound of an edge (bounds that grow for long, nearly parallel segments and
// for thin triangles, whose planes tilt easily).
bool segment_triangle_in_doubt(const Segment& s, const Triangle& t, double delta);

// The segment against the triangle's plane, n = (v1 - v0) x (v2 - v0).
struct PlaneCrossing {
  int side_a = 0, side_b = 0;   // exact signs of (a - v0) . n and (b - v0) . n
  double d_a = 0.0, d_b = 0.0;  // signed distances (unit normal); 0 for a zero-area triangle
  bool crosses = false;         // exactly one common point with the plane
  double t = 0.0;               // that point is a + t (b - a)
  Vec3 point = Vec3::Zero();
};
PlaneCrossing segment_plane(const Segment& s, const Triangle& t);
// Only its `crosses`, from exact signs: cheap enough to ask many times.
bool segment_crosses_plane(const Segment& s, const Triangle& t);

// Is x, projected onto the triangle's plane along its normal, in the closed triangle?
// False for a zero-area triangle.
bool point_in_triangle_projected(const Vec3& x, const Triangle& t);
// Could moving x by `delta` change that? Exact, and conservative in the other sense from
// segment_triangle_in_doubt: true only when the projection lies within delta of an edge
// (then x moved by delta across it, or onto it, flips the answer); a flip that needs the
// vertices to move is left to check::flips_under_perturbation. False for zero area.
bool point_in_triangle_in_doubt(const Vec3& x, const Triangle& t, double delta);

// The exact unit normal (v1 - v0) x (v2 - v0) / |...|, rounded; zero for zero area.
Vec3 unit_normal(const Triangle& t);

// Exact reproduction checks, for answers that describe a point in two ways:
//   |w0 v0 + w1 v1 + w2 v2 - x| <= tolerance
bool weights_reproduce(const Triangle& t, const Vec3& weights, const Vec3& x, double tolerance);
//   |v0 + alpha (v1 - v0) + beta (v2 - v0) - x| <= tolerance
bool alpha_beta_reproduce(const Triangle& t, double alpha, double beta, const Vec3& x, double tolerance);
//   |a + t (b - a) - x| <= tolerance
bool parameter_reproduces(const Segment& s, double t, const Vec3& x, double tolerance);

struct SegmentHit {
  bool hit = false;
  bool coplanar = false;      // the segment lies in the triangle's plane
  double t = 0.0;             // parameter of the first common point: a + t (b - a)
  Vec3 point = Vec3::Zero();  // that point
  int triangle = -1;          // for meshes: which triangle
};

// The first common point along the segment (exact, rounded once).
SegmentHit segment_triangle(const Segment& s, const Triangle& t);

// Every triangle of the mesh the segment meets, sorted by t (ties by index).
std::vector<SegmentHit> segment_mesh_hits(const Segment& s, const Mesh& mesh);
bool segment_hits_mesh(const Segment& s, const Mesh& mesh);

// The mesh moves from pose m0 to pose m1 while the particle moves from s.a to s.b; in
// the mesh's own frame the particle travels the straight segment m0^-1 a -> m1^-1 b.
// Hits are given in the world with the mesh at m1 (points), with t along that path.
// The inverses are exact inverses of the given (nearly rigid) matrices.
std::vector<SegmentHit> moving_mesh_hits(const Segment& s, const Mesh& mesh, const RigidTransform& m0,
                                         const RigidTransform& m1);

// The particle's path in the mesh's frame, m0^-1 a -> m1^-1 b (exact, then rounded).
Segment moving_local_path(const Segment& s, const RigidTransform& m0, const RigidTransform& m1);

// Whether the moving case above has any hit (exact, no constructions: fast).
bool moving_mesh_hit_any(const Segment& s, const Mesh& mesh, const RigidTransform& m0, const RigidTransform& m1);

// Checks a reported hit of the moving case, in the world with the mesh at m1: the point
// is within `tolerance` of triangle `index` posed at m1 and of the segment a' b, where
// a' = m1 m0^-1 a (the lecture's delta matrix), and a' + t (b - a') reproduces it.
// Returns "" when all hold, else which one fails.
std::string check_moving_hit(const Segment& s, const Mesh& mesh, const RigidTransform& m0, const RigidTransform& m1,
                             int index, double t, const Vec3& point, double tolerance);

}  // namespace oracle
