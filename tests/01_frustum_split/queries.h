// Lab 01's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), the table of the queries, and how each input is drawn and each answer
// judged (last): a new query is written here, then defined in generators*.cpp and
// judge*.cpp. Both processes include it; the answerer uses only its first part.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too.
#pragma once

#include "frustum_split.h"

#include "common/fields.h"
#include "common/harness/outcome.h"
#include "common/harness/query.h"
#include "common/protocol/calls.h"

#include <array>
#include <vector>

namespace labkit::lab01 {

LABKIT_FIELDS(Camera, eye, forward, up, fov_y, aspect, near, far)
LABKIT_FIELDS(ColoredMesh, mesh, colors)
LABKIT_FIELDS(ClippedMesh, mesh, colors, source)

using Sides = std::array<Side, 3>;
using Triangles = std::vector<Triangle>;

}  // namespace labkit::lab01

// clang-format off
#define LABKIT_LAB01_CALLS(CALL, METHOD)                                           \
  CALL(double, signed_distance, (const Plane&, const Vec3&))                       \
  CALL(Sides, classify, (const Plane&, const Triangle&))                           \
  CALL(Triangles, split_triangle, (const Triangle&, const Plane&))                 \
  CALL(Frustum, frustum_from_camera, (const Camera&))                              \
  CALL(Frustum, frustum_from_matrix, (const Mat4&))                                \
  CALL(Triangles, clip_triangle, (const Triangle&, const Frustum&))                \
  CALL(ClippedMesh, clip_mesh, (const ColoredMesh&, const Frustum&))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab01, LABKIT_LAB01_CALLS)

// ---- The inputs ------------------------------------------------------------------------
// Lab 01's inputs: what each query of frustum_split.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (gen::, declared below) draw them, the judge and the viewer read them.
namespace labkit {

struct TrianglePlane {
  Triangle triangle;
  Plane plane;
};
LABKIT_FIELDS(TrianglePlane, triangle, plane)

struct TriangleFrustum {
  Triangle triangle;
  Frustum frustum;
};
LABKIT_FIELDS(TriangleFrustum, triangle, frustum)

// A mesh with one colour per vertex, and a frustum to clip it to.
struct MeshFrustum {
  Mesh mesh;
  std::vector<Vec3> colors;
  Frustum frustum;
};
LABKIT_FIELDS(MeshFrustum, mesh, colors, frustum)

// A perspective camera's parameters, as gluLookAt and gluPerspective take them (lab 01's
// Camera holds the same).
struct CameraParameters {
  Vec3 eye = Vec3::Zero();
  Vec3 forward = -Vec3::UnitZ();
  Vec3 up = Vec3::UnitY();
  double fov_y = 1.5707963267948966;
  double aspect = 1.0;
  double near = 1.0;
  double far = 100.0;
};
LABKIT_FIELDS(CameraParameters, eye, forward, up, fov_y, aspect, near, far)

}  // namespace labkit

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB01_QUERIES(X, X_IN)                                                            \
  /* step 1 */ X(signed_distance, TrianglePlane) X(classify, TrianglePlane)                      \
  /* step 2 */ X(split_triangle, TrianglePlane)                                                  \
  /* step 3 */ X(frustum_from_camera, Camera) X(frustum_from_matrix, Mat4)                       \
  /* step 4 */ X(clip_triangle, TriangleFrustum)                                                 \
  /* step 5 */ X(clip_mesh, MeshFrustum)                                                         \
  /* step 6 */ X_IN(robust, classify, TrianglePlane) X_IN(robust, split_triangle, TrianglePlane) \
               X_IN(robust, clip_triangle, TriangleFrustum) X_IN(robust, clip_mesh, MeshFrustum)
// clang-format on

namespace labkit::lab01::query {
LABKIT_QUERIES(LABKIT_LAB01_QUERIES)
}  // namespace labkit::lab01::query

