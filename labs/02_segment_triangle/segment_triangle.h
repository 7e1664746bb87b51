// Lab 02: segment against triangle, and against a mesh.
// Handout: handouts/02_segment_triangle.md. Lectures 000 and 004 (collision detection:
// segment vs. triangle, faster point containment, segment vs. mesh, moving mesh).
//
// You write labs/02_segment_triangle/segment_triangle.cpp; this header is the contract.
//
//                 a
//                 |  d_a > 0            The segment a-b against the triangle v0 v1 v2,
//        v2       |                     normal n = (v1 - v0) x (v2 - v0).
//        | \      |                     Signed distances d_a, d_b to its plane; if they
//        |   \    x  <- crossing        differ in sign the segment crosses the plane at
//        |     \  |                     x = (d_a b - d_b a) / (d_a - d_b),
//        v0 ---- v1                     and hits the triangle when x is inside it.
//                 |
//                 b  d_b < 0
//
// Sets are closed. Touching counts as a hit: an end on the triangle, a segment through
// an edge or a vertex. A segment lying in the triangle's plane hits it where the two
// meet, and "first" is the first such point from a. A zero-length segment (a == b)
// hits when a is on the closed triangle. A zero-area triangle (collinear or coincident
// vertices) has no plane and is never hit.
//
// Input domain: where answers must match the exact ones (within the tolerances below).
//  - S, the largest absolute coordinate of the input (every point of it, including mesh
//    vertices and transform translations), is between 1e-50 and 1e50. Products of
//    three coordinates must neither overflow nor underflow there.
//  - Triangles of any shape, among them needles: aspect ratio (longest edge over the
//    height on it) up to 1e8, in every orientation and position, and zero area.
//  - Segments of any length and direction, among them zero length, lying in the
//    triangle's plane, nearly parallel to it, nearly along an edge.
//
// Preconditions (not graded; the reference throws std::invalid_argument naming the
// argument): every coordinate finite (no NaN, no infinity); mesh.triangles index
// mesh.vertices; m0 and m1 rigid (orthonormal linear part, determinant +1, to 1e-6).
// Zero-length segments and zero-area triangles are valid: their answers are below.
//
// Tolerances. tol = 1e-9 * S.
//  - Yes/no answers must equal the exact answer, except on ambiguous inputs, whose
//    exact answer changes under a perturbation of tol: there either answer passes.
//  - A needle's plane is known in doubles only to about 1e-16 times its aspect ratio
//    (rounding its edges tilts it that much): the unit normal must be within 1e-9 + k
//    of the exact one, k = 64 * 2^-52 * (longest edge)^2 / |n|, and a distance of p
//    within tol + |p - v0| * k (for a fat triangle k is about 1e-14: just tol).
//  - Points: within tol of the exact point, or, for a reported hit, within tol of the
//    segment and within tol + |b - a| * (t's tolerance below) of the closed triangle.
//  - The parameter t of a crossing: within (the distances' tolerance) / |d_a - d_b| of
//    the exact one (a segment almost parallel to the plane fixes t, and so its crossing
//    point, only loosely).
//  - t, and the barycentric weights (and alpha, beta), must reproduce the reported point
//    within tol: for a needle, solve them so that they do (handout, step 3).
#pragma once

#include "common/geometry.h"

#include <vector>

