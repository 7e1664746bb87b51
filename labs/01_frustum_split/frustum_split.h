// Lab 01: view-frustum clipping by triangle splitting.
// Handout: handouts/01_frustum_split.md. Lecture 000 (course lecture 24, "Collision
// Handling Part 1 of 2": view frustum clipping, triangle splitting, figure 3.4).
//
// You write labs/01_frustum_split/frustum_split.cpp; this header is the contract.
//
// A plane n . x + offset = 0 keeps the closed side its normal points to: value(x) =
// n . x + offset >= 0 is "in". The signs of the three vertices' values give the
// lecture's four configurations (c0, c1: where an edge crosses the plane):
//
//   all in: keep      one in: one triangle  two in: a quadrilateral,    none in: cull
//                                          cut into two triangles
//       v2                  v2               v2 ________ v1
//      /  \                /  \               \          /
//     /    \              /    \               \        /
//    v0----v1            /      \               \      /
//   --------------    --c1--------c0--     -----c1----c0-----          --------------
//                       /          \              \  /                    v1----v0
//                      v0----------v1              v0                      \    /
//                                                                           \  /
//                                                                            v2
//   In: above the line. Kept: (v0 v1 v2); (c0 v2 c1); (c0 v1 v2) and (c0 v2 c1); nothing.
//
// The one-plane rule (Sutherland-Hodgman on a closed half-space). Walk the polygon's
// corners in order; keep every corner with value >= 0, and add the cut point of every
// side whose two ends have strictly opposite signs (one > 0, the other < 0). The kept
// polygon, with m corners, becomes m - 2 triangles; fewer than 3 corners: nothing. So:
//  - a vertex exactly on the plane is in: it is kept, and its sides are not cut;
//  - a triangle touching the plane from outside at a vertex or along an edge is culled;
//  - a triangle lying in the plane is kept whole.
// The frustum applies the rule plane after plane; computed exactly, the result is the
// convex polygon triangle ∩ frustum, with m corners, and again m - 2 triangles. Decide
// every sign as exact arithmetic would: on the robustness step's integer input, the
// number of triangles must be exactly m - 2.
//
// Every output triangle winds like the input: its normal (v1 - v0) x (v2 - v0) points
// the same way. A zero-area input triangle may come back as nothing or as zero-area
// pieces.
//
// Tolerances. S is the largest absolute coordinate of the input's points (the
// triangle's or mesh's vertices; for a camera, its eye and the eight corners of its
// frustum) and of the planes' distances from the origin, |offset| / |normal|.
// tol = 1e-9 S; L is the input triangle's longest edge.
//  - Signed distances within tol. Normals of frustum planes have unit length (within
//    1e-9) and point into the frustum.
//  - Vertex classes are exact, except for a vertex within 8 tol of the plane
//    (ambiguous: there any class passes). Piece counts likewise: exact, unless moving
//    the vertices by tol, or the planes by tol (or turning them by 1e-9), could change
//    the exact count.
//  - Pieces: every corner within tol of the inner side of every plane and within tol
//    of the input triangle; their areas sum to the exact area within 1e-9 S L (or to
//    anything between the exact areas with every plane moved 8 tol out and 8 tol in:
//    a triangle almost parallel to a plane is cut at a very uncertain place); no two
//    pieces overlap by more than 1e-9 S L; every piece of area above 1e-9 S L winds
//    like the input.
//  - Colours: within 1e-9 (C + G S) of the colour that linear interpolation over the
//    input triangle gives at the piece's vertex, where C is the largest |colour
//    component| and G the largest rate of change of a colour component across the
//    triangle.
//  - Planes from a camera pass within tol of their four corners of the frustum.
//  - Planes from a matrix, with (a, b, c, d) the row sum or difference and n = (a, b, c):
//    the normal within 1e-9 A / |n| of the exact unit normal and the offset within
//    1e-9 (B + A |d| / |n|) / |n| of the exact d / |n|, A being the largest |entry|
//    of the matrix's first three columns and B of its last column.
//
// Domain: where answers must match the exact ones within those tolerances. Finite
// input whose non-zero coordinates and normal components have magnitudes from 2^-130 to
// 2^130 (about 1e-39 to 1e39), normals of any length in that range, and offsets at most
// 2^130 (a smaller one, down to 0, is a plane through or near the origin); triangles
// of any shape, needles with an aspect up to 1e8 included; cameras with fov_y from 20
// to 120 degrees, aspect from 1/2 to 2 and far / near up to 64. (In that range a product
// of three plane values neither overflows nor underflows.)
//
// Preconditions. Every query needs finite numbers and planes with a non-zero normal. A
// camera also needs forward and up non-zero and not parallel, 0 < fov_y < pi,
// aspect > 0 and 0 < near < far; a matrix, a non-zero normal (a, b, c) for each of its
// six planes; a mesh, one colour per vertex and indices into its vertices. Input that
// breaks one throws std::invalid_argument naming the argument and the rule, such as
// "classify: plane.normal must be non-zero, got (0, 0, 0)". No step grades invalid input:
// the checks are good practice, not a requirement.
#pragma once

