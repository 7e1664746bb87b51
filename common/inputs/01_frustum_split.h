// Lab 01's inputs: what each query of frustum_split.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (common/generators/01_frustum_split.h) draw them, the judge and the viewer read them.
#pragma once

#include "frustum_split.h"

#include "common/harness/query.h"

#include <vector>

namespace labkit {

struct TrianglePlane {
  Triangle triangle;
  Plane plane;
};
template <class Visit> void fields(TrianglePlane& p, Visit&& visit) {
  visit("triangle", p.triangle);
  visit("plane", p.plane);
}

struct TriangleFrustum {
  Triangle triangle;
  Frustum frustum;
};
template <class Visit> void fields(TriangleFrustum& p, Visit&& visit) {
  visit("triangle", p.triangle);
  visit("frustum", p.frustum);
}

// A mesh with one colour per vertex, and a frustum to clip it to.
struct MeshFrustum {
  Mesh mesh;
  std::vector<Vec3> colors;
  Frustum frustum;
};
template <class Visit> void fields(MeshFrustum& p, Visit&& visit) {
  visit("mesh", p.mesh);
  visit("colors", p.colors);
  visit("frustum", p.frustum);
}

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
template <class Visit> void fields(CameraParameters& c, Visit&& visit) {
  visit("eye", c.eye);
  visit("forward", c.forward);
  visit("up", c.up);
  visit("fov_y", c.fov_y);
  visit("aspect", c.aspect);
  visit("near", c.near);
  visit("far", c.far);
}

}  // namespace labkit

// ---- The queries -------------------------------------------------------------------------
// The name of each question the tests ask (a replay token's prefix) and the input it takes,
// by the step that asks it first. The tests, the viewer's scene and its presets read this
// table (common/harness/query.h): a query is added or renamed here and nowhere else.
#define LABKIT_LAB01_QUERIES(X)                                    \
  /* step 1 */                                                     \
  X(signed_distance, "signed_distance", TrianglePlane)             \
  X(classify, "classify", TrianglePlane)                           \
  /* step 2 */                                                     \
  X(split_triangle, "split_triangle", TrianglePlane)               \
  /* step 3 */                                                     \
  X(frustum_from_camera, "frustum_from_camera", Camera)            \
  X(frustum_from_matrix, "frustum_from_matrix", Mat4)              \
  /* step 4 */                                                     \
  X(clip_triangle, "clip_triangle", TriangleFrustum)               \
  /* step 5 */                                                     \
  X(clip_mesh, "clip_mesh", MeshFrustum)                           \
  /* step 6 */                                                     \
  X(robust_classify, "robust.classify", TrianglePlane)             \
  X(robust_split_triangle, "robust.split_triangle", TrianglePlane) \
  X(robust_clip_triangle, "robust.clip_triangle", TriangleFrustum) \
  X(robust_clip_mesh, "robust.clip_mesh", MeshFrustum)

namespace labkit::lab01::query {
LABKIT_LAB01_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB01_QUERIES)
}  // namespace labkit::lab01::query
