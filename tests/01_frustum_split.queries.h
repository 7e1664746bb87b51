// Lab 01's queries: the name of each question its tests ask (a replay token's prefix,
// `./labkit replay signed_distance:...`) and the input it takes. The tests, the viewer's scene and
// its presets read this table (common/harness/query.h); a query is added or renamed here.
#pragma once

#include "common/harness/query.h"
#include "common/inputs/01_frustum_split.h"

#define LABKIT_LAB01_QUERIES(X) \
  X(signed_distance, "signed_distance", TrianglePlane)               \
  X(classify, "classify", TrianglePlane)                             \
  X(split_triangle, "split_triangle", TrianglePlane)                 \
  X(frustum_from_camera, "frustum_from_camera", Camera)              \
  X(frustum_from_matrix, "frustum_from_matrix", Mat4)                \
  X(clip_triangle, "clip_triangle", TriangleFrustum)                 \
  X(clip_mesh, "clip_mesh", MeshFrustum)                             \
  X(robust_classify, "robust.classify", TrianglePlane)               \
  X(robust_split_triangle, "robust.split_triangle", TrianglePlane)   \
  X(robust_clip_triangle, "robust.clip_triangle", TriangleFrustum)   \
  X(robust_clip_mesh, "robust.clip_mesh", MeshFrustum)              

namespace labkit::lab01::query {
LABKIT_LAB01_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB01_QUERIES)
}  // namespace labkit::lab01::query