namespace labkit::lab02 {

// ---- Step 1 (L02S1): signed distances, crossing point ------------------------------

struct PlaneCrossing {
  double d_a = 0.0;           // signed distance of a to the triangle's plane (unit normal)
  double d_b = 0.0;           // signed distance of b
  bool crosses = false;       // the segment meets the plane in exactly one point
  double t = 0.0;             // that point is a + t (b - a), 0 <= t <= 1
  Vec3 point = Vec3::Zero();  // that point
};

// d_a, d_b always (both 0 for a zero-area triangle); t and point only when `crosses`,
// which is false when both ends are strictly on one side, and when both are on the
// plane (the segment lies in it: step 8).
PlaneCrossing segment_plane(const Segment& segment, const Triangle& triangle);

// ---- Step 2 (L02S2): point in triangle: edge tests ---------------------------------

// For a point in the triangle's plane: is it inside the closed triangle? Use the three
// edge tests: x is inside when (x - v_i) . (n x (v_{i+1} - v_i)) >= 0 for i = 0, 1, 2
// (n x (v_{i+1} - v_i) lies in the plane and points into the triangle). False for a
// zero-area triangle.
bool point_in_triangle_edges(const Vec3& x, const Triangle& triangle);

// ---- Step 3 (L02S3): point in triangle: barycentric --------------------------------

struct Barycentric {
  int dropped_axis = -1;  // 0, 1 or 2: the largest |component| of the normal (ties: the
                          // lower index); -1 for a zero-area triangle
  double alpha = 0.0;     // x = v0 + alpha (v1 - v0) + beta (v2 - v0)
  double beta = 0.0;
};

// For a point in the triangle's plane, solved in 2D after dropping one coordinate.
Barycentric barycentric(const Vec3& x, const Triangle& triangle);

// Inside the closed triangle when alpha >= 0, beta >= 0 and alpha + beta <= 1.
bool point_in_triangle_barycentric(const Vec3& x, const Triangle& triangle);

// ---- Step 4 (L02S4): test and find segment-triangle --------------------------------

bool test_segment_triangle(const Segment& segment, const Triangle& triangle);

struct SegmentTriangleHit {
  bool hit = false;                 // false: no common point; the other fields mean nothing
  double t = 0.0;                   // the first common point from a is a + t (b - a)
  Vec3 point = Vec3::Zero();        // that point
  Vec3 barycentric = Vec3::Zero();  // its weights (w0, w1, w2) of v0, v1, v2, summing to 1
  Vec3 normal = Vec3::Zero();       // the triangle's unit normal, as it is wound
};

SegmentTriangleHit find_segment_triangle(const Segment& segment, const Triangle& triangle);

// ---- Step 5 (L02S5): segment against a mesh ----------------------------------------

struct MeshHit {
  bool hit = false;
  int triangle = -1;  // which triangle: an index into mesh.triangles
  double t = 0.0;
  Vec3 point = Vec3::Zero();
  Vec3 barycentric = Vec3::Zero();
  Vec3 normal = Vec3::Zero();
};

// The hit with the smallest t (when two triangles tie, either).
MeshHit first_hit(const Segment& segment, const Mesh& mesh);
// Whether any triangle is hit; may stop at the first one found.
// (A mesh may hold the same face twice, wound both ways: both are hit, at the same t.)
bool any_hit(const Segment& segment, const Mesh& mesh);
// Every triangle the segment meets, once each, sorted by t (ties: lower index first).
// A segment through an edge shared by two triangles meets both.
std::vector<MeshHit> all_hits(const Segment& segment, const Mesh& mesh);

// ---- Step 6 (L02S6): segment against a moving mesh ---------------------------------

// The mesh (vertices in its own frame) moves from pose m0 to pose m1 while the particle
// moves from segment.a to segment.b. Use the delta-matrix idea of the lecture: in the
// mesh's frame the particle goes from m0^-1 a to m1^-1 b. Report the first hit with
// the mesh at m1: t along that path (in the mesh's frame), the point as the contact on
// the mesh at its end pose (m1 times the point found in the mesh's frame; not a point
// of the world segment a-b, nor of the mesh at m0), the normal turned by m1.
MeshHit first_hit_moving(const Segment& segment, const Mesh& mesh, const RigidTransform& m0, const RigidTransform& m1);

// ---- Step 7 (L02S7): moving mesh against moving mesh -------------------------------

// Two meshes move by translations during the frame, t from 0 to 1: a vertex p of A is at
// p + t velocity_a, a vertex q of B at q + t velocity_b (vertices given at t = 0). Seen
// from B, only A moves, by d = velocity_a - velocity_b (the delta matrix of step 6 for
// translations), and the 4D question "when do they first touch?" becomes lab 02's 3D
// segment-against-triangle queries (lecture 000 and 004, "moving meshes: extrusion"):
//   - a vertex p of A along the segment p -> p + d, against B's faces;
//   - a vertex q of B along q -> q - d, against A's faces (the other delta matrix);
//   - an edge p0 p1 of A sweeps the parallelogram p0, p1, p1 + d, p0 + d: as the two
//     triangles (p0, p1, p1 + d) and (p0, p1 + d, p0 + d), against each edge q0 q1 of B.
//     The time of a hit is its weight along d: w2 on the first triangle, w1 + w2 on the
//     second.
//            p0 + d ------ p1 + d          edges: the distinct vertex pairs of the
//              |  second  /  |             triangles, each once: mesh.edges().
//              |       /     |
//              |   /  first  |
//             p0 ---------- p1
// The first contact is the smallest such time over the three families (at the first
// touch of two triangles, a vertex touches a face or an edge touches an edge). Report
// it, the contact point in the world at that time (on both meshes as they are then),
// and the contact's normal, the other half of a contact's description (the direction a
// response pushes along): the unit normal of the face a vertex meets, or for two edges e
// and f, (e x f) / |e x f|; for parallel edges, any unit vector perpendicular to both.
// Its sign: d . normal <= 0, so it points from B toward A (A closes on B against it);
// either sign where d . normal = 0. No contact during [0, 1]: hit = false.
//
// Precondition (not checked: it would cost a triangle-triangle test per pair): the
// meshes do not touch at t = 0. Checked (std::invalid_argument naming the argument):
// finite coordinates and velocities, triangles indexing their mesh's vertices.
// Closed sets, as above: touching counts, a grazing contact is a contact, and a
// contact at t = 1 counts. Equal velocities: the meshes never meet.
//
// Tolerances. tol = 1e-9 * S, S the largest absolute coordinate of the input (vertices
// and velocities).
//  - hit must equal the exact answer, except where a perturbation of tol changes it.
//  - t is certified exactly: the meshes must not touch before t - tol / c, and must
//    touch by t + tol / c, c the closing speed along the contact's unit normal (the
//    face's normal; for two edges e, f, their cross product e x f). A grazing contact
//    (small c) fixes t only loosely.
//  - point: within 2 tol + |d| tol / c of both meshes at your t.
//  - normal: unit length within 1e-9, and within 1e-8 k of the normal of a face or an
//    edge pair that touches, or comes within tol of touching, by your t + tol / c,
//    k = |e| |f| / |e x f| (for a face, its two edges from one vertex): a needle face or
//    nearly parallel edges fix their normal only loosely. Where several features touch
//    at once (or within tol of it), any of their normals will do.
struct MeshContact {
  bool hit = false;            // the meshes touch at some t in [0, 1]
  double t = 0.0;              // the first such time
  Vec3 point = Vec3::Zero();   // a point where they touch then, in the world
  Vec3 normal = Vec3::Zero();  // the contact's unit normal, from B toward A
};

MeshContact first_contact_moving_meshes(const Mesh& a, const Vec3& velocity_a, const Mesh& b, const Vec3& velocity_b);

// ---- Step 8 (L02S8): robustness: touching and coplanar -----------------------------
// No new function: steps 2 to 5 must follow the rules at the top of this file on exact
// degenerate input (ends on the triangle, through edges and vertices, coplanar
// segments, zero-length segments, zero-area triangles, edges shared in a mesh).

// ---- Step 9 (L02S9): robustness: moving meshes -------------------------------------
// No new function (an extension, as step 7 is): step 7 must follow its rules above on
// exact degenerate input (meshes touching exactly at a vertex or an edge, at t = 1, or
// sliding into each other in one plane).

}  // namespace labkit::lab02