#include "common/geometry.h"

#include <array>
#include <vector>

namespace labkit::lab01 {

// ---- Step 1 (L01S1): signed distance, vertex classes -------------------------------

// (normal . x + offset) / |normal|: the normal need not have unit length.
double signed_distance(const Plane& plane, const Vec3& x);

// The exact sign of value(x) = normal . x + offset.
enum class Side { out = -1, on = 0, in = 1 };

// The sides of v0, v1, v2.
std::array<Side, 3> classify(const Plane& plane, const Triangle& triangle);

// ---- Step 2 (L01S2): split a triangle by one plane ---------------------------------

// The part with value >= 0, by the one-plane rule: 0, 1 or 2 triangles.
std::vector<Triangle> split_triangle(const Triangle& triangle, const Plane& plane);

// ---- Step 3 (L01S3): the six frustum planes ----------------------------------------

// A perspective camera, as OpenGL's gluLookAt and gluPerspective take it.
struct Camera {
  Vec3 eye = Vec3::Zero();
  Vec3 forward = -Vec3::UnitZ();      // where it looks; any length
  Vec3 up = Vec3::UnitY();            // any length, not parallel to forward; the image's up is
                                      // the part of it perpendicular to forward
  double fov_y = 1.5707963267948966;  // the vertical field of view, top to bottom, radians
  double aspect = 1.0;                // image width / height
  double near = 1.0;                  // distances along forward, 0 < near < far
  double far = 100.0;
};

// The planes in the order of Frustum::Side (left, right, bottom, top, near, far), each
// with a unit normal pointing into the frustum. The side planes pass through the eye;
// near and far are perpendicular to forward.
Frustum frustum_from_camera(const Camera& camera);

// The planes of the clip volume -w <= x, y, z <= w of a view-projection matrix M
// (OpenGL: a point p is seen when (x, y, z, w) = M (p, 1) lies in it). With r0..r3 the
// rows of M: left r3 + r0, right r3 - r0, bottom r3 + r1, top r3 - r1, near r3 + r2,
// far r3 - r2, each (a, b, c, d) read as the plane (a, b, c) . x + d, then divided by
// |(a, b, c)| so that its normal has unit length.
Frustum frustum_from_matrix(const Mat4& view_projection);

// ---- Step 4 (L01S4): clip a triangle to the frustum --------------------------------

// triangle ∩ frustum by the rule at the top (planes need not have unit normals).
std::vector<Triangle> clip_triangle(const Triangle& triangle, const Frustum& frustum);

// ---- Step 5 (L01S5): clip a mesh, interpolate colours ------------------------------

// A mesh with a colour per vertex: colors[i] belongs to mesh.vertices[i]. Any other
// per-vertex attribute (a texture coordinate, a normal) is cut the same way.
struct ColoredMesh {
  Mesh mesh;
  std::vector<Vec3> colors;
};

struct ClippedMesh {
  Mesh mesh;                 // the pieces; vertices may be shared, repeated or unused
  std::vector<Vec3> colors;  // colors[i] belongs to mesh.vertices[i]
  std::vector<int> source;   // source[k]: the input triangle that mesh triangle k is a piece of
};

// Every triangle clipped as in step 4. A cut point's colour is interpolated like its
// position: where p = a + t (b - a), its colour is c_a + t (c_b - c_a) with the same t.
ClippedMesh clip_mesh(const ColoredMesh& mesh, const Frustum& frustum);

// ---- Step 6 (L01S6): robustness: vertices on planes --------------------------------
// No new function: steps 1 to 5 must follow the rules at the top of this file exactly on
// exact input: integer coordinates |x| <= 1024 and integer offsets |offset| <= 2^14, all
// times one power of two, and integer normal components |n_i| <= 16. Every plane value
// is then an integer (times that power of two) with |d| <= 3 * 16 * 1024 + 2^14 = 2^16,
// so products of up to three of them stay below 2^53, exact in doubles. The input has
// vertices exactly on planes, edges along them, triangles lying in them or touching them
// at a point, and edges through the lines where two planes meet.

}  // namespace labkit::lab01