// ---- How each input is drawn, and the verdicts -----------------------------------------
// Declared here, beside the queries they serve; defined in generators*.cpp (gen::) and
// judge*.cpp (judge::). RapidCheck is included where the generators are called.
namespace rc {
template <typename T> class Gen;
}  // namespace rc

// Seeded inputs for view-frustum clipping (lab 01), on the same dyadic lattice as
// common/generators/generators.h, so that the degenerate families are exact: a vertex "on
// the plane" is on it, an edge "through the line where two planes meet" passes through
// it.
//
// Planes carry integer normals (not unit: the labs must not assume it) through lattice
// points, or rounded unit normals; frustums come from random cameras (rounded unit
// planes) or are exact: boxes and pyramids with integer normals. Families on purpose:
// vertices on planes, edges along them, triangles lying in them or touching them at a
// point, edges through frustum edges and corners, tiny offsets off all of these, needle
// triangles (aspects up to 2^27, about 1.3e8), every scale from 2^-20 to 2^20 and some at
// the ends of lab 01's domain (2^-100 to 2^100), and far from the origin.
namespace labkit::gen {

// A plane and a triangle: generic, a vertex on the plane, an edge along it, the triangle
// in it, touching it at a vertex from either side, tiny offsets off those, every scale,
// far from the origin; integer normals (the plane through a lattice point) or rounded
// unit normals.
rc::Gen<TrianglePlane> triangle_plane();
// Only exactly degenerate ones, on integer coordinates (|x| <= 1024, times a power of
// two) and integer normals: the robustness step's input.
rc::Gen<TrianglePlane> exact_triangle_plane();

// Cameras at every scale and distance from the origin: fields of view from 20 to 120
// degrees, aspects from 1/2 to 2, far / near from 2 to 64, up at least 15 degrees away
// from forward.
rc::Gen<CameraParameters> camera();
// The same cameras as the lab's Camera, for frustum_from_camera.
rc::Gen<lab01::Camera> lab_camera();
// View-projection matrices: perspective cameras, orthographic views, and either times a
// positive power of two (the same clip volume).
rc::Gen<Mat4> view_projection_matrix();

// A triangle near a frustum: across its corners, edges and faces, inside, outside, and
// near-degenerate against frustums from cameras; exactly degenerate against exact ones.
rc::Gen<TriangleFrustum> triangle_frustum();
// Exact frustums (boxes and pyramids with integer normals) and triangles with vertices on
// their planes, edges along them, in them, touching them, and through their edges and
// corners: the robustness step's input.
rc::Gen<TriangleFrustum> exact_triangle_frustum();

// A small mesh (soup, terrain, octahedron) with colours, across a frustum.
rc::Gen<MeshFrustum> mesh_frustum();
// The same on integer coordinates, across exact frustums: the robustness step's input.
rc::Gen<MeshFrustum> exact_mesh_frustum();

}  // namespace labkit::gen

// Lab 01's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/01_frustum_split/frustum_split.h. The tests and
// the viewer both use them, so a red mark in the viewer and a failing case in `./labkit
// check` always agree.
namespace labkit::lab01::judge {

using check::Outcome;
using check::Rules;  // random cases, or a robustness step's exact input

// got[i] is the signed distance of vertex i to the plane.
Outcome signed_distance(const TrianglePlane& in, const std::array<double, 3>& got);
Outcome classify(const TrianglePlane& in, const std::array<Side, 3>& got, Rules rules = Rules::random);
Outcome split_triangle(const TrianglePlane& in, const std::vector<Triangle>& got, Rules rules = Rules::random);
Outcome frustum_from_camera(const Camera& in, const Frustum& got);
Outcome frustum_from_matrix(const Mat4& in, const Frustum& got);
Outcome clip_triangle(const TriangleFrustum& in, const std::vector<Triangle>& got, Rules rules = Rules::random);
Outcome clip_mesh(const MeshFrustum& in, const ClippedMesh& got, Rules rules = Rules::random);

}  // namespace labkit::lab01::judge
