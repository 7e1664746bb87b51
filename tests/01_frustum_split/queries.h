// Lab 01's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), and the table of the queries (last). Both processes include it.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too.
#pragma once

#include "frustum_split.h"

#include "common/fields.h"
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
// (gen:: in tests/01_frustum_split/judge.h) draw them, the judge and the viewer read them.
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
