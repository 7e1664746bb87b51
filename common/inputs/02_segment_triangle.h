// Lab 02's inputs beyond the shared pairs (common/inputs/inputs.h): each query's
// arguments as one struct, whose fields() let reports print it and replay tokens carry it
// (the answers' fields are in tests/02_segment_triangle.wire.h).
#pragma once

#include "segment_triangle.h"

#include "common/harness/query.h"

#include "common/inputs/inputs.h"

namespace labkit::lab02 {

struct PointTriangle {
  Vec3 x = Vec3::Zero();
  Triangle triangle;
};
template <class V> void fields(PointTriangle& p, V&& v) {
  v("x", p.x);
  v("triangle", p.triangle);
}

struct MovingMesh {
  Segment segment;
  Mesh mesh;
  RigidTransform m0 = RigidTransform::Identity();
  RigidTransform m1 = RigidTransform::Identity();
};
template <class V> void fields(MovingMesh& m, V&& v) {
  v("segment", m.segment);
  v("mesh", m.mesh);
  v("m0", m.m0);
  v("m1", m.m1);
}

// Step 7: two meshes, each moving by a translation over [0, 1].
struct MovingMeshes {
  Mesh a;
  Vec3 velocity_a = Vec3::Zero();
  Mesh b;
  Vec3 velocity_b = Vec3::Zero();
};
template <class V> void fields(MovingMeshes& m, V&& v) {
  v("a", m.a);
  v("velocity_a", m.velocity_a);
  v("b", m.b);
  v("velocity_b", m.velocity_b);
}

}  // namespace labkit::lab02

// ---- The queries -------------------------------------------------------------------------
// The name of each question the tests ask (a replay token's prefix) and the input it takes,
// by the step that asks it first. The tests, the viewer's scene and its presets read this
// table (common/harness/query.h): a query is added or renamed here and nowhere else.
#define LABKIT_LAB02_QUERIES(X)                                                        \
  /* step 1 */                                                                         \
  X(segment_plane, "segment_plane", SegmentTrianglePair)                               \
  /* step 2 */                                                                         \
  X(point_in_triangle_edges, "point_in_triangle_edges", PointTriangle)                 \
  /* step 3 */                                                                         \
  X(barycentric, "barycentric", PointTriangle)                                         \
  X(point_in_triangle_barycentric, "point_in_triangle_barycentric", PointTriangle)     \
  /* step 4 */                                                                         \
  X(test_segment_triangle, "test_segment_triangle", SegmentTrianglePair)               \
  X(find_segment_triangle, "find_segment_triangle", SegmentTrianglePair)               \
  /* step 5 */                                                                         \
  X(any_hit, "any_hit", SegmentMeshPair)                                               \
  X(first_hit, "first_hit", SegmentMeshPair)                                           \
  X(all_hits, "all_hits", SegmentMeshPair)                                             \
  /* step 6 */                                                                         \
  X(first_hit_moving, "first_hit_moving", MovingMesh)                                  \
  /* step 7 */                                                                         \
  X(first_contact_moving_meshes, "first_contact_moving_meshes", MovingMeshes)          \
  /* step 8 */                                                                         \
  X(robust_point_in_triangle, "robust.point_in_triangle", PointTriangle)               \
  X(robust_find_segment_triangle, "robust.find_segment_triangle", SegmentTrianglePair) \
  X(robust_all_hits, "robust.all_hits", SegmentMeshPair)                               \
  X(robust_first_contact_moving_meshes, "robust.first_contact_moving_meshes", MovingMeshes)

namespace labkit::lab02::query {
LABKIT_LAB02_QUERIES(LABKIT_QUERY)
LABKIT_QUERY_TABLE(LABKIT_LAB02_QUERIES)
}  // namespace labkit::lab02::query
